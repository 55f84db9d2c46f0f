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
    TileFactorSet tile = FromTileFactors(factors);
    uint limit = VertexCacheFactorLimit();
    uint base = drawPatch * VertexCacheSlotsPerTile(limit);
    if (!CellKeptWhole(factors.keptCellSpan))
        return CachedCellPointVaryings(base, CellPoint(tess, tile, CachedCellFactors(drawPatch), factors.keptCellSpan, limit), tessFactor);
    return CachedTerrainVaryings(base + VertexCacheSlot(tess, tile.edge, tile.inside, limit), tessFactor);
}

#if defined(GT_DEBUG_PATCH_ID)
// A record has no room for the patch index: the Patch Id view looks it up where the kernel evaluated
// the vertex's records (on a clipped tile, its cell's points, not the tile's evenly spread ones).
uint CachedVertexPatch(TileFactors factors, uint drawPatch, float2 tess)
{
    TileFactorSet cell = CachedCellFactors(drawPatch);
    uint limit = VertexCacheFactorLimit();
    CellPointBlend p = CellPoint(tess, FromTileFactors(factors), cell, factors.keptCellSpan, limit);
    return FindPatchAt(CellToTerrainPoint(FrameTileLayout(), drawPatch, CellPointTess(p, cell, limit)));
}
#endif

TerrainVaryings StageDomainVertex(TileFactors factors, uint drawPatch, float2 tess, float tessFactor)
{
    TerrainVaryings v = CachedTileVaryings(factors, drawPatch, tess, tessFactor);
#if defined(GT_DEBUG_PATCH_ID)
    v.patch = CachedVertexPatch(factors, drawPatch, tess);
#endif
    return v;
}

#endif // GT_VERTEX_SOURCE_CACHE_INCLUDED
