// A kernel group's share of one tile's factors (CacheTileFactors, LodFactorPieces): the tile's
// samples one a lane (TileFactorSampleAt), then its seven pieces one a lane. Include after
// TileFactors.hlsl, in a compute shader.
#ifndef GT_TILE_FACTOR_GROUP_INCLUDED
#define GT_TILE_FACTOR_GROUP_INCLUDED

groupshared float4 gtTileFactorSamples[GT_TILE_FACTOR_SAMPLES];
groupshared float gtTileFactorPieces[GT_TILE_FACTOR_PIECES];

// The tile's corners from the group's samples (after the samples' barrier).
void GroupTileCorners(out float3 cornerOS[4])
{
    [unroll] for (uint c = 0u; c < 4u; c++)
        cornerOS[c] = gtTileFactorSamples[c].xyz;
}

// Lane's piece (lanes 0-6) of tile `tile` of l from the group's samples: TileFactorPiece's arithmetic.
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

// The seven pieces the group wrote (after the pieces' barrier).
void GroupTileFactorPieces(out float piece[GT_TILE_FACTOR_PIECES])
{
    [unroll] for (uint k = 0u; k < GT_TILE_FACTOR_PIECES; k++)
        piece[k] = gtTileFactorPieces[k];
}

#endif // GT_TILE_FACTOR_GROUP_INCLUDED
