#ifndef GT_PATCH_GRID_INCLUDED
#define GT_PATCH_GRID_INCLUDED

// The patch grid on the GPU; mirrors PatchGrid.cs (FindPatch, FindInterval, RegionOf) and the
// layout of GpuLayout.cs. Declares no resource: include TerrainInputs.hlsl (which declares
// _ControlPoints, _Regions, _GridLines and _GridSize) before this file.
//   _ControlPoints  StructuredBuffer<float4>  20 per patch, patch p at [20 p .. 20 p + 19], w = 1
//   _Regions        StructuredBuffer<float4>  (a, b, e, f) per patch
//   _GridLines      StructuredBuffer<float>   xLines[0..n] then yLines[0..m]
//   _GridSize       float4                    (n, m, 0, 0)

#include "../Library/GregoryPatch.hlsl"

// The largest i in [0, count - 1] with _GridLines[first + i] <= x (0 if none), by binary search over
// the interior lines. count = number of intervals (n or m). A point on a shared line goes to the
// higher-index interval; x = 1 (the last line) stays in the last one; outside [0, 1] clamps.
uint PatchGridFindInterval(uint first, uint count, float x)
{
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

// Region (a, b, e, f) of a patch: it covers [a, e] x [b, f].
float4 PatchRegion(uint patch)
{
    return _Regions[patch];
}

// The 20 control points of a patch, slot order of GregoryPatch.hlsl.
void LoadGregoryPatch(uint patch, out float3 cp[20])
{
    uint base = GREGORY_SLOT_COUNT * patch;
    [unroll] for (uint k = 0u; k < 20u; k++)
        cp[k] = _ControlPoints[base + k].xyz;
}

#endif // GT_PATCH_GRID_INCLUDED
