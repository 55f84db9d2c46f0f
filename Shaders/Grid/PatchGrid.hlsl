#ifndef GT_PATCH_GRID_INCLUDED
#define GT_PATCH_GRID_INCLUDED

// The patch grid on the GPU; mirrors PatchGrid.cs (FindPatch, FindInterval, RegionOf) and the
// layout of GpuLayout.cs. Declares no resource: include TerrainInputs.hlsl (which declares
// _ControlPoints, _Regions, _GridLines and _GridSize) before this file.
//   _ControlPoints  StructuredBuffer<GregoryPatchRecord>  one per patch, points[k] = slot k:
//                                             xyz = P - R_p, w of slots 0..2 = R_p (the reference point)
//   _Regions        StructuredBuffer<float4>  (a, b, e, f) per patch (the lines' hi parts)
//   _GridLines      StructuredBuffer<float>   hi parts xLines[0..n], yLines[0..m], then the lo parts
//   _GridSize       float4                    (n, m, 0, 0)

#include "../Library/GregoryPatch.hlsl"

// The largest i in [0, count - 1] with _GridLines[first + i] <= x (0 if none): the interval a uniform
// grid would give when its lines bracket x (one multiply, two reads), else a binary search over the
// interior lines; the same answer either way, the lines increase. The guess made the domain stage
// measurably cheaper than the search's dependent reads (Tools~/bench/records.md, "Where the domain stage's
// time goes"). count = number of intervals (n or m). A point on a shared line goes to the
// higher-index interval; x = 1 (the last line) stays in the last one; outside [0, 1] clamps.
uint PatchGridFindInterval(uint first, uint count, float x)
{
    uint g = x > 0.0 ? min((uint)(min(x, 1.0) * float(count)), count - 1u) : 0u;   // NaN: 0
    [branch] if (_GridLines[first + g] <= x && (g == count - 1u || _GridLines[first + g + 1u] > x))
        return g;
    uint lo = 0u;
    uint hi = count - 1u;
    [loop] while (lo < hi)
    {
        uint mid = (lo + hi + 1u) >> 1;
        if (_GridLines[first + mid] <= x)
            lo = mid;
        else
            hi = mid - 1u;
    }
    return lo;
}

// Index j * n + i of the patch containing the global point q (same rule as PatchGrid.FindPatch).
uint FindPatch(float2 q)
{
    uint n = (uint)_GridSize.x;
    uint m = (uint)_GridSize.y;
    uint i = PatchGridFindInterval(0u, n, q.x);
    uint j = PatchGridFindInterval(n + 1u, m, q.y);
    return j * n + i;
}

// Region (a, b, e, f) of a patch: it covers [a, e] x [b, f] (the hi parts of its grid lines).
float4 PatchRegion(uint patch)
{
    return _Regions[patch];
}

// The lo parts (a, b, e, f) of a patch's grid lines: PatchRegion + PatchRegionLo is the region to ~1e-16.
float4 PatchRegionLo(uint patch)
{
    uint n = (uint)_GridSize.x;
    uint i = patch % n;
    uint j = patch / n;
    uint lo = n + 1u + (uint)_GridSize.y + 1u;
    return float4(_GridLines[lo + i], _GridLines[lo + n + 1u + j], _GridLines[lo + i + 1u], _GridLines[lo + n + 1u + j + 1u]);
}

// The patch's reference point R_p (w of slots 0..2): the surface is R_p + the evaluation of the
// points LoadGregoryPatch gives (exact, the weights sum to 1).
float3 PatchReference(uint patch)
{
    return float3(_ControlPoints[patch].points[0].w, _ControlPoints[patch].points[1].w, _ControlPoints[patch].points[2].w);
}

// The 20 control points of a patch relative to its reference point, slot order of GregoryPatch.hlsl.
void LoadGregoryPatch(uint patch, out float3 cp[20])
{
    [unroll] for (uint k = 0u; k < 20u; k++)
        cp[k] = _ControlPoints[patch].points[k].xyz;
}

#endif // GT_PATCH_GRID_INCLUDED
