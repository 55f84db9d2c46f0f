// Rig only, never shipped (issue 38, where the levels' vert + hull time goes): the Horizon levels'
// tile factors computed once per draw patch in two compute kernels instead of in every hull
// invocation, and the stages that read them (Tools~/rig/lod_factors_ab.py says how to compile and run
// them). Compiled with GT_LOD GT_NOISE GT_HEIGHT_COLOR and one of:
//   LOD_KERNELS   compute entry points lod_pieces (a group per draw patch: the tile's 51 samples on
//                 51 lanes, its seven pieces on seven, TileCulled on lane 0: the vertex cache's
//                 CacheTileFactors split) and lod_seams (a thread per draw patch: the cell's factors
//                 and the seam rule, the coarse tile's edge piece read from the pieces, not computed
//                 again)
//   (none)        vert_light (the draw patch only: the levels' domain stage reads no corner),
//                 vert_buffered (the corners lod_pieces wrote, for the flat floor domain) and
//                 hull_buffered (returns the factors lod_seams wrote)
// Bindings (rig shifts): 7 the factors (u2 / t5), 8 the pieces (u3), 9 the corners (u4 / t7).
#include "TerrainRig.hlsl"

#if defined(LOD_KERNELS)
RWStructuredBuffer<float4> _LodFactorsRW GT_REGISTER(u2);   // 2 float4 a draw patch: edge, (inside, 0, 0)
RWStructuredBuffer<float4> _LodPiecesRW GT_REGISTER(u3);    // 2 float4 a draw patch: pieces 0-3, (4, 5, 6, culled)
RWStructuredBuffer<float4> _LodCornersRW GT_REGISTER(u4);   // 4 float4 a draw patch: the corners (object space)

groupshared float4 gtLodSamples[GT_TILE_FACTOR_SAMPLES];
groupshared float gtLodPieces[GT_TILE_FACTOR_PIECES];

uint LodDrawPatches() { return LodLevelCount() * LodTilesPerLevel(TileCountInt()); }

[numthreads(64, 1, 1)]
void lod_pieces(uint3 group : SV_GroupID, uint lane : SV_GroupIndex)
{
    uint patch = group.x;
    bool live = patch < LodDrawPatches();
    uint slot;
    TileLayout l = StageTileLayout(min(patch, LodDrawPatches() - 1u), slot);
    if (live && lane < GT_TILE_FACTOR_SAMPLES)
        gtLodSamples[lane] = TileFactorSampleAt(lane, TileFactorSamplePosition(l, slot, lane));
    GroupMemoryBarrierWithGroupSync();
    float3 cornerOS[4];
    [unroll] for (uint c = 0u; c < 4u; c++)
        cornerOS[c] = gtLodSamples[c].xyz;
    if (live && lane < GT_TILE_FACTOR_PIECES)
    {
        if (lane == 6u)
            gtLodPieces[lane] = CentreErrorTessFactor(cornerOS, gtLodSamples[GT_TILE_CENTRE_SAMPLE]);
        else
        {
            float3 p[GT_EDGE_SEGMENTS + 1];
            float k[GT_EDGE_SEGMENTS + 1];
            [unroll] for (uint i = 0u; i <= GT_EDGE_SEGMENTS; i++)
            {
                float4 v = gtLodSamples[TileLineSample(lane, i)];
                p[i] = v.xyz;
                k[i] = v.w;
            }
            gtLodPieces[lane] = LineErrorTessFactor(l, slot, lane, p, k);
        }
    }
    GroupMemoryBarrierWithGroupSync();
    if (live && lane < 4u) _LodCornersRW[4u * patch + lane] = float4(cornerOS[lane], 0.0);
    if (!live || lane != 0u) return;
    bool culled = TileCulled(cornerOS, TileNoiseMargin(l, slot));
    _LodPiecesRW[2u * patch] = float4(gtLodPieces[0], gtLodPieces[1], gtLodPieces[2], gtLodPieces[3]);
    _LodPiecesRW[2u * patch + 1u] = float4(gtLodPieces[4], gtLodPieces[5], gtLodPieces[6], culled ? 1.0 : 0.0);
}

