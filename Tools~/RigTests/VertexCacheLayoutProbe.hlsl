// Test kernel (VertexCacheGpuTests): the vertex cache's layout functions (Shaders/Cache/VertexCache.hlsl)
// and the factor sample count (Shaders/Terrain/TileFactors.hlsl) on the GPU, for Core's mirrors
// VertexCache and VertexCacheBudget. Lane i writes, for the factor limit L = i + 1 and tile i of
// 7 x 7 tiles: (slots a tile, groups a tile, most points a tile, factor samples a tile), then
// (factor record index, evaluated-range index, lanes a factors group, passes a vertex group), then
// (the index of the tile's factor sample i mod 51, lanes a vertex group, cell key index, cell
// factor index), then (factor inputs index, float4 of factor inputs, 0, 0). Compiled with the
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
    _Layout[4u * id.x + 1u] = uint4(VertexCacheFactorIndex(id.x), VertexCacheEvaluatedRangeIndex(id.x, 7u),
                                    GT_VERTEX_CACHE_GROUP, GT_VERTEX_CACHE_PASSES);
    _Layout[4u * id.x + 2u] = uint4(VertexCacheFactorSampleIndex(id.x, id.x % GT_TILE_FACTOR_SAMPLES, 7u), GT_VERTEX_CACHE_VERTEX_GROUP,
                                    VertexCacheCellKeyIndex(id.x, 7u), VertexCacheCellFactorIndex(id.x, 7u));
    _Layout[4u * id.x + 3u] = uint4(VertexCacheFactorInputsIndex(id.x, 7u), GT_FACTOR_INPUTS, 0u, 0u);
}
