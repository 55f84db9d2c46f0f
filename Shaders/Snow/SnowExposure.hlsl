#ifndef GT_SNOW_EXPOSURE_INCLUDED
#define GT_SNOW_EXPOSURE_INCLUDED

#include "SnowCells.hlsl"

// L(x, w) of the snow paper's eq. 1: exposure of a snow-map cell to the wind-driven snowfall.
// Mirrors Runtime/Core/Snow/SnowExposure.cs (read its summary for the derivation).
//   field: R x R cells, float4 (detail normal.xyz, height), cell (i, j) at j * R + i
//   grid = _SnowGrid = (R, 1/R, rayLength, raySteps)
//   fall = _SnowFall = (upwind.xy, cos F, sin F), F the elevation of the fall line

// sin(H - F) of one march sample (height difference dz at horizontal distance t > 0):
// > 0 when the sample stands above the fall line. Bounded in [-1, 1]; t > 0 keeps the root > 0.
float SnowExposureOcclusion(float dz, float t, float cosF, float sinF)
{
    return (dz * cosF - t * sinF) / sqrt(t * t + dz * dz);
}

// L = 1 at or below the fall line, 0 once the worst blocker is `softness` (in sin) above it.
float SnowExposureFromOcclusion(float occlusion, float softness)
{
    return 1.0 - smoothstep(0.0, softness, occlusion);
}

// Bilinear height at terrain point p between cell centres, edge cells repeated outside.
float SnowExposureSampleHeight(StructuredBuffer<float4> field, float4 grid, float2 p)
{
    SnowCellBlend b = SnowCellsBilinear(grid.x, p);
    return SnowCellsBlend(b, field[b.c00].w, field[b.c10].w, field[b.c01].w, field[b.c11].w);
}

// L at cell (i, j): march upwind, keep the worst blocker, map it smoothly.
float SnowExposureEvaluate(StructuredBuffer<float4> field, uint2 cell, float4 grid, float4 fall, float softness)
{
    if (!(fall.z > 0.0)) return 1.0; // no horizontal wind: snow falls straight, nothing shields
    int r = (int)grid.x;
    float2 x = (float2(cell) + 0.5) * grid.y;
    float h0 = field[cell.y * r + cell.x].w;
    int steps = (int)grid.w;
    float stepLength = grid.z / grid.w;
    float occlusion = -1.0;
    for (int k = 1; k <= steps; k++)
    {
        float t = k * stepLength;
        float2 p = x + fall.xy * t; // fall.xy points upwind
        if (p.x < 0.0 || p.x > 1.0 || p.y < 0.0 || p.y > 1.0) break; // beyond the terrain: open ground
        float dz = SnowExposureSampleHeight(field, grid, p) - h0;
        occlusion = max(occlusion, SnowExposureOcclusion(dz, t, fall.z, fall.w));
    }
    return SnowExposureFromOcclusion(occlusion, softness);
}

#endif // GT_SNOW_EXPOSURE_INCLUDED
