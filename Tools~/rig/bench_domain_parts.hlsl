// gt bench's domain-stage breakdown (rig only, never shipped): the package's domain stage
// (noise + height colour, TerrainVertex.hlsl's tile path with the range origin at 0, without
// its deep-zoom branch) rewritten from
// the same library functions, with one piece taken out per PART_* define, so that the breakdown
// table of the run's bench_table.md ("Where the domain stage's time goes") reads the cost of each piece as
// (full - part) in one run. Compiled by Tools~/rig/bench.sh with the fair variant's keywords
// (GT_NOISE GT_HEIGHT_COLOR), entry point domain_part, one SPIR-V per part (bench_parts.txt).
// A knocked-out piece is replaced by the cheapest stand-in that keeps the rest of the work alive
// (what the driver cannot prove dead); the pictures are wrong on purpose: these are timings only.
//   PART_FULL         nothing removed (the deep-zoom code is compiled in only with GT_RANGE_ORIGIN,
//                     so terrain - full is what this rewrite misses; it was that branch's cost)
//   PART_NO_LOOKUP    FindPatchAt (FindPatch's guess, its binary searches as the fallback) -> the
//                     patch of a uniform grid, by multiply
//   PART_NO_RANGE     tile -> q and q -> (u, v) by plain float (no TwoSum, no tile lattice reads)
//   PART_NO_DERIV     the Gregory derivatives (position only; dP/du, dP/dv of the corners' bilinear patch)
//   PART_NO_GREGORY   the Gregory evaluation itself (the bilinear patch of the four corner points)
//   PART_NO_OCTAVES   the noise height (colour kept)
//   PART_ONE_OCTAVE   one octave instead of the frame's count: (full - one) / (count - 1) an octave
//   PART_CHEAP_HASH   each PCG hash -> one multiply and shift
//   PART_PLAIN_SPLIT  the lattice split -> floor(f q + offset) in plain float (without a hi part
//                     neither the octaves' nor the colour noise's split has a TwoProduct left)
//   PART_NO_NORMAL    the normal (and every derivative only it needs) -> up
//   PART_NO_COLOUR    the height colour's noise
//   PART_PLAIN        no noise, no colour: the plain domain stage
//   PART_HOIST        a candidate: the hull stage finds the tile's patch once (its two opposite
//                     corners in the same patch interval: the search is monotonic in q, so every
//                     vertex of the tile is in it) and the domain stage searches only where they
//                     differ; compile the tesc too (entry hull_part)
//   PART_LINEAR_LOOKUP a candidate: FindPatch's intervals counted over the lines (independent loads)
//                     instead of the binary search's dependent ones
//   PART_MINIMAL      a minimal Gregory evaluator drawing the same triangles: the patch of a uniform
//                     grid by multiply, q and (u, v) in plain float, the Gregory position and normal,
//                     the package's varyings (what the plain stage is measured against)
//   PART_TABLE_CELLS  a candidate noise (it repeats every 256 lattice cells): each cell's four corner
//                     gradients from a 256 x 256 table (two float4 loads) instead of six PCG hashes
//                     and four reads of the direction table
//   PART_TABLE_COEF   the same table holding each cell's noise polynomial (three float4 loads), so
//                     the corner ramps' differences are not formed per vertex
#include "TerrainRig.hlsl"

#if defined(PART_PLAIN) || defined(PART_MINIMAL)
    #define PART_NO_OCTAVES
    #define PART_NO_COLOUR
#endif
#if defined(PART_MINIMAL)
    #define PART_NO_LOOKUP
    #define PART_NO_RANGE
#endif

uint PartHash(uint v)
{
#if defined(PART_CHEAP_HASH)
    return v * 2654435769u >> 13;
#else
    return GradientNoiseHash(v);
#endif
}

#if defined(PART_TABLE_CELLS) || defined(PART_TABLE_COEF)
// The candidates' table: 256 x 256 lattice cells, so the noise would repeat every 256 cells (a new
// noise, not the package's). The rig binds it zero-filled (--storage 9): timings only.
StructuredBuffer<float4> _PartGradients : register(t7);
#endif

