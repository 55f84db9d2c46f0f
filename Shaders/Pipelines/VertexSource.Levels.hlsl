// Vertex source: the Horizon levels (GT_LOD): L levels in one draw (LodTiles.hlsl), draw patch p is
// tile p mod M^2 of level p / M^2. The domain stage's factors and vertices, with the seam rule where
// levels meet. Stage shape: VertexSource.Domain.hlsl.
#ifndef GT_VERTEX_SOURCE_LEVELS_INCLUDED
#define GT_VERTEX_SOURCE_LEVELS_INCLUDED

// The seam rule needs integer factors: 2g coarse segments meet g + g fine.
#define GT_STAGE_PARTITIONING "integer"

#include "LevelTiles.hlsl"
#include "../Cache/LevelVertexCache.hlsl"

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
        if (ViewCullsTile(l, slot, cornerOS)) return ToTileFactors(CulledTileFactors());
        return ToTileFactors(LodKernelTileFactors(patch));
    }
    return ToTileFactors(LodTileFactors(patch, CornerTileFactors(l, slot, corners)));
}

// While the vertex kernels ran (LodVertexCacheOn, a uniform) a tile reads its records, or without
// any evaluates at the kernel's points (LevelVertexCachePointTess): its edges match a cached neighbour's.
TerrainVaryings StageDomainVertex(TileFactors factors, uint drawPatch, float2 tess, float tessFactor)
{
    float4 edge = float4(factors.edge[0], factors.edge[1], factors.edge[2], factors.edge[3]);
    [branch] if (LodVertexCacheOn())
    {
        TileFactorSet drawn = VertexCacheIntegerFactors(FromTileFactors(factors));
        int first = LodFirstRecord(drawPatch);
        float2 kernelTess = LevelVertexCachePointTess(tess, drawn);
        if (first >= 0)
        {
            TerrainVaryings v = CachedTerrainVaryings(LevelVertexCacheRecord((uint)first, tess, drawn), tessFactor);
#if defined(GT_DEBUG_PATCH_ID)
            // The record has no room for the patch index: the debug view finds it at the kernel's point.
            uint s;
            TileLayout t = StageTileLayout(drawPatch, s);
            v.patch = FindPatchAt(LodVertexPoint(t, s, drawPatch, kernelTess, edge));
#endif
            return v;
        }
        tess = kernelTess;
    }
    uint slot;
    TileLayout l = StageTileLayout(drawPatch, slot);
    return TerrainVertexAtPoint(l, drawPatch, tess, LodVertexPoint(l, slot, drawPatch, tess, edge), tessFactor);
}

#endif // GT_VERTEX_SOURCE_LEVELS_INCLUDED
