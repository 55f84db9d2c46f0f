// A factor kernel group's share of one tile (CacheTileFactors, LodFactorPieces): its samples one a
// lane, then its seven pieces one a lane. Include after TileFactors.hlsl.
#ifndef GT_TILE_FACTOR_GROUP_INCLUDED
#define GT_TILE_FACTOR_GROUP_INCLUDED

groupshared float4 gtTileFactorSamples[GT_TILE_FACTOR_SAMPLES];
groupshared float gtTileFactorPieces[GT_TILE_FACTOR_PIECES];

// After the samples' barrier: lane 0-6's piece, TileFactorPiece's arithmetic on the shared samples.
void WriteGroupTileFactorPiece(TileLayout l, uint tile, uint lane, float3 cornerOS[4])
{
    if (lane == 6u)
        gtTileFactorPieces[lane] = CentreErrorTessFactor(cornerOS, gtTileFactorSamples[GT_TILE_CENTRE_SAMPLE]);
    else if (lane < GT_TILE_FACTOR_PIECES)
    {
        float3 p[GT_EDGE_SEGMENTS + 1];
        float k[GT_EDGE_SEGMENTS + 1];
        [unroll] for (uint i = 0u; i <= GT_EDGE_SEGMENTS; i++)
        {
            float4 v = gtTileFactorSamples[TileLineSample(lane, i)];
            p[i] = v.xyz;
            k[i] = v.w;
        }
        gtTileFactorPieces[lane] = LineErrorTessFactor(l, tile, lane, p, k);
    }
}

#endif // GT_TILE_FACTOR_GROUP_INCLUDED
