// Vertex source: the compute cache (GT_VERTEX_CACHE). A compute pre-pass decided each cell's factors
// and evaluated its vertices into slots (VertexCacheKernels.hlsl); the hull stage reads the factors,
// the domain stage the vertex, and only the camera transform is left. Stage shape: VertexSource.Domain.hlsl.
#ifndef GT_VERTEX_SOURCE_CACHE_INCLUDED
#define GT_VERTEX_SOURCE_CACHE_INCLUDED

#include "../Cache/ClippedCell.hlsl"
#if defined(GT_EXTEND_DRAW_PATCHES) || defined(GT_EXTEND_VERTEX) || defined(GT_EXTEND_TILE_FACTORS)
    #error "GT_VERTEX_CACHE draws tiles from the cache: no other draw patches, and the cache holds the vertices and factors"
#endif

// The cache stores vertices at k / F: only integer partitioning makes those.
#define GT_STAGE_PARTITIONING "integer"

TileLayout StageTileLayout(uint drawPatch, out uint slot)
{
    slot = drawPatch;
    return FrameTileLayout();
}

float3 StageCornerPosition(uint drawPatch, uint corner)
{
    return float3(0.0, 0.0, 0.0);   // the factors come from the cache
}

// The cell's factors, decided by CacheTileFactors, already integers (culled: all 0): what its
// slots hold. StageTileFactors clips them to the part of the cell the tile keeps; the domain stage
// reads them again for a clipped tile's records.
TileFactorSet CachedCellFactors(uint patch)
{
    TileFactorSet set;
    set.edge = _TileFactors[patch].edge;
    set.inside = _TileFactors[patch].inside.xy;
    return set;
}

// Anchored, the cache holds the tile's whole cell: draw the part of it the tile keeps
// (ClippedCell.hlsl), and tell the domain stage which part that is.
TileFactors StageTileFactors(InputPatch<TileCorner, 4> corners)
{
    uint patch = corners[0].drawPatch;
    float4 kept = TileKeptCellSpan(FrameTileLayout(), patch);
    TileFactors f = ToTileFactors(ClippedTileFactors(CachedCellFactors(patch), kept));
    f.keptCellSpan = kept;
    return f;
}

// The compute pass evaluated this vertex into its slot (a clipped tile's: from its cell's records).
TerrainVaryings CachedTileVaryings(TileFactors factors, uint drawPatch, float2 tess, float tessFactor)
{
    float4 edge = float4(factors.edge[0], factors.edge[1], factors.edge[2], factors.edge[3]);
    float2 inside = float2(factors.inside[0], factors.inside[1]);
    uint limit = VertexCacheFactorLimit();
    uint base = drawPatch * VertexCacheSlotsPerTile(limit);
    if (!CellKeptWhole(factors.keptCellSpan))
    {
        TileFactorSet tile;
        tile.edge = edge;
        tile.inside = inside;
        TileFactorSet cell = CachedCellFactors(drawPatch);
        return CachedCellPointVaryings(base, CellPoint(tess, tile, cell, factors.keptCellSpan, limit), tessFactor);
    }
    return CachedTerrainVaryings(base + VertexCacheSlot(tess, edge, inside, limit), tessFactor);
}

TerrainVaryings StageDomainVertex(TileFactors factors, uint drawPatch, float2 tess, float tessFactor)
{
    TerrainVaryings v = CachedTileVaryings(factors, drawPatch, tess, tessFactor);
#if defined(GT_DEBUG_PATCH_ID)
    // A record has no room for the patch index: the debug view finds it at the vertex's point.
    v.patch = FindPatchAt(TileToTerrainPoint(FrameTileLayout(), drawPatch, tess));
#endif
    return v;
}

#endif // GT_VERTEX_SOURCE_CACHE_INCLUDED
