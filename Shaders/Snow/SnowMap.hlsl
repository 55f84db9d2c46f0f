// The snow depth map as the terrain stages read it (keyword GT_SNOW). Mirrors Runtime/Core/Snow/SnowMap.cs.
//   depth   = _SnowDepth: R x R floats, cell (i, j) at j * R + i, centred on ((i + 0.5) / R, (j + 0.5) / R)
//   mapSize = _SnowMapSize = (R, 1/R, depthCap, 0)
// Pure functions of their arguments: TerrainInputs.hlsl declares the resources, and only under GT_SNOW.
#ifndef GT_SNOW_MAP_INCLUDED
#define GT_SNOW_MAP_INCLUDED

#include "SnowCells.hlsl"

// Depth, as a fraction of the cap, at which the surface is fully white (SnowMap.FullCoverFraction).
static const float GT_SNOW_FULL_COVER_FRACTION = 0.5;
static const float3 GT_SNOW_ALBEDO = float3(0.92, 0.94, 0.98);

// Depth at the global point q. A continuous function of q, so vertices with bit-identical q
// (shared tile edges) get the same depth: watertight.
float SnowMapSample(StructuredBuffer<float> depth, float4 mapSize, float2 q)
{
    SnowCellBlend b = SnowCellsBilinear(mapSize.x, q);
    return SnowCellsBlend(b, depth[b.c00], depth[b.c10], depth[b.c01], depth[b.c11]);
}

// How white the surface is: 0 (bare) to 1 (covered), a smoothstep up to half the cap.
float SnowMapCoverage(float depth, float depthCap)
{
    return smoothstep(0.0, GT_SNOW_FULL_COVER_FRACTION * depthCap, depth);
}

#endif // GT_SNOW_MAP_INCLUDED
