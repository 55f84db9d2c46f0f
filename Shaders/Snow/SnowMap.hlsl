// The snow depth map as the terrain stages read it (keyword GT_SNOW). Mirrors Runtime/Core/Snow/SnowMap.cs.
//   depth   = _SnowDepth: R x R floats, cell (i, j) at j * R + i, centred on ((i + 0.5) / R, (j + 0.5) / R)
//   mapSize = _SnowMapSize = (R, 1/R, depthCap, 0)
// Pure functions of their arguments: TerrainInputs.hlsl declares the resources, and only under GT_SNOW.
#ifndef GT_SNOW_MAP_INCLUDED
#define GT_SNOW_MAP_INCLUDED

// Depth, as a fraction of the cap, at which the surface is fully white (SnowMap.FullCoverFraction).
static const float GT_SNOW_FULL_COVER_FRACTION = 0.5;
static const float3 GT_SNOW_ALBEDO = float3(0.92, 0.94, 0.98);

// Depth at the global point q: bilinear between cell centres, edge cells repeated. A continuous
// function of q, so vertices with bit-identical q (shared tile edges) get the same depth: watertight.
float SnowMapSample(StructuredBuffer<float> depth, float4 mapSize, float2 q)
{
    int r = (int)mapSize.x;
    float2 uv = q * mapSize.x - 0.5;
    float2 f = floor(uv);
    float2 t = uv - f;
    int2 c0 = clamp((int2)f, 0, r - 1);
    int2 c1 = clamp((int2)f + 1, 0, r - 1);
    float d00 = depth[c0.y * r + c0.x], d10 = depth[c0.y * r + c1.x];
    float d01 = depth[c1.y * r + c0.x], d11 = depth[c1.y * r + c1.x];
    return lerp(lerp(d00, d10, t.x), lerp(d01, d11, t.x), t.y);
}

// How white the surface is: 0 (bare) to 1 (covered), a smoothstep up to half the cap.
float SnowMapCoverage(float depth, float depthCap)
{
    return smoothstep(0.0, GT_SNOW_FULL_COVER_FRACTION * depthCap, depth);
}

#endif // GT_SNOW_MAP_INCLUDED
