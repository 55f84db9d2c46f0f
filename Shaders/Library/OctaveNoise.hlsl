#ifndef GT_OCTAVE_NOISE_INCLUDED
#define GT_OCTAVE_NOISE_INCLUDED

// Height detail p = amplitude * sum_k beta^-k * GradientNoise(f_k q + offset_k), eq. 12-13 with N
// octaves, the last one weighted by the fraction of octaveCount. Mirrors Runtime/Core/Library/OctaveNoise.cs
// (C# OctaveNoise.Evaluate == HLSL OctaveNoise). f_0 = frequency, f_{k+1} = f_k * alpha in float.

#include "GradientNoise.hlsl"

#define GT_MAX_OCTAVES 16

// The running sum over octaves (C# OctaveNoise.OctaveSum): octave k weighted by beta^-k times its
// fade, its lattice gradient scaled by its frequency (chain rule: d/dq = f d/d(lattice)),
// frequencies the float sequence f_{k+1} = f_k alpha. noise = _Noise = (amplitude, frequency,
// alpha, beta).
struct OctaveSum
{
    float frequency;
    float weight;
    float invBeta;
    float height;
    float2 gradient;
};

OctaveSum OctaveSumStart(float4 noise)
{
    OctaveSum s;
    s.frequency = noise.y;
    s.weight = 1.0;
    s.invBeta = 1.0 / noise.w;
    s.height = 0.0;
    s.gradient = float2(0.0, 0.0);
    return s;
}

// Adds octave value nk (gradient gk, lattice units) at the current frequency, then steps to the next.
void OctaveSumAdd(inout OctaveSum s, float fade, float nk, float2 gk, float4 noise)
{
    float wk = s.weight * fade;
    s.height += wk * nk;
    s.gradient += gk * (wk * s.frequency);
    s.frequency *= noise.z;
    s.weight *= s.invBeta;
}

float OctaveSumResult(OctaveSum s, float4 noise, out float2 gradient)
{
    gradient = s.gradient * noise.x;
    return noise.x * s.height;
}

// octaveCount must already be clamped to [0, N] (OctaveCount does). gradient = d p / d q in
// terrain units.
float OctaveNoise(TerrainPoint p, float4 noise, float octaveCount, out float2 gradient)
{
    OctaveSum sum = OctaveSumStart(noise);
    // Without a hi part (no range origin: uniform over a frame) the lattice split needs no
    // TwoProduct (GradientNoiseAtLocal): the same values bit for bit, cheaper. Core mirrors it.
    [branch] if (all(p.originHi == 0.0))
    {
        [unroll] for (uint k = 0u; k < GT_MAX_OCTAVES; ++k)
        {
            float fade = saturate(octaveCount - float(k));
            if (fade <= 0.0) break;
            float2 gk;
            float nk = GradientNoiseAtLocal(p.local, sum.frequency, GradientNoiseStreamOffset(k), gk);
            OctaveSumAdd(sum, fade, nk, gk, noise);
        }
        return OctaveSumResult(sum, noise, gradient);
    }
    // [unroll], not [loop]: each octave's stream offset folds to a constant and the early-out is a
    // uniform branch; the same arithmetic in the same order as the C# mirror.
    [unroll] for (uint k = 0u; k < GT_MAX_OCTAVES; ++k)
    {
        float fade = saturate(octaveCount - float(k));
        if (fade <= 0.0) break;
        float2 gk;
        float nk = GradientNoiseAtPoint(p, sum.frequency, GradientNoiseStreamOffset(k), gk);
        OctaveSumAdd(sum, fade, nk, gk, noise);
    }
    return OctaveSumResult(sum, noise, gradient);
}

// One octave of OctaveNoiseRelative: K(f q + offset) - K(f O + offset) from the precise q - O,
// gradient at q (lattice units); the three cases: the C#'s OctaveNoise.Relative.
float OctaveNoiseDifference(TerrainPoint q, TerrainPoint origin, float2 qMinusOrigin, float frequency, float2 offset, out float2 gradient)
{
    int2 c0;
    float2 f0;
    GradientNoiseSplitLattice(origin.originHi.x, origin.local.x, frequency, offset.x, c0.x, f0.x);
    GradientNoiseSplitLattice(origin.originHi.y, origin.local.y, frequency, offset.y, c0.y, f0.y);
    float2 s = qMinusOrigin * frequency;      // the lattice step
    int2 m = int2(floor(f0 + s));             // q's cell relative to O's
    float unused;
    if (all(m == 0))
        return GradientNoiseCellDifference(c0, f0, s, gradient, unused);
    if (all(abs(m) <= 1))
    {
        float2 r = float2(m.x == 0 ? f0.x : (m.x > 0 ? 1.0 : 0.0), m.y == 0 ? f0.y : (m.y > 0 ? 1.0 : 0.0));
        float2 t = r - f0;                    // O -> r1
        float2 g0;
        float toR1 = GradientNoiseCellDifference(c0, f0, t, g0, unused);
        float fromR1 = GradientNoiseCellDifference(c0 + m, r - float2(m), s - t, gradient, unused);
        return fromR1 + toR1;
    }
    float2 g1;
    float atQ = GradientNoiseAtPoint(q, frequency, offset, gradient);
    return atQ - GradientNoiseCell(c0, f0, g1);
}

// Deep-zoom noise height p(q) - p(O), O the range origin, from the precise difference qMinusOrigin
// (TerrainPointDifference); the renderer adds p(O) back (precision.md). Mirrors OctaveNoise.Relative.
float OctaveNoiseRelative(TerrainPoint q, TerrainPoint origin, float2 qMinusOrigin, float4 noise, float octaveCount, out float2 gradient)
{
    OctaveSum sum = OctaveSumStart(noise);
    [loop] for (uint k = 0u; k < GT_MAX_OCTAVES; ++k)
    {
        float fade = saturate(octaveCount - float(k));
        if (fade <= 0.0) break;
        float2 gk;
        float nk = OctaveNoiseDifference(q, origin, qMinusOrigin, sum.frequency, GradientNoiseStreamOffset(k), gk);
        OctaveSumAdd(sum, fade, nk, gk, noise);
    }
    return OctaveSumResult(sum, noise, gradient);
}

// Octaves whose wavelength 1 / (frequency alpha^k) is at least two vertex spacings
// (2 rangeWidth / verticesAcross): 1 + log_alpha(verticesAcross / (2 rangeWidth frequency)),
// clamped to [0, maxOctaves]. Uniform per frame, so every vertex uses the same count.
float OctaveCount(float rangeWidth, float verticesAcross, float4 noise, float maxOctaves)
{
    float k = 1.0 + log2(verticesAcross / (2.0 * rangeWidth * noise.y)) / log2(noise.z);
    return clamp(k, 0.0, maxOctaves);
}

// The continuous rule of the levels of detail: OctaveCount of the vertex spacing segmentPixels /
// pixelsPerUnit and one vertex. Infinite and zero scales are tested before dividing, so no inf or
// NaN reaches log2. Mirrors Core TerrainInputs.NoiseOctaveCountAt (float) and
// OctaveNoise.OctaveCountAtPixelScale (double).
float OctaveCountAtPixelScale(float pixelsPerUnit, float segmentPixels, float4 noise, float maxOctaves)
{
    if (!(pixelsPerUnit < asfloat(0x7F800000u))) return maxOctaves;
    if (!(pixelsPerUnit > 0.0)) return 0.0;
    return OctaveCount(segmentPixels / pixelsPerUnit, 1.0, noise, maxOctaves);
}

#endif // GT_OCTAVE_NOISE_INCLUDED
