// Vertex source: the Horizon levels (GT_LOD): L levels in one draw (LodTiles.hlsl), draw patch p is
// tile p mod M^2 of level p / M^2. The domain stage's factors and vertices, with the seam rule where
// levels meet. Stage shape: VertexSource.Domain.hlsl.
#ifndef GT_VERTEX_SOURCE_LEVELS_INCLUDED
#define GT_VERTEX_SOURCE_LEVELS_INCLUDED

// The seam rule needs integer factors: 2g coarse segments meet g + g fine.
#define GT_STAGE_PARTITIONING "integer"

TileLayout StageTileLayout(uint drawPatch, out uint slot)
{
    slot = LodSlotOfPatch(drawPatch, TileCountInt());
    return LodLevelLayout(LodLevelOfPatch(drawPatch, TileCountInt()));
}

float3 StageCornerPosition(uint drawPatch, uint corner)
{
    uint slot;
    TileLayout l = StageTileLayout(drawPatch, slot);
    return CellCornerObjectPosition(l, slot, corner);
}

// The seams of draw patch p's tile (LodTiles.hlsl): coarseMask, its edges on the rim of the finer
// level (none on level 0), fineMask, its edges on its own level's boundary where a coarser level
// lies beyond (none on the last level); inside: wholly inside the finer level (culled). ab: the
// finer level's offset in this level's cells, abUp this level's in the coarser one's.
void LodTileSeams(uint drawPatch, out uint coarseMask, out uint fineMask, out bool inside, out int2 ab, out int2 abUp)
{
    uint m = TileCountInt();
    uint level = LodLevelOfPatch(drawPatch, m), slot = LodSlotOfPatch(drawPatch, m);
    int2 tile = int2(slot % m, slot / m);
    coarseMask = 0u;
    fineMask = 0u;
    inside = false;
    ab = int2(0, 0);
    abUp = int2(0, 0);
    if (level > 0u)
    {
        ab = FinerOffsetCells(LodRange(level), LodRange(level - 1u), TileCount());
        inside = TileInsideFiner(tile, ab, (int)m);
        coarseMask = CoarseSeamEdges(tile, ab, (int)m);
    }
    if (level + 1u < LodLevelCount())
    {
        abUp = FinerOffsetCells(LodRange(level + 1u), LodRange(level), TileCount());
        fineMask = FineSeamEdges(tile, abUp, (int)m);
    }
}

// The factor of edge `edge` (0..3) of the coarse tile across a fine seam edge: what that coarse
// tile's hull computes for it (the same function of the same inputs), uniform or adaptive.
float CoarseSeamEdgeFactor(uint drawPatch, uint edgeBit, int2 abUp)
{
    if (UsesUniformTessFactor()) return UniformTessFactor();
    uint m = TileCountInt();
    uint level = LodLevelOfPatch(drawPatch, m), slot = LodSlotOfPatch(drawPatch, m);
    uint coarseEdge;
    int upperHalf;
    int2 coarseTile = FineSeamCoarseTile(edgeBit, int2(slot % m, slot / m), abUp, coarseEdge, upperHalf);
    uint coarseSlot = (uint)coarseTile.y * m + (uint)coarseTile.x;
    TileLayout coarse = LodLevelLayout(level + 1u);
    float3 cornerOS[4];
    [unroll] for (uint c = 0; c < 4; c++)
        cornerOS[c] = CellCornerObjectPosition(coarse, coarseSlot, c);
    uint piece = coarseEdge == GT_EDGE_U0 ? 0u : (coarseEdge == GT_EDGE_V0 ? 1u : (coarseEdge == GT_EDGE_U1 ? 2u : 3u));
    return max(TileFactorPiece(coarse, coarseSlot, piece, cornerOS), 1.0);
}

// The seam rule on a tile's factors: tiles inside the finer level culled; a coarse seam edge of
// factor f draws 2g, each fine one g, g = SeamHalfFactor of the coarse edge's factor.
TileFactorSet LodTileFactors(uint drawPatch, TileFactorSet set)
{
    uint coarseMask, fineMask;
    bool inside;
    int2 ab, abUp;
    LodTileSeams(drawPatch, coarseMask, fineMask, inside, ab, abUp);
    if (inside) return CulledTileFactors();
    if (TileFactorsCulled(set)) return set;
    float edge[4] = { set.edge.x, set.edge.y, set.edge.z, set.edge.w };
    [unroll] for (uint i = 0u; i < 4u; i++)
    {
        uint bit = 1u << i;
        if ((coarseMask & bit) != 0u) edge[i] = 2.0 * SeamHalfFactor(edge[i], MaxTessFactor());
        else if ((fineMask & bit) != 0u) edge[i] = SeamHalfFactor(CoarseSeamEdgeFactor(drawPatch, bit, abUp), MaxTessFactor());
    }
    set.edge = float4(edge[0], edge[1], edge[2], edge[3]);
    return set;
}

TileFactors StageTileFactors(InputPatch<TileCorner, 4> corners)
{
    uint patch = corners[0].drawPatch, slot;
    TileLayout l = StageTileLayout(patch, slot);
    return ToTileFactors(LodTileFactors(patch, CornerTileFactors(l, slot, corners)));
}

// The domain stage's vertex: a seam vertex's q is the coarse tile's point (SeamCoarsePoint), formed
// alike on both sides; any other vertex its tile's own point.
TerrainVaryings LodDomainVertex(uint drawPatch, float2 tess, float4 edgeFactors, float tessFactor)
{
    uint slot;
    TileLayout l = StageTileLayout(drawPatch, slot);
    uint m = TileCountInt();
    uint level = LodLevelOfPatch(drawPatch, m);
    int2 tile = int2(slot % m, slot / m);
    uint coarseMask, fineMask;
    bool inside;
    int2 ab, abUp;
    LodTileSeams(drawPatch, coarseMask, fineMask, inside, ab, abUp);
    TerrainPoint q = TileToTerrainPoint(l, slot, tess);
    uint coarseEdge = SeamEdgeAt(coarseMask, tess), fineEdge = SeamEdgeAt(fineMask, tess);
    float factors[4] = { edgeFactors.x, edgeFactors.y, edgeFactors.z, edgeFactors.w };
    if (coarseEdge != 0u)
        q = SeamCoarsePoint(false, coarseEdge, tess, 0.5 * factors[firstbitlow(coarseEdge)], tile, l.range, l.range, ab, l.origin, TileCount());
    else if (fineEdge != 0u)
        q = SeamCoarsePoint(true, fineEdge, tess, factors[firstbitlow(fineEdge)], tile, l.range, LodRange(level + 1u), abUp, l.origin, TileCount());
    return TerrainVertexAtPoint(l, drawPatch, tess, q, tessFactor);
}

TerrainVaryings StageDomainVertex(TileFactors factors, uint drawPatch, float2 tess, float tessFactor)
{
    return LodDomainVertex(drawPatch, tess, float4(factors.edge[0], factors.edge[1], factors.edge[2], factors.edge[3]), tessFactor);
}

#endif // GT_VERTEX_SOURCE_LEVELS_INCLUDED
