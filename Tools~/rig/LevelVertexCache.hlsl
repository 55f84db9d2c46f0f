// The Horizon levels' vertex cache layout (Tools~/docs/design-notes.md, "Levels of detail through a
// compute cache"). Mirrors Tools~/dotnet/Gt/LevelVertexCache.cs name for name; rig-side until the
// package has room for it (PackageSizeTests), then Shaders/Cache beside VertexCache.hlsl. Every drawn tile is
// evaluated again each frame the camera or the levels move, so records take a compact layout made
// again each frame: a draw patch takes S of its own largest integer factor (VertexCache.hlsl's slot
// rule, unchanged), a culled one none, its first record the exclusive prefix sum of those before it.
#ifndef GT_LEVEL_VERTEX_CACHE_INCLUDED
#define GT_LEVEL_VERTEX_CACHE_INCLUDED

#include "../../Shaders/Cache/VertexCache.hlsl"

// The largest of a tile's six integer factors (VertexCacheIntegerFactors): its slot rule's L; 0 culled.
uint LevelVertexCacheTileFactorLimit(TileFactorSet integerFactors)
{
    if (integerFactors.edge.x == 0.0) return 0u;
    float4 e = integerFactors.edge;
    return (uint)max(max(max(e.x, e.y), max(e.z, e.w)), max(integerFactors.inside.x, integerFactors.inside.y));
}

// The slots a draw patch at these integer factors takes: S(its own L), or 0 when culled.
uint LevelVertexCacheTileSlots(TileFactorSet integerFactors)
{
    uint limit = LevelVertexCacheTileFactorLimit(integerFactors);
    return limit == 0u ? 0u : VertexCacheSlotsPerTile(limit);
}

// The record of the vertex the tessellator puts at tess in a draw patch whose records start at firstRecord.
uint LevelVertexCacheRecord(uint firstRecord, float2 tess, TileFactorSet integerFactors)
{
    return firstRecord + VertexCacheSlot(tess, integerFactors.edge, integerFactors.inside, LevelVertexCacheTileFactorLimit(integerFactors));
}

#endif // GT_LEVEL_VERTEX_CACHE_INCLUDED
