// Vertex source: the Horizon levels (GT_LOD): L levels in one draw (LodTiles.hlsl), draw patch p is
// tile p mod M^2 of level p / M^2. The domain stage's factors and vertices, with the seam rule where
// levels meet. Stage shape: VertexSource.Domain.hlsl.
#ifndef GT_VERTEX_SOURCE_LEVELS_INCLUDED
#define GT_VERTEX_SOURCE_LEVELS_INCLUDED

// The seam rule needs integer factors: 2g coarse segments meet g + g fine.
#define GT_STAGE_PARTITIONING "integer"

#include "LevelTiles.hlsl"

float3 StageCornerPosition(uint drawPatch, uint corner)
{
    uint slot;
    TileLayout l = StageTileLayout(drawPatch, slot);
    return CellCornerObjectPosition(l, slot, corner);
}

// The tile's factors: the factor kernels' record while the renderer dispatched them this frame
// (LodKernelFactorsOn, a uniform), else computed here from the corners. The record is the camera's
// factors for every tile, culled in no view: each pass culls in its own (a shadow map's view keeps the
// tiles off screen that cast into it), after the uniform factor as ComputeTileFactors does.
TileFactors StageTileFactors(InputPatch<TileCorner, 4> corners)
{
    uint patch = corners[0].drawPatch, slot;
    TileLayout l = StageTileLayout(patch, slot);
    [branch] if (LodKernelFactorsOn())
    {
        float3 cornerOS[4];
        [unroll] for (uint c = 0; c < 4; c++)
            cornerOS[c] = corners[c].positionOS;
        if (!UsesUniformTessFactor() && TileCulled(cornerOS, TileNoiseMargin(l, slot))) return ToTileFactors(CulledTileFactors());
        return ToTileFactors(LodKernelTileFactors(patch));
    }
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
