// The Horizon levels' tile factors in two compute kernels (GT_LOD; internals.md, "Levels of detail"),
// dispatched before the levels' draw; the hull then reads each draw patch's record (_LodLevels.y = 1)
// instead of evaluating 51 surface samples per invocation. Include a pipeline adapter first (Unity:
// TerrainCache.compute; the rig: Tools~/rig/TerrainRig.hlsl).
//
//   LodFactorPieces   a group per draw patch, dispatch (M^2, L, 1): the tile's samples one a lane,
//                     its seven pieces one a lane (CacheTileFactors' split); the factors are culled in
//                     no view (each pass culls in its own in the hull, StageTileFactors, shadow maps
//                     included); pieces[1].w flags a tile the camera's view culls (ViewCullsTile), which
//                     the vertex cache gives no records
//   LodFactorSeams    a thread per draw patch, dispatch (ceil(L M^2 / 64), 1, 1): the tile's factors
//                     from its pieces, then the seam rule (LodSeamFactors), the coarse edge across a
//                     fine seam read from the coarse tile's pieces, not computed again
// Every frame, in that order: nothing is kept, so moving costs what still does. The levels' vertex
// cache's kernels (LevelVertexCacheKernels.hlsl) follow, when the renderer draws from it.
#ifndef GT_LEVEL_FACTOR_KERNELS_INCLUDED
#define GT_LEVEL_FACTOR_KERNELS_INCLUDED

#include "../Terrain/TerrainVertex.hlsl"
#include "../Terrain/TileFactors.hlsl"
#include "../Pipelines/LevelTiles.hlsl"
#include "TileFactorGroup.hlsl"

// The same buffer as the hull's _LodFactors (t5): binding 7 in the rig either way.
RWStructuredBuffer<LodFactorRecord> _LodFactorsRW GT_REGISTER(u2);

uint LodDrawPatches() { return LodLevelCount() * LodTilesPerLevel(TileCountInt()); }

// Every lane reaches both barriers: nothing returns before them.
[numthreads(64, 1, 1)]
void LodFactorPieces(uint3 group : SV_GroupID, uint lane : SV_GroupIndex)
{
    uint patch = group.y * LodTilesPerLevel(TileCountInt()) + group.x, slot;
    TileLayout l = StageTileLayout(patch, slot);
    if (lane < GT_TILE_FACTOR_SAMPLES) gtTileFactorSamples[lane] = TileFactorSampleAt(lane, TileFactorSamplePosition(l, slot, lane));
    GroupMemoryBarrierWithGroupSync();
    float3 cornerOS[4];
    [unroll] for (uint c = 0u; c < 4u; c++)
        cornerOS[c] = gtTileFactorSamples[c].xyz;
    WriteGroupTileFactorPiece(l, slot, lane, cornerOS);
    GroupMemoryBarrierWithGroupSync();
    if (lane != 0u || patch >= LodDrawPatches()) return;
    _LodFactorsRW[patch].pieces[0] = float4(gtTileFactorPieces[0], gtTileFactorPieces[1], gtTileFactorPieces[2], gtTileFactorPieces[3]);
    _LodFactorsRW[patch].pieces[1] = float4(gtTileFactorPieces[4], gtTileFactorPieces[5], gtTileFactorPieces[6], ViewCullsTile(l, slot, cornerOS) ? 1.0 : 0.0);
}

// ComputeTileFactors from the pieces LodFactorPieces wrote.
TileFactorSet KernelCellFactors(TileLayout l, uint slot, uint drawPatch)
{
    TileFactorSet f;
    if (TileEmpty(l, slot)) return CulledTileFactors();
    if (UniformTileFactors(f)) return f;
    float4 a = _LodFactorsRW[drawPatch].pieces[0], b = _LodFactorsRW[drawPatch].pieces[1];
    float piece[GT_TILE_FACTOR_PIECES] = { a.x, a.y, a.z, a.w, b.x, b.y, b.z };
    return TileFactorsOfCell(TileFactorsOfPieces(piece), TileKeptFraction(l, slot));
}

// CoarseSeamEdgeFactor with the coarse tile's piece read from its record.
float KernelCoarseSeamEdgeFactor(uint drawPatch, uint edgeBit, int2 abUp)
{
    if (UsesUniformTessFactor()) return UniformTessFactor();
    uint piece;
    float4 edges = _LodFactorsRW[FineSeamCoarsePatch(drawPatch, edgeBit, abUp, piece)].pieces[0];
    return max(edges[piece], 1.0);
}

// LodTileFactors on the record: what the hull stage would return for the draw patch.
[numthreads(64, 1, 1)]
void LodFactorSeams(uint3 id : SV_DispatchThreadID)
{
    uint patch = id.x, slot, coarseMask, fineMask;
    if (patch >= LodDrawPatches()) return;
    TileLayout l = StageTileLayout(patch, slot);
    bool inside;
    int2 ab, abUp;
    LodTileSeams(patch, coarseMask, fineMask, inside, ab, abUp);
    TileFactorSet set = CulledTileFactors();
    if (!inside) set = KernelCellFactors(l, slot, patch);
    float across[4] = { 0.0, 0.0, 0.0, 0.0 };
    if (!TileFactorsCulled(set))
        [unroll] for (uint i = 0u; i < 4u; i++)
            if ((fineMask & (1u << i)) != 0u) across[i] = KernelCoarseSeamEdgeFactor(patch, 1u << i, abUp);
    set = LodSeamFactors(set, coarseMask, fineMask, float4(across[0], across[1], across[2], across[3]));
    _LodFactorsRW[patch].edge = set.edge;
    _LodFactorsRW[patch].inside = float4(set.inside, 0.0, 0.0);
}

#endif // GT_LEVEL_FACTOR_KERNELS_INCLUDED