// CoarseSeamEdgeFactor with the coarse tile's edge piece read from lod_pieces' record.
float BufferedCoarseSeamEdgeFactor(uint drawPatch, uint edgeBit, int2 abUp)
{
    if (UsesUniformTessFactor()) return UniformTessFactor();
    uint m = TileCountInt();
    uint level = LodLevelOfPatch(drawPatch, m), slot = LodSlotOfPatch(drawPatch, m);
    uint coarseEdge;
    int upperHalf;
    int2 coarseTile = FineSeamCoarseTile(edgeBit, int2(slot % m, slot / m), abUp, coarseEdge, upperHalf);
    uint coarsePatch = (level + 1u) * LodTilesPerLevel(m) + (uint)coarseTile.y * m + (uint)coarseTile.x;
    float4 edges = _LodPiecesRW[2u * coarsePatch];
    float piece = coarseEdge == GT_EDGE_U0 ? edges.x : (coarseEdge == GT_EDGE_V0 ? edges.y : (coarseEdge == GT_EDGE_U1 ? edges.z : edges.w));
    return max(piece, 1.0);
}

[numthreads(64, 1, 1)]
void lod_seams(uint3 id : SV_DispatchThreadID)
{
    uint patch = id.x;
    if (patch >= LodDrawPatches()) return;
    uint slot;
    TileLayout l = StageTileLayout(patch, slot);
    TileFactorSet set;
    if (TileEmpty(l, slot)) set = CulledTileFactors();
    else if (!UniformTileFactors(set))
    {
        float4 a = _LodPiecesRW[2u * patch], b = _LodPiecesRW[2u * patch + 1u];
        float piece[GT_TILE_FACTOR_PIECES] = { a.x, a.y, a.z, a.w, b.x, b.y, b.z };
        set = b.w != 0.0 ? CulledTileFactors() : TileFactorsOfCell(TileFactorsOfPieces(piece), TileKeptFraction(l, slot));
    }
    // LodTileFactors, the fine seam edges from the record.
    uint coarseMask, fineMask;
    bool inside;
    int2 ab, abUp;
    LodTileSeams(patch, coarseMask, fineMask, inside, ab, abUp);
    if (inside) set = CulledTileFactors();
    if (!TileFactorsCulled(set))
    {
        float edge[4] = { set.edge.x, set.edge.y, set.edge.z, set.edge.w };
        [unroll] for (uint i = 0u; i < 4u; i++)
        {
            uint bit = 1u << i;
            if ((coarseMask & bit) != 0u) edge[i] = 2.0 * SeamHalfFactor(edge[i], MaxTessFactor());
            else if ((fineMask & bit) != 0u) edge[i] = SeamHalfFactor(BufferedCoarseSeamEdgeFactor(patch, bit, abUp), MaxTessFactor());
        }
        set.edge = float4(edge[0], edge[1], edge[2], edge[3]);
    }
    _LodFactorsRW[2u * patch] = set.edge;
    _LodFactorsRW[2u * patch + 1u] = float4(set.inside, 0.0, 0.0);
}

#else
StructuredBuffer<float4> _LodFactors GT_REGISTER(t5);
StructuredBuffer<float4> _LodCorners GT_REGISTER(t7);

TileCorner vert_light(uint vertexID : SV_VertexID)
{
    TileCorner o;
    o.drawPatch = vertexID / 4u;
    o.positionOS = 0.0;
    return o;
}

TileCorner vert_buffered(uint vertexID : SV_VertexID)
{
    TileCorner o;
    o.drawPatch = vertexID / 4u;
    o.positionOS = _LodCorners[vertexID].xyz;
    return o;
}

TileFactors hull_const_buffered(InputPatch<TileCorner, 4> corners)
{
    uint p = corners[0].drawPatch;
    TileFactorSet set;
    set.edge = _LodFactors[2u * p];
    set.inside = _LodFactors[2u * p + 1u].xy;
    return ToTileFactors(set);
}

[domain("quad")]
[partitioning(GT_PARTITIONING)]
[outputtopology("triangle_ccw")]
[patchconstantfunc("hull_const_buffered")]
[outputcontrolpoints(4)]
TileCorner hull_buffered(InputPatch<TileCorner, 4> corners, uint id : SV_OutputControlPointID)
{
    return corners[id];
}
#endif