#if defined(PART_TABLE_COEF)
// Each cell's noise polynomial from the table, its coefficients scaled by sqrt(2) (GT_NOISE_SCALE):
// r0 = (g00, A = g10 - g00), r1 = (B = g01 - g00, C = g00 - g10 - g01 + g11), r2 = (c1, c2, c3, 0)
// with c1 = -g10.x, c2 = -g01.y, c3 = g10.x + g01.y - g11.x - g11.y, so that
// GradientNoiseCorners' k1 = A.f + c1, k2 = B.f + c2, k3 = C.f + c3 and n00 = g00.f.
float PartCellPolynomial(int2 cell, float2 f, out float2 gradient)
{
    uint i = (((uint(cell.y) & 255u) << 8u) | (uint(cell.x) & 255u)) * 3u;
    float4 r0 = _PartGradients[i], r1 = _PartGradients[i + 1u], r2 = _PartGradients[i + 2u];
    float n00 = r0.x * f.x + r0.y * f.y;
    float k1 = r0.z * f.x + r0.w * f.y + r2.x;
    float k2 = r1.x * f.x + r1.y * f.y + r2.y;
    float k3 = r1.z * f.x + r1.w * f.y + r2.z;
    float u = GradientNoiseFade(f.x), v = GradientNoiseFade(f.y);
    float du = GradientNoiseFadeDerivative(f.x), dv = GradientNoiseFadeDerivative(f.y);
    float uv = u * v;
    gradient = r0.xy + u * r0.zw + v * r1.xy + uv * r1.zw + float2(du * (k1 + v * k3), dv * (k2 + u * k3));
    return n00 + u * k1 + v * k2 + uv * k3;
}
#endif

// The four corner gradients of lattice cell `cell`: hashed (the package's), or (PART_TABLE_CELLS)
// one record of two float4 a cell, (g00, g10) and (g01, g11), from the candidates' table.
void PartCellGradients(int2 cell, out float2 g00, out float2 g10, out float2 g01, out float2 g11)
{
#if defined(PART_TABLE_CELLS)
    uint i = (((uint(cell.y) & 255u) << 8u) | (uint(cell.x) & 255u)) << 1u;
    float4 r0 = _PartGradients[i], r1 = _PartGradients[i + 1u];
    g00 = r0.xy; g10 = r0.zw; g01 = r1.xy; g11 = r1.zw;
#else
    uint h0 = PartHash(asuint(cell.y)), h1 = PartHash(asuint(cell.y + 1));
    g00 = GradientNoiseGradient(PartHash(asuint(cell.x) + h0));
    g10 = GradientNoiseGradient(PartHash(asuint(cell.x + 1) + h0));
    g01 = GradientNoiseGradient(PartHash(asuint(cell.x) + h1));
    g11 = GradientNoiseGradient(PartHash(asuint(cell.x + 1) + h1));
#endif
}

float PartNoiseAtPoint(TerrainPoint p, float frequency, float2 offset, out float2 gradient)
{
    int2 cell;
    float2 f;
#if defined(PART_PLAIN_SPLIT)
    float2 x = TerrainPointApprox(p) * frequency + offset;
    float2 c = floor(x);
    cell = int2(c);
    f = x - c;
#else
    GradientNoiseSplitLattice(p.originHi.x, p.local.x, frequency, offset.x, cell.x, f.x);
    GradientNoiseSplitLattice(p.originHi.y, p.local.y, frequency, offset.y, cell.y, f.y);
#endif
#if defined(PART_TABLE_COEF)
    return PartCellPolynomial(cell, f, gradient);
#else
    float2 g00, g10, g01, g11;
    PartCellGradients(cell, g00, g10, g01, g11);
    return GradientNoiseCorners(g00, g10, g01, g11, f, gradient);
#endif
}

float PartNoiseAtLocal(float2 local, float frequency, float2 offset, out float2 gradient)
{
    int2 cell;
    float2 f;
#if defined(PART_PLAIN_SPLIT)
    float2 x = local * frequency + offset;
    float2 c = floor(x);
    cell = int2(c);
    f = x - c;
#else
    GradientNoiseSplitLocal(local.x, frequency, offset.x, cell.x, f.x);
    GradientNoiseSplitLocal(local.y, frequency, offset.y, cell.y, f.y);
#endif
#if defined(PART_TABLE_COEF)
    return PartCellPolynomial(cell, f, gradient);
#else
    float2 g00, g10, g01, g11;
    PartCellGradients(cell, g00, g10, g01, g11);
    return GradientNoiseCorners(g00, g10, g01, g11, f, gradient);
#endif
}

