#ifndef GT_RELATIVE_SURFACE_INCLUDED
#define GT_RELATIVE_SURFACE_INCLUDED

// The deep-zoom vertex position S(q) - S(O), O the range origin, from precise local differences;
// mirrors RelativeSurface.cs (float path), whose summary says how. Active when _RangeOrigin is not
// zero; the renderer then adds S(O), in double, in the object-to-world transform.
// Include TerrainInputs.hlsl (the buffers) before this file.

#include "RangeMapping.hlsl"
#include "../Grid/PatchGrid.hlsl"
#include "GregoryDifference.hlsl"

// p - r per axis, precise to float's relative precision of the result (TwoSum of the large parts).
float2 TerrainPointDifference(TerrainPoint p, TerrainPoint r)
{
    float ex, ey;
    float sx = TwoSum(p.originHi.x, -r.originHi.x, ex);
    float sy = TwoSum(p.originHi.y, -r.originHi.y, ey);
    precise float2 d = float2(sx + (ex + (p.local.x - r.local.x)), sy + (ey + (p.local.y - r.local.y)));
    return d;
}

TerrainPoint MakeTerrainPoint(float2 hi, float2 lo)
{
    TerrainPoint p;
    p.originHi = hi;
    p.local = lo;
    return p;
}

bool RelativeSurfaceIsActive(float4 rangeOrigin) { return any(rangeOrigin != 0.0); }

// FindPatch decided on the precise point, from `patch`, FindPatch's answer on the rounded point: that
// can be one patch off within a float step of a grid line, where u or v would be clamped (a flat
// strip at deep zoom). The lines are the hi/lo pairs of _GridLines (right to ~1e-16).
uint FindPatchCorrect(TerrainPoint q, uint patch)
{
    uint n = GridColumns();
    uint i = patch % n;
    uint j = patch / n;
    float4 region = PatchRegion(patch);
    float4 regionLo = PatchRegionLo(patch);
    float2 lo = TerrainPointDifference(q, MakeTerrainPoint(region.xy, regionLo.xy));
    float2 hi = TerrainPointDifference(q, MakeTerrainPoint(region.zw, regionLo.zw));
    if (lo.x < 0.0 && i > 0u) i--;
    else if (hi.x >= 0.0 && i < n - 1u) i++;
    if (lo.y < 0.0 && j > 0u) j--;
    else if (hi.y >= 0.0 && j < GridRows() - 1u) j++;
    return j * n + i;
}

// The FindPatch rule decided on the precise point (the deep-zoom paths).
uint FindPatchPrecise(TerrainPoint q)
{
    return FindPatchCorrect(q, FindPatch(TerrainPointApprox(q)));
}

// The tile path's lookup: FindPatchPrecise while q has a hi part (a range origin is set: every
// point of the frame has the origin's, so the branch is uniform; compiled with GT_RANGE_ORIGIN_CODE
// only, TerrainInputs.hlsl), else FindPatch on the plain float
// point. Without an origin q is one float: a point within a float step of a line is one rounding
// from either patch, whose surfaces meet there, so the correction buys nothing visible and cost a
// fifth of the domain stage (Tools~/bench/records.md, "Where the domain stage's time goes").
uint FindPatchAt(TerrainPoint q)
{
    uint patch = FindPatch(TerrainPointApprox(q));
#if defined(GT_RANGE_ORIGIN_CODE)
    [branch] if (any(q.originHi != 0.0))
        patch = FindPatchCorrect(q, patch);
#endif
    return patch;
}

// p clamped into the hi/lo region (a, b, e, f) per axis; p itself, bit for bit, when inside.
TerrainPoint ClampToRegion(TerrainPoint p, float4 region, float4 regionLo)
{
    float2 lo = TerrainPointDifference(p, MakeTerrainPoint(region.xy, regionLo.xy));
    float2 hi = TerrainPointDifference(p, MakeTerrainPoint(region.zw, regionLo.zw));
    TerrainPoint r = p;
    if (lo.x < 0.0) { r.originHi.x = region.x; r.local.x = regionLo.x; }
    else if (hi.x > 0.0) { r.originHi.x = region.z; r.local.x = regionLo.z; }
    if (lo.y < 0.0) { r.originHi.y = region.y; r.local.y = regionLo.y; }
    else if (hi.y > 0.0) { r.originHi.y = region.w; r.local.y = regionLo.w; }
    return r;
}

// S_p(x) - S_p(r) in one patch; u0 clamped to [0, 1], the step not (see the C#). The control
// points are relative to the patch's reference point, which a difference does not see.
float3 PatchDifference(uint patch, float4 region, float4 regionLo, TerrainPoint x, TerrainPoint r)
{
    float3 cp[20];
    LoadGregoryPatch(patch, cp);
    float2 uv0 = saturate(PatchLocalUV(r, region, regionLo));
    float2 duv = clamp(TerrainPointDifference(x, r) / RegionSize(region, regionLo), -1.0, 1.0);
    return GregoryDifferenceEvaluate(cp, uv0, duv);
}

// S(q) - S(O) as a sum of differences within one patch each: S_p(q) - S_p(r1), r1 = O clamped into
// q's patch p, then, while that point is not O, one patch (or diagonal) step toward O at a time, each
// step from where the last ended (on the line or corner the two patches share, so inside the next one
// bit for bit) to O clamped into the next patch. A neighbour of O's patch takes one step (deep zoom);
// the levels' far tiles take more, each a difference across one patch (float keeps ~6e-8 of a patch).
// One PatchDifference call site: the driver keeps registers for this code even where no vertex of a
// frame enters it (no range origin).
float3 RelativeSurfaceFromOrigin(TerrainPoint q, float4 rangeOrigin)
{
    TerrainPoint origin = MakeTerrainPoint(rangeOrigin.xy, rangeOrigin.zw);
    uint n = GridColumns();
    uint patch = FindPatchPrecise(q);
    int2 cell = int2(patch % n, patch / n);
    TerrainPoint from = q;   // the first step starts at q itself (outside [0, 1] the difference extrapolates)
    float3 d = 0.0;
    [loop] for (uint k = 0u; k <= n + GridRows(); k++)
    {
        uint p = (uint)cell.y * n + (uint)cell.x;
        float4 region = PatchRegion(p);
        float4 regionLo = PatchRegionLo(p);
        TerrainPoint to = ClampToRegion(origin, region, regionLo);
        d += PatchDifference(p, region, regionLo, from, to);
        int2 step = int2(sign(TerrainPointDifference(origin, to)));   // 0 on an axis where O is inside p
        if (all(step == 0)) break;
        cell += step;
        from = to;
    }
    return d;
}

#endif // GT_RELATIVE_SURFACE_INCLUDED
