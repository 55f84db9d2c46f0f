// Test kernel (VertexCacheGpuTests): the vertex cache's layout functions (Shaders/Cache/VertexCache.hlsl)
// and the factor sample count (Shaders/Terrain/TileFactors.hlsl) on the GPU, for Core's mirrors
// VertexCache and VertexCacheBudget. Lane i writes, for the factor limit L = i + 1:
// (slots a tile, groups a tile, most points a tile, factor samples a tile), then
// (0, 0, lanes a factors group, passes a vertex group), then (0, lanes a vertex group, 0, 0), then
// (0, float4 of factor inputs, 0, 0). Compiled with the
// rig's register shifts (u4 -> binding 9); only pure functions are called, so the terrain's own
// buffers and constants are declared but never read.
#define GT_VERTEX_CACHE
#include "../../Shaders/Pipelines/StandaloneAdapter.hlsl"
#include "../../Shaders/Cache/VertexCache.hlsl"

RWStructuredBuffer<uint4> _Layout : register(u4);

[numthreads(64, 1, 1)]
void VertexCacheLayoutProbe(uint3 id : SV_DispatchThreadID)
{
    uint limit = id.x + 1u;
    _Layout[4u * id.x] = uint4(VertexCacheSlotsPerTile(limit), VertexCacheGroupsPerTile(limit),
                               VertexCacheMaxTilePoints(limit), GT_TILE_FACTOR_SAMPLES);
    _Layout[4u * id.x + 1u] = uint4(0u, 0u, GT_VERTEX_CACHE_GROUP, GT_VERTEX_CACHE_PASSES);
    _Layout[4u * id.x + 2u] = uint4(0u, GT_VERTEX_CACHE_VERTEX_GROUP, 0u, 0u);
    _Layout[4u * id.x + 3u] = uint4(0u, GT_FACTOR_INPUTS, 0u, 0u);
}