float PartOctaveNoise(TerrainPoint p, float4 noise, float octaveCount, out float2 gradient)
{
#if defined(PART_ONE_OCTAVE)
    octaveCount = min(octaveCount, 1.0);
#endif
    OctaveSum sum = OctaveSumStart(noise);
    // OctaveNoise's branch: without a hi part (here, origin 0) the split without TwoProduct.
    [branch] if (all(p.originHi == 0.0))
    {
        [unroll] for (uint k = 0u; k < GT_MAX_OCTAVES; ++k)
        {
            float fade = saturate(octaveCount - float(k));
            if (fade <= 0.0) break;
            float2 gk;
            float nk = PartNoiseAtLocal(p.local, sum.frequency, GradientNoiseStreamOffset(k), gk);
            OctaveSumAdd(sum, fade, nk, gk, noise);
        }
        return OctaveSumResult(sum, noise, gradient);
    }
    [unroll] for (uint k = 0u; k < GT_MAX_OCTAVES; ++k)
    {
        float fade = saturate(octaveCount - float(k));
        if (fade <= 0.0) break;
        float2 gk;
        float nk = PartNoiseAtPoint(p, sum.frequency, GradientNoiseStreamOffset(k), gk);
        OctaveSumAdd(sum, fade, nk, gk, noise);
    }
    return OctaveSumResult(sum, noise, gradient);
}



void PartGregory(float3 cp[20], float2 uv, out float3 position, out float3 dPdu, out float3 dPdv)
{
#if defined(PART_NO_GREGORY)
    float3 low = lerp(cp[0], cp[3], uv.x), high = lerp(cp[12], cp[15], uv.x);
    position = lerp(low, high, uv.y);
#else
    GregoryEvaluate(cp, uv, position, dPdu, dPdv);
#endif
#if defined(PART_NO_GREGORY) || defined(PART_NO_DERIV)
    // The derivatives of the corners' bilinear patch: what is left of the Gregory sums is dead code.
    float3 lowD = lerp(cp[0], cp[3], uv.x), highD = lerp(cp[12], cp[15], uv.x);
    dPdu = lerp(cp[3] - cp[0], cp[15] - cp[12], uv.y);
    dPdv = highD - lowD;
#endif
}

#if defined(PART_HOIST)
struct PartFactors
{
    float edge[4] : SV_TessFactor;
    float inside[2] : SV_InsideTessFactor;
    uint patchHint : TEXCOORD5;   // the tile's one patch, or 0xFFFFFFFF where it spans several
};

PartFactors hull_const_part(InputPatch<TileCorner, 4> corners)
{
    TileFactors f = hull_const(corners);
    PartFactors o;
    [unroll] for (uint e = 0u; e < 4u; e++) o.edge[e] = f.edge[e];
    o.inside[0] = f.inside[0];
    o.inside[1] = f.inside[1];
    uint slot = corners[0].drawPatch;
    float2 q0 = TerrainPointApprox(TileToTerrainPoint(FrameTileLayout(), slot, float2(0.0, 0.0)));
    float2 q1 = TerrainPointApprox(TileToTerrainPoint(FrameTileLayout(), slot, float2(1.0, 1.0)));
    uint n = GridColumns(), m = GridRows();
    uint i0 = PatchGridFindInterval(0u, n, q0.x), i1 = PatchGridFindInterval(0u, n, q1.x);
    uint j0 = PatchGridFindInterval(n + 1u, m, q0.y), j1 = PatchGridFindInterval(n + 1u, m, q1.y);
    o.patchHint = (i0 == i1 && j0 == j1) ? j0 * n + i0 : 0xFFFFFFFFu;
    return o;
}

[domain("quad")]
[partitioning(GT_PARTITIONING)]
[outputtopology("triangle_ccw")]
[patchconstantfunc("hull_const_part")]
[outputcontrolpoints(4)]
TileCorner hull_part(InputPatch<TileCorner, 4> corners, uint id : SV_OutputControlPointID)
{
    return corners[id];
}
    #define PART_FACTORS PartFactors
