// The Horizon levels' vertex cache layout (internals.md, "Levels of detail"). Mirrors
// Runtime/Core/Cache/LevelVertexCache.cs name for name. Every drawn tile is evaluated again each
// frame the levels draw, so records take a compact layout made again each frame: a draw patch takes
// S of its own largest integer factor (VertexCache.hlsl's slot rule, unchanged), a culled one none,
// its first record the exclusive prefix sum of those before it (LevelVertexCacheKernels.hlsl's scan).
#ifndef GT_LEVEL_VERTEX_CACHE_INCLUDED
#define GT_LEVEL_VERTEX_CACHE_INCLUDED

#include "VertexCache.hlsl"

// The largest of a tile's six integer factors (VertexCacheIntegerFactors): its slot rule's L; 0 culled.
uint LevelVertexCacheTileFactorLimit(TileFactorSet integerFactors)
{
    if (TileFactorsCulled(integerFactors)) return 0u;
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

// The kernel's point for the vertex at tess: exact k / F or (i / Iu, j / Iv), where the tessellator's
// coordinate carries its fixed-point error. A tile without records evaluates there: bit for bit.
float2 LevelVertexCachePointTess(float2 tess, TileFactorSet integerFactors)
{
    float4 e = integerFactors.edge;
    if (tess.x == 0.0) return VertexCacheEdgeTess(0u, (uint)round(tess.y * e.x), e.x);
    if (tess.y == 0.0) return VertexCacheEdgeTess(1u, (uint)round(tess.x * e.y), e.y);
    if (tess.x == 1.0) return VertexCacheEdgeTess(2u, (uint)round(tess.y * e.z), e.z);
    if (tess.y == 1.0) return VertexCacheEdgeTess(3u, (uint)round(tess.x * e.w), e.w);
    return round(tess * integerFactors.inside) / integerFactors.inside;
}

#endif // GT_LEVEL_VERTEX_CACHE_INCLUDED
