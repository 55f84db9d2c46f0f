#ifndef GT_RANGE_MAPPING_INCLUDED
#define GT_RANGE_MAPPING_INCLUDED

// From tile and tess coordinate to the global point q and on to a patch's local (u, v).
// Mirrors Runtime/Core/Library/RangeMapping.cs (+ TerrainPoint.cs); see Documentation~/internals.md,
// "The tile layout" and "Range origin". Parameters in, no resources declared here.

// q = originHi + local. originHi is the same for every vertex of a frame; local is small at deep
// zoom, so its float keeps fine absolute resolution (near 0.7 a plain float q resolves ~6e-8 only).
struct TerrainPoint
{
    float2 originHi;
    float2 local;
};

// Knuth's TwoSum: returns s = fl(a + b) and err with a + b == s + err exactly. `precise` forbids
// the compiler to reassociate or fuse these steps, which would make err zero or garbage.
float TwoSum(float a, float b, out float err)
{
    precise float s = a + b;
    precise float bv = s - a;
    precise float av = s - bv;
    precise float e = (a - av) + (b - bv);
    err = e;
    return s;
}

// Corrected eq. 10: u = (q - a) / (e - a).
float LocalCoordinate(float q, float a, float e)
{
    return (q - a) / (e - a);
}

// o = ((ti + s) / M, (tj + t) / M). tile + tess is formed first: on a shared edge both tiles get the
// same small integer exactly (ti + 1 == (ti + 1) + 0), so shared edges give bit-identical o.
float2 RangeCoordinate(uint2 tile, float2 tess, float tiles)
{
    precise float2 sum = float2(tile) + tess;
    return sum / tiles;
}

// range = _Range = (c, d, g, h) - (O, O); rangeOrigin = _RangeOrigin = (hi.x, hi.y, lo.x, lo.y).
// local = originLo + (range.xy + o (range.zw - range.xy)): every term is of the size of the local
// range. With origin 0 this is the paper's q = c + o (g - c) bit for bit.
TerrainPoint RangeToTerrainPoint(float4 range, float4 rangeOrigin, float tiles, uint2 tile, float2 tess)
{
    float2 o = RangeCoordinate(tile, tess, tiles);
    precise float2 local = rangeOrigin.zw + (range.xy + o * (range.zw - range.xy));
    TerrainPoint p;
    p.originHi = rangeOrigin.xy;
    p.local = local;
    return p;
}

// q rounded to float: good for finding the patch that holds q, not for the local coordinate.
float2 TerrainPointApprox(TerrainPoint p)
{
    return p.originHi + p.local;
}

// Corrected eq. 10 for a TerrainPoint in region (a, b, e, f): u = ((originHi.x - a) + local.x) / (e - a).
// Trap: (originHi + local) - a would round q to ~6e-8 first and lose the fine local offset; the
// large difference is taken exactly (TwoSum), small parts are added together, one rounding at the end.
float2 PatchLocalUV(TerrainPoint p, float4 region)
{
    float eu, ev;
    float du = TwoSum(p.originHi.x, -region.x, eu);
    float dv = TwoSum(p.originHi.y, -region.y, ev);
    precise float nu = du + (eu + p.local.x);
    precise float nv = dv + (ev + p.local.y);
    return float2(nu / (region.z - region.x), nv / (region.w - region.y));
}

// The width and height (e - a, f - b) of a region given as hi/lo pairs (the grid lines of
// _GridLines): (e.hi - a.hi) + (e.lo - a.lo). A one-float e - a of a patch 1e-6 wide is off by up to 6%.
float2 RegionSize(float4 region, float4 regionLo)
{
    precise float2 size = (region.zw - region.xy) + (regionLo.zw - regionLo.xy);
    return size;
}

// PatchLocalUV for a hi/lo region: q - a = (originHi - a.hi) + (local - a.lo), over RegionSize.
// A line like 0.13 is off by 4.8e-9 as one float (9% of a range 1e-7 wide), by ~1e-16 as the pair.
float2 PatchLocalUV(TerrainPoint p, float4 region, float4 regionLo)
{
    float eu, ev;
    float du = TwoSum(p.originHi.x, -region.x, eu);
    float dv = TwoSum(p.originHi.y, -region.y, ev);
    precise float nu = du + (eu + (p.local.x - regionLo.x));
    precise float nv = dv + (ev + (p.local.y - regionLo.y));
    return float2(nu, nv) / RegionSize(region, regionLo);
}

#endif // GT_RANGE_MAPPING_INCLUDED
