// gt bench's floor (rig only, never shipped): the terrain's tiles through the same vert, hull,
// hull_const, tessellator and frag as the package's variant, with a domain stage that evaluates
// nothing: each vertex is the bilinear blend of its tile's four corners (which hull_const already
// has, corner c at tess (c & 1, c >> 1)), normal up, height weight from that blend. What the
// tessellator, the rasteriser and the frag cost alone; every path is reported as a ratio to it.
// Compiled by Tools~/rig/bench.sh with the variant's keywords, entry point domain_floor.
#include "TerrainRig.hlsl"

[domain("quad")]
TerrainVaryings domain_floor(TileFactors factors, const OutputPatch<TileCorner, 4> corners,
                             float2 tess : SV_DomainLocation)
{
    float3 low = lerp(corners[0].positionOS, corners[1].positionOS, tess.x);
    float3 high = lerp(corners[2].positionOS, corners[3].positionOS, tess.x);
    float3 positionOS = lerp(low, high, tess.y);
    float3 shading = PackNormalAndHeightWeight(float3(0.0, 1.0, 0.0), TerrainHeightWeight(positionOS.y, 0.0));
    return TerrainVaryingsOf(positionOS, shading, 0.0, corners[0].drawPatch, factors.inside[0]);
}
