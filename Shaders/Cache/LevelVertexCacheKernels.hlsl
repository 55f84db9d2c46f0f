// The Horizon levels' vertex cache in two compute kernels (GT_LOD; internals.md, "Levels of
// detail"), dispatched after the factor kernels (LevelFactorKernels.hlsl, whose records they read)
// every frame the levels draw from it. The domain stage then reads one record a vertex
// (VertexSource.Levels.hlsl, while _LodLevels.z = C, the records the buffer holds, is nonzero).
//
//   LodVertexSlots     one group, dispatch (1, 1, 1): each draw patch's slots (LodPatchSlots) and
//                      their exclusive prefix sum, its first record (LevelVertexCache.hlsl's
//                      layout), into its LodFactorRecord's inside.z: -1 for none, and for a block
//                      that would end past C (the domain stage evaluates that tile itself); the
//                      records the frame needed into draw patch 0's inside.w (the renderer grows the
//                      buffer from it). Each of the GT_LEVEL_CACHE_SCAN_LANES lanes sums a run of
//                      ceil(P / lanes) patches in turn, the lanes' sums are scanned in log2(lanes)
//                      steps, and each lane writes its run's first records. Any P works; its cost
//                      grows as P / lanes: the levels' P = L M^2 is 5,120 at L = 20, M = 16 (20 a
//                      lane), 81,920 at M = 64 (320 a lane). C and the first records are floats:
//                      exact below 2^24 records (the renderer's bound).
//   LodCacheVertices   a few groups per draw patch, dispatch (M^2, L, G), G =
//                      VertexCacheGroupsPerTile(VertexCacheFactorLimit()): every vertex the
//                      tessellator makes at the patch's integer factors, evaluated by
//                      EvaluateLodTerrainVertex (the domain stage's own path, at this frame's
//                      camera and origin) into its record. Patches without records do nothing.
#ifndef GT_LEVEL_VERTEX_CACHE_KERNELS_INCLUDED
#define GT_LEVEL_VERTEX_CACHE_KERNELS_INCLUDED

#include "LevelVertexCache.hlsl"
#include "VertexCacheWrites.hlsl"

#define GT_LEVEL_CACHE_SCAN_LANES 256u

groupshared uint gtLevelCacheRunSums[GT_LEVEL_CACHE_SCAN_LANES];

// The slots draw patch p takes this frame: S of its own largest integer factor
// (LevelVertexCacheTileSlots); none when its record is culled or the camera's view culls it
// (LodFactorPieces' flag: only the camera's pass draws from records, another evaluates such a tile).
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
        uint before = lane >= step ? gtLevelCacheRunSums[lane - step] : 0u;
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

// The factors and first record come through the read-only _LodFactors (the same buffer): FXC
// refuses a compute loop whose end depends on a UAV read without [allow_uav_condition].
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
