// The vertex cache's two compute kernels (GT_VERTEX_CACHE; Documentation~/internals.md, "Vertex
// cache"). Include a pipeline adapter first (the rig: StandaloneAdapter through TerrainRig.hlsl;
// Unity: TerrainCache.compute with LodCameraComputeAdapter.hlsl): the factors need GT_ObjectToClip
// and GT_ScreenSize of the camera that decides the tessellation.
//
//   CacheTileFactors    8 lanes per tile: culling and adaptive (or uniform) factors, rounded to
//                       the integer factors the draw will use (VertexCacheIntegerFactors)
//   CacheTileVertices   a few groups per tile: every vertex the tessellator makes at those factors,
//                       evaluated by EvaluateTerrainVertex (the domain stage's own path) into its slot
//
// A frame dispatches both, in that order, then draws; the hull stage reads the factors and the
// domain stage reads the records (TerrainStages.hlsl). Why: the per-vertex work (FindPatch, the 20
// control points, the rational Gregory evaluation, the noise octaves) runs on every compute unit
// instead of the graphics stages (on NVIDIA's H100/H200 only a few units run those at all), and
// each vertex of the tile is evaluated once, not once per triangle fan the tessellator emits.
#ifndef GT_VERTEX_CACHE_KERNELS_INCLUDED
#define GT_VERTEX_CACHE_KERNELS_INCLUDED

#include "VertexCache.hlsl"

// The same bindings as the graphics stages' _TileFactors and _VertexCache (t5, t6): binding 7 and
// 8 in the rig either way (TerrainInputs.hlsl).
RWStructuredBuffer<float4> _TileFactorsRW GT_REGISTER(u2);
RWStructuredBuffer<float4> _VertexCacheRW GT_REGISTER(u3);

groupshared float gtTileFactorPieces[GT_VERTEX_CACHE_GROUP];

// Dispatch (ceil(8 M^2 / 64), 1, 1): 8 lanes a tile, lane k < 7 computing piece k of its factors
// (TileFactorPiece), lane 0 assembling them. Why not one lane a tile: a tile's ~50 surface
// evaluations in one thread made the pass as long as that chain, on 16 of the GPU's units at
// 32 x 32 tiles (adaptive, 0.6M triangles: 0.1 ms of pre-pass against 0.04 for uniform factors).
[numthreads(64, 1, 1)]
void CacheTileFactors(uint3 id : SV_DispatchThreadID, uint lane : SV_GroupIndex)
{
    uint tiles = TileCountInt();
    uint tile = id.x / GT_VERTEX_CACHE_FACTOR_LANES, piece = id.x % GT_VERTEX_CACHE_FACTOR_LANES;
    bool live = tile < tiles * tiles;
    TileFactorSet f = CulledTileFactors();
    bool pieces = false;
    if (live && !UniformTileFactors(f))
    {
        f = CulledTileFactors();
        float3 cornerOS[4];
        [unroll] for (uint c = 0u; c < 4u; c++)
            cornerOS[c] = TileCornerObjectPosition(tile, c);
        pieces = !TileCulled(cornerOS);
        if (pieces && piece < GT_TILE_FACTOR_PIECES)
            gtTileFactorPieces[lane] = TileFactorPiece(tile, piece, cornerOS);
    }
    GroupMemoryBarrierWithGroupSync();
    if (!live || piece != 0u) return;
    if (pieces)
    {
        float p[GT_TILE_FACTOR_PIECES];
        [unroll] for (uint k = 0u; k < GT_TILE_FACTOR_PIECES; k++)
            p[k] = gtTileFactorPieces[lane + k];
        f = TileFactorsOfPieces(p);
    }
    f = VertexCacheIntegerFactors(f);
    _TileFactorsRW[2u * tile] = f.edge;
    _TileFactorsRW[2u * tile + 1u] = float4(f.inside, f.edge.x == 0.0 ? 1.0 : 0.0, 0.0);
}

void WriteVertexCacheRecord(uint slot, TerrainVertexAttributes a)
{
    [unroll] for (uint part = 0u; part < GT_VERTEX_CACHE_FLOAT4S; part++)
        _VertexCacheRW[GT_VERTEX_CACHE_FLOAT4S * slot + part] = VertexCacheRecordPart(a, part);
}

// Point k of the tile's list "inside points, then edge 0, 1, 2, 3": its tess coordinate and slot.
// Inside points are the (Iu - 1) x (Iv - 1) interior of the grid (its border is the edges').
void VertexCachePoint(uint k, float4 edge, float2 inside, uint limit, out float2 tess, out uint slot)
{
    uint2 n = (uint2)inside - 1u;
    uint interior = n.x * n.y;
    if (k < interior)
    {
        uint2 ij = uint2(1u + k % n.x, 1u + k / n.x);
        tess = (float2)ij / inside;
        slot = VertexCacheInteriorSlot(ij, (uint)inside.x);
        return;
    }
    k -= interior;
    uint e = 0u;
    [unroll] for (uint i = 0u; i < 3u; i++)
    {
        uint count = (uint)edge[e] + 1u;
        if (k >= count) { k -= count; e++; }
    }
    tess = VertexCacheEdgeTess(e, k, edge[e]);
    slot = VertexCacheEdgeSlot(e, k, limit);
}

// Dispatch (M, M, G), G = VertexCacheGroupsPerTile(L): groups (x, y, 0 .. G - 1) share tile
// y M + x, their G x 64 lanes striding over its points (at most GT_VERTEX_CACHE_PASSES each).
[numthreads(64, 1, 1)]
void CacheTileVertices(uint3 group : SV_GroupID, uint lane : SV_GroupIndex)
{
    uint tiles = TileCountInt();
    if (group.x >= tiles || group.y >= tiles) return;
    uint tile = group.y * tiles + group.x;
    float4 edge = _TileFactorsRW[2u * tile];
    float4 inside = _TileFactorsRW[2u * tile + 1u];
    if (inside.z != 0.0) return;   // culled: the draw emits nothing for it
    uint limit = VertexCacheFactorLimit();
    uint base = tile * VertexCacheSlotsPerTile(limit);
    uint2 n = (uint2)inside.xy - 1u;
    uint count = n.x * n.y + (uint)(edge.x + edge.y + edge.z + edge.w) + 4u;
    uint stride = VertexCacheGroupsPerTile(limit) * GT_VERTEX_CACHE_GROUP;
    for (uint k = group.z * GT_VERTEX_CACHE_GROUP + lane; k < count; k += stride)
    {
        float2 tess;
        uint slot;
        VertexCachePoint(k, edge, inside.xy, limit, tess, slot);
        WriteVertexCacheRecord(base + slot, EvaluateTerrainVertex(tile, tess));
    }
}

#endif // GT_VERTEX_CACHE_KERNELS_INCLUDED
