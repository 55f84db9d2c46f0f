// Vertex source: the domain stage (the default). The hull stage decides each tile's factors from its
// corners' surface points (TileFactors.hlsl); the domain stage evaluates each vertex (TerrainVertex.hlsl).
// Every VertexSource.*.hlsl defines the same stage shape, read by TerrainStages.hlsl's entry points:
//   GT_STAGE_PARTITIONING                 the hull stage's partitioning unless GT_PARTITIONING is set
//   StageTileLayout(drawPatch, out slot)  the layout a draw patch is drawn with and its tile there
//   StageCornerPosition(drawPatch, c)     corner c's surface point without noise, object space
//   StageTileFactors(corners)             hull_const's factors
//   StageDomainVertex(factors, drawPatch, tess, tessFactor)   the domain stage's vertex
#ifndef GT_VERTEX_SOURCE_DOMAIN_INCLUDED
#define GT_VERTEX_SOURCE_DOMAIN_INCLUDED

// Factors change continuously with the view, so no popping.
#define GT_STAGE_PARTITIONING "fractional_odd"

TileLayout StageTileLayout(uint drawPatch, out uint slot)
{
    slot = drawPatch;
    return FrameTileLayout();
}

float3 StageCornerPosition(uint drawPatch, uint corner)
{
    uint slot;
    TileLayout l = StageTileLayout(drawPatch, slot);
    return CellCornerObjectPosition(l, slot, corner);
}

TileFactors StageTileFactors(InputPatch<TileCorner, 4> corners)
{
    uint slot;
    TileLayout l = StageTileLayout(corners[0].drawPatch, slot);
    return ToTileFactors(CornerTileFactors(l, slot, corners));
}

TerrainVaryings StageDomainVertex(TileFactors factors, uint drawPatch, float2 tess, float tessFactor)
{
    return TerrainVertex(FrameTileLayout(), drawPatch, tess, tessFactor);
}

#endif // GT_VERTEX_SOURCE_DOMAIN_INCLUDED
