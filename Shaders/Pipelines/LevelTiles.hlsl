// The Horizon levels' draw patches (GT_LOD; LodTiles.hlsl): where draw patch p lies, its seams, and
// the seam rule on its factors. Read by the levels' hull stage (VertexSource.Levels.hlsl) and by the
// factor kernels (Shaders/Cache/LevelFactorKernels.hlsl), so both apply one rule. Include after
// TerrainVertex.hlsl and TileFactors.hlsl.
#ifndef GT_LEVEL_TILES_INCLUDED
#define GT_LEVEL_TILES_INCLUDED

// Draw patch p: tile p mod M^2 (slot) of level p / M^2.
TileLayout StageTileLayout(uint drawPatch, out uint slot)
{
    slot = LodSlotOfPatch(drawPatch, TileCountInt());
    return LodLevelLayout(LodLevelOfPatch(drawPatch, TileCountInt()));
}

// The factor kernels' factors of a draw patch (its LodFactorRecord in _LodFactors).
TileFactorSet LodKernelTileFactors(uint drawPatch)
{
    TileFactorSet f;
    f.edge = _LodFactors[drawPatch].edge;
    f.inside = _LodFactors[drawPatch].inside.xy;
    return f;
}

// A draw patch's first record in _VertexCache (LodVertexSlots), or -1: none.
int LodFirstRecord(uint drawPatch) { return (int)_LodFactors[drawPatch].inside.z; }

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

// The coarse tile across fine seam edge `edgeBit` of draw patch p: its draw patch, and which of its
// pieces is its edge on the seam (edge bit 1 << k is piece k).
uint FineSeamCoarsePatch(uint drawPatch, uint edgeBit, int2 abUp, out uint piece)
{
    uint m = TileCountInt();
    uint level = LodLevelOfPatch(drawPatch, m), slot = LodSlotOfPatch(drawPatch, m);
    uint coarseEdge;
    int upperHalf;
    int2 coarseTile = FineSeamCoarseTile(edgeBit, int2(slot % m, slot / m), abUp, coarseEdge, upperHalf);
    piece = firstbitlow(coarseEdge);
    return (level + 1u) * LodTilesPerLevel(m) + (uint)coarseTile.y * m + (uint)coarseTile.x;
}

// The factor of the coarse tile's edge across a fine seam edge: what that coarse tile's hull
// computes for it (the same function of the same inputs), uniform or adaptive.
float CoarseSeamEdgeFactor(uint drawPatch, uint edgeBit, int2 abUp)
{
    if (UsesUniformTessFactor()) return UniformTessFactor();
    uint piece, coarseSlot;
    TileLayout coarse = StageTileLayout(FineSeamCoarsePatch(drawPatch, edgeBit, abUp, piece), coarseSlot);
    float3 cornerOS[4];
    [unroll] for (uint c = 0; c < 4; c++)
        cornerOS[c] = CellCornerObjectPosition(coarse, coarseSlot, c);
    return max(TileFactorPiece(coarse, coarseSlot, piece, cornerOS), 1.0);
}

// The seam rule on a tile's factors: a coarse seam edge of factor f draws 2g, each fine one g, g =
// SeamHalfFactor of the coarse edge's factor; across[i]: the factor of the coarse tile's edge across
// fine seam edge 1 << i (read only there). The hull stage and the factor kernels pass it in.
TileFactorSet LodSeamFactors(TileFactorSet set, uint coarseMask, uint fineMask, float4 across)
{
    if (TileFactorsCulled(set)) return set;
    float edge[4] = { set.edge.x, set.edge.y, set.edge.z, set.edge.w };
    float coarse[4] = { across.x, across.y, across.z, across.w };
    [unroll] for (uint i = 0u; i < 4u; i++)
    {
        uint bit = 1u << i;
        if ((coarseMask & bit) != 0u) edge[i] = 2.0 * SeamHalfFactor(edge[i], MaxTessFactor());
        else if ((fineMask & bit) != 0u) edge[i] = SeamHalfFactor(coarse[i], MaxTessFactor());
    }
    set.edge = float4(edge[0], edge[1], edge[2], edge[3]);
    return set;
}

// The hull stage's seam rule: tiles inside the finer level culled; the coarse edges across the fine
// seam edges computed here (CoarseSeamEdgeFactor), only for a tile that is drawn.
TileFactorSet LodTileFactors(uint drawPatch, TileFactorSet set)
{
    uint coarseMask, fineMask;
    bool inside;
    int2 ab, abUp;
    LodTileSeams(drawPatch, coarseMask, fineMask, inside, ab, abUp);
    if (inside) return CulledTileFactors();
    float across[4] = { 0.0, 0.0, 0.0, 0.0 };
    if (!TileFactorsCulled(set))
        [unroll] for (uint i = 0u; i < 4u; i++)
            if ((fineMask & (1u << i)) != 0u) across[i] = CoarseSeamEdgeFactor(drawPatch, 1u << i, abUp);
    return LodSeamFactors(set, coarseMask, fineMask, float4(across[0], across[1], across[2], across[3]));
}

// The terrain point of the vertex at tess of draw patch p (tile `slot` of layout l): a seam vertex's
// q is the coarse tile's point (SeamCoarsePoint), formed alike on both sides; any other vertex its
// tile's own point. edgeFactors: the tile's edge factors as the hull output them (the seam's g).
TerrainPoint LodVertexPoint(TileLayout l, uint slot, uint drawPatch, float2 tess, float4 edgeFactors)
{
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
    return q;
}

// The levels' vertex: what the domain stage draws and the vertex kernel stores.
TerrainVertexAttributes EvaluateLodTerrainVertex(uint drawPatch, float2 tess, float4 edgeFactors)
{
    uint slot;
    TileLayout l = StageTileLayout(drawPatch, slot);
    return EvaluatePointTerrainVertex(l, drawPatch, tess, LodVertexPoint(l, slot, drawPatch, tess, edgeFactors));
}

// Whether a pass's hull culls the tile in its view (StageTileFactors); the factor kernels ask it in the
// camera's view, and the levels' vertex cache gives such a tile no records (LevelVertexCacheKernels.hlsl).
bool ViewCullsTile(TileLayout l, uint slot, float3 cornerOS[4])
{
    return !UsesUniformTessFactor() && TileCulled(cornerOS, TileNoiseMargin(l, slot));
}

#endif // GT_LEVEL_TILES_INCLUDED
