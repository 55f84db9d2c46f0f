// Drawing the levels of detail (Documentation~/internals.md, "Levels of detail: from the feet to the
// horizon"). Mirrors Runtime/Core/Terrain/LodTiles.cs, same names, step for step. Library: every
// function takes what it needs as parameters; the levels' vertex source (VertexSource.Levels.hlsl)
// reads _Ranges and passes them in.
//
// Draw patch p is tile p mod M^2 of level p / M^2, finest first; the finer level covers M/2 x M/2
// coarse tiles at an integer offset (FinerOffsetCells), which are culled, so the seam is decided on
// integers, not on float lines. Seam vertices are formed on both sides as the coarse tile's point at
// tess n / (2g) (SeamCoarsePoint): the same q, the same vertex bit for bit (internals.md, "Seams
// without T-junctions").
#ifndef GT_LOD_TILES_INCLUDED
#define GT_LOD_TILES_INCLUDED

#include "../Library/RangeMapping.hlsl"

// Most levels a draw holds (the _Ranges array's length). Core LodTiles.MaxLevels.
#define GT_MAX_LOD_LEVELS 20

// Edge bits in the tessellator's order: u = 0 (x low), v = 0 (y low), u = 1 (x high), v = 1 (y high).
#define GT_EDGE_U0 1u
#define GT_EDGE_V0 2u
#define GT_EDGE_U1 4u
#define GT_EDGE_V1 8u

uint LodTilesPerLevel(uint tiles) { return tiles * tiles; }
uint LodLevelOfPatch(uint drawPatch, uint tiles) { return drawPatch / LodTilesPerLevel(tiles); }
uint LodSlotOfPatch(uint drawPatch, uint tiles) { return drawPatch % LodTilesPerLevel(tiles); }

// Where the finer range's corner sits in the coarser range, in coarse cells: an integer by the
// layout's snapping, rounded so the ranges' last bits do not matter.
int2 FinerOffsetCells(float4 coarse, float4 finer, float tiles)
{
    return int2(round((finer.xy - coarse.xy) / (coarse.zw - coarse.xy) * tiles));
}

// Coarse tile (ti, tj) wholly inside the finer level at offset ab: culled.
bool TileInsideFiner(int2 tile, int2 ab, int tiles)
{
    int h = tiles / 2;
    return all(tile >= ab) && all(tile < ab + h);
}

// The coarse tile's edges on the rim of the finer level's hole.
uint CoarseSeamEdges(int2 tile, int2 ab, int tiles)
{
    int h = tiles / 2;
    bool alongY = tile.y >= ab.y && tile.y < ab.y + h, alongX = tile.x >= ab.x && tile.x < ab.x + h;
    uint mask = 0u;
    if (alongY && tile.x == ab.x + h) mask |= GT_EDGE_U0;
    if (alongX && tile.y == ab.y + h) mask |= GT_EDGE_V0;
    if (alongY && tile.x == ab.x - 1) mask |= GT_EDGE_U1;
    if (alongX && tile.y == ab.y - 1) mask |= GT_EDGE_V1;
    return mask;
}

// The fine tile's edges on its range's boundary where the coarser level lies beyond (the level
// sits at offset ab in the coarser one's cells; at the terrain's edge nothing lies beyond).
uint FineSeamEdges(int2 tile, int2 ab, int tiles)
{
    int h = tiles / 2;
    uint mask = 0u;
    if (tile.x == 0 && ab.x > 0) mask |= GT_EDGE_U0;
    if (tile.y == 0 && ab.y > 0) mask |= GT_EDGE_V0;
    if (tile.x == tiles - 1 && ab.x + h < tiles) mask |= GT_EDGE_U1;
    if (tile.y == tiles - 1 && ab.y + h < tiles) mask |= GT_EDGE_V1;
    return mask;
}

// g = ceil(f / 2) of the coarse edge's factor f, in [1, floor(maxFactor / 2)]: the coarse seam edge
// draws 2g segments, each fine half g.
float SeamHalfFactor(float coarseEdgeFactor, float maxFactor)
{
    return clamp(ceil(coarseEdgeFactor * 0.5), 1.0, floor(maxFactor * 0.5));
}

