// The levels' vertex cache kernels (GT_LOD; internals.md, "Vertex cache of the levels"), after the
// factor kernels, whose records they read; the domain stage reads the records while _LodLevels.z = C.
//   LodVertexSlots     dispatch (1, 1, 1): each draw patch's slots (LodPatchSlots), their exclusive
//                      prefix sum into inside.z (-1: none, or past C), the total into patch 0's inside.w.
//                      A lane sums ceil(P / 256) patches, the lanes' sums are scanned in 8 steps: any P
//                      works, at a cost of P / 256 a lane (P = L M^2: 20 at L = 20, M = 16; 320 at M = 64).
//                      Floats: exact below 2^24 records (LevelVertexCache.MaxRecords).
//   LodCacheVertices   dispatch (M^2, L, VertexCacheGroupsPerTile(VertexCacheFactorLimit())): every
//                      vertex at the patch's integer factors, by the domain stage's own path.
#ifndef GT_LEVEL_VERTEX_CACHE_KERNELS_INCLUDED
#define GT_LEVEL_VERTEX_CACHE_KERNELS_INCLUDED

#include "LevelVertexCache.hlsl"
#include "VertexCacheWrites.hlsl"

#define GT_LEVEL_CACHE_SCAN_LANES 256u

groupshared uint gtLevelCacheRunSums[GT_LEVEL_CACHE_SCAN_LANES];

// Draw patch p's slots: none when culled in its record or in the camera's view (LodFactorPieces' flag).
uint LodPatchSlots(uint patch)
{
    if (_LodFactorsRW[patch].pieces[1].w != 0.0) return 0u;
    TileFactorSet f;
    f.edge = _LodFactorsRW[patch].edge;
    f.inside = _LodFactorsRW[patch].inside.xy;
    return LevelVertexCacheTileSlots(VertexCacheIntegerFactors(f));
}

// Every lane reaches every barrier: the loops' ends are the same for all.
[numthreads(GT_LEVEL_CACHE_SCAN_LANES, 1, 1)]
void LodVertexSlots(uint lane : SV_GroupIndex)
{
    uint patches = LodDrawPatches();
    uint run = (patches + GT_LEVEL_CACHE_SCAN_LANES - 1u) / GT_LEVEL_CACHE_SCAN_LANES;
    uint begin = min(lane * run, patches), end = min(begin + run, patches);
    uint sum = 0u;
    for (uint p = begin; p < end; p++)
        sum += LodPatchSlots(p);
    gtLevelCacheRunSums[lane] = sum;
    [unroll] for (uint step = 1u; step < GT_LEVEL_CACHE_SCAN_LANES; step <<= 1u)
    {
        GroupMemoryBarrierWithGroupSync();
        // The index stays in range for every lane: ?: reads both sides, and an out-of-range groupshared read is undefined.
        uint before = lane >= step ? gtLevelCacheRunSums[lane - min(step, lane)] : 0u;
        GroupMemoryBarrierWithGroupSync();
        gtLevelCacheRunSums[lane] += before;
    }
    GroupMemoryBarrierWithGroupSync();
    uint first = gtLevelCacheRunSums[lane] - sum, records = LodVertexCacheRecords();
    for (uint q = begin; q < end; q++)
    {
        uint slots = LodPatchSlots(q);
        _LodFactorsRW[q].inside.z = slots != 0u && first + slots <= records ? (float)first : -1.0;
        first += slots;
    }
    if (lane == GT_LEVEL_CACHE_SCAN_LANES - 1u) _LodFactorsRW[0].inside.w = (float)gtLevelCacheRunSums[lane];
}

// Reads through _LodFactors (the same buffer): FXC refuses a loop ending on a UAV read.
[numthreads(GT_VERTEX_CACHE_VERTEX_GROUP, 1, 1)]
void LodCacheVertices(uint3 group : SV_GroupID, uint lane : SV_GroupIndex)
{
    uint patch = group.y * LodTilesPerLevel(TileCountInt()) + group.x;
    if (patch >= LodDrawPatches()) return;
    int first = LodFirstRecord(patch);
    if (first < 0) return;
    TileFactorSet drawn = LodKernelTileFactors(patch);   // as the camera's hull outputs them
    TileFactorSet f = VertexCacheIntegerFactors(drawn);
    uint limit = LevelVertexCacheTileFactorLimit(f);
    uint count = VertexCacheTilePointCount(f.edge, f.inside, false);
    uint stride = VertexCacheGroupsPerTile(VertexCacheFactorLimit()) * GT_VERTEX_CACHE_VERTEX_GROUP;
    for (uint k = group.z * GT_VERTEX_CACHE_VERTEX_GROUP + lane; k < count; k += stride)
    {
        float2 tess;
        uint slot;
        VertexCachePoint(k, f.edge, f.inside, limit, false, tess, slot);
        WriteVertexCacheRecord((uint)first + slot, EvaluateLodTerrainVertex(patch, tess, drawn.edge));
    }
}

#endif // GT_LEVEL_VERTEX_CACHE_KERNELS_INCLUDED