#else
    #define PART_FACTORS TileFactors
#endif

#if defined(PART_LINEAR_LOOKUP)
uint PartCountInterval(uint first, uint count, float x)
{
    uint i = 0u;
    [loop] for (uint k = 1u; k < count; k++)
        i += _GridLines[first + k] <= x ? 1u : 0u;
    return i;
}
#endif

[domain("quad")]
TerrainVaryings domain_part(PART_FACTORS factors, const OutputPatch<TileCorner, 4> corners,
                            float2 tess : SV_DomainLocation)
{
    uint drawPatch = corners[0].drawPatch;
    float tessFactor = max(factors.inside[0], factors.inside[1]);
    TerrainPoint q;
    uint patch;
    float4 region;
    float2 uv;
#if defined(PART_NO_RANGE)
    float m = TileCount();
    uint across = TileCountInt();
    float2 o = (float2(uint2(drawPatch % across, drawPatch / across)) + tess) / m;
    q.originHi = float2(0.0, 0.0);
    q.local = _Range.xy + o * (_Range.zw - _Range.xy);
#else
    q = TileToTerrainPoint(FrameTileLayout(), drawPatch, tess);
#endif
#if defined(PART_NO_LOOKUP)
    float2 qa = saturate(TerrainPointApprox(q));
    uint2 ij = min(uint2(qa * _GridSize.xy), uint2(GridColumns() - 1u, GridRows() - 1u));
    patch = ij.y * GridColumns() + ij.x;
#elif defined(PART_HOIST)
    patch = factors.patchHint != 0xFFFFFFFFu ? factors.patchHint : FindPatch(TerrainPointApprox(q));
#elif defined(PART_LINEAR_LOOKUP)
    float2 qa = TerrainPointApprox(q);
    patch = PartCountInterval(GridColumns() + 1u, GridRows(), qa.y) * GridColumns() + PartCountInterval(0u, GridColumns(), qa.x);
#else
    patch = FindPatchAt(q);   // the shipped lookup (hi/lo grid lines only while a range origin is set)
#endif
    region = PatchRegion(patch);
    float4 regionLo = PatchRegionLo(patch);
#if defined(PART_NO_RANGE)
    uv = (q.local - region.xy) / (region.zw - region.xy);
#else
    uv = PatchLocalUV(q, region, regionLo);
#endif
    float3 cp[20];
    LoadGregoryPatch(patch, cp);   // relative to the patch's reference point
    float3 position, dPdu, dPdv;
    PartGregory(cp, uv, position, dPdu, dPdv);
    position += PatchReference(patch);
    float absoluteHeight = position.z;
#if !defined(PART_NO_OCTAVES)
    float octaves = OctaveCount(LayoutWidth(FrameTileLayout()), NoiseVerticesAcross(), NoiseSettings(), MaxNoiseOctaves());
    float2 gradient;
    float noiseHeight = PartOctaveNoise(q, NoiseSettings(), octaves, gradient);
    position.z += noiseHeight;
    absoluteHeight += noiseHeight;
    float2 regionSize = RegionSize(region, regionLo);
    dPdu.z += gradient.x * regionSize.x;
    dPdv.z += gradient.y * regionSize.y;
#endif
#if defined(PART_NO_NORMAL)
    float3 normalOS = float3(0.0, 1.0, 0.0);
#else
    float3 normalOS = TerrainToObject(GregoryNormalFromDerivatives(dPdu, dPdv));
#endif
    float colorNoise = 0.0;
#if !defined(PART_NO_COLOUR) && defined(GT_HEIGHT_COLOR)
    float4 hc = HeightColorSettings();
    float2 unusedGradient;
    // As the stage without the origin's code: q has no hi part, the split without TwoProduct.
    colorNoise = hc.y * PartNoiseAtLocal(q.local, hc.z, GradientNoiseStreamOffset(GT_COLOR_NOISE_STREAM), unusedGradient);
#endif
    float3 positionOS = TerrainToObject(position);
    float3 shading = PackNormalAndHeightWeight(GT_ObjectToWorldNormal(normalOS), TerrainHeightWeight(absoluteHeight, colorNoise));
    return TerrainVaryingsOf(positionOS, shading, 0.0, patch, tessFactor);
}