// Tess coordinate n / (2g) along the edge, exactly 0 or 1 across it.
float2 SeamCoarseTess(uint edge, int numerator, float halfFactor)
{
    float along = float(numerator) / (2.0 * halfFactor);
    if (edge == GT_EDGE_U0) return float2(0.0, along);
    if (edge == GT_EDGE_U1) return float2(1.0, along);
    if (edge == GT_EDGE_V0) return float2(along, 0.0);
    return float2(along, 1.0);
}

// The coarse tile across fine seam edge `edge` of fine tile `tile` at offset ab, the coarse tile's
// edge on the seam, and which half of it the fine edge is (upperHalf 1: the upper tess half).
int2 FineSeamCoarseTile(uint edge, int2 tile, int2 ab, out uint coarseEdge, out int upperHalf)
{
    int2 f = 2 * ab + tile;   // the fine tile in fine cells of the coarse range
    if (edge == GT_EDGE_U0) { coarseEdge = GT_EDGE_U1; upperHalf = f.y % 2; return int2(ab.x - 1, f.y / 2); }
    if (edge == GT_EDGE_U1) { coarseEdge = GT_EDGE_U0; upperHalf = f.y % 2; return int2((f.x + 1) / 2, f.y / 2); }
    if (edge == GT_EDGE_V0) { coarseEdge = GT_EDGE_V1; upperHalf = f.x % 2; return int2(f.x / 2, ab.y - 1); }
    coarseEdge = GT_EDGE_V0;
    upperHalf = f.x % 2;
    return int2(f.x / 2, (f.y + 1) / 2);
}

// The first seam edge (in edge order) a vertex at tess lies on, or 0.
uint SeamEdgeAt(uint mask, float2 tess)
{
    if ((mask & GT_EDGE_U0) != 0u && tess.x == 0.0) return GT_EDGE_U0;
    if ((mask & GT_EDGE_V0) != 0u && tess.y == 0.0) return GT_EDGE_V0;
    if ((mask & GT_EDGE_U1) != 0u && tess.x == 1.0) return GT_EDGE_U1;
    if ((mask & GT_EDGE_V1) != 0u && tess.y == 1.0) return GT_EDGE_V1;
    return 0u;
}

// The tess coordinate along the edge (v on u-edges, u on v-edges).
float SeamAlong(uint edge, float2 tess) { return (edge & (GT_EDGE_U0 | GT_EDGE_U1)) != 0u ? tess.y : tess.x; }

// The global point of a seam vertex at tess of tile `tile` of level `range`. Coarse side (fine
// false): the edge draws 2g, n = round(along 2g). Fine side: g, n = round(along g) + upperHalf g on the
// coarse tile across (`coarser`; this level at offset ab in its cells). round() recovers n from a
// tessellator's fixed-point tess coordinate (lavapipe: 16.16). Both sides then form
// RangeToTerrainPoint of the coarse range, tile and SeamCoarseTess, bit for bit the same.
TerrainPoint SeamCoarsePoint(bool fine, uint edge, float2 tess, float halfFactor, int2 tile, float4 range,
                             float4 coarser, int2 ab, float4 rangeOrigin, float tiles)
{
    float along = SeamAlong(edge, tess);
    if (!fine)
    {
        int n = (int)round(along * 2.0 * halfFactor);
        return RangeToTerrainPoint(range, rangeOrigin, tiles, uint2(tile), SeamCoarseTess(edge, n, halfFactor));
    }
    uint coarseEdge;
    int upperHalf;
    int2 coarseTile = FineSeamCoarseTile(edge, tile, ab, coarseEdge, upperHalf);
    int m = (int)round(along * halfFactor) + upperHalf * (int)halfFactor;
    return RangeToTerrainPoint(coarser, rangeOrigin, tiles, uint2(coarseTile), SeamCoarseTess(coarseEdge, m, halfFactor));
}

#endif // GT_LOD_TILES_INCLUDED
