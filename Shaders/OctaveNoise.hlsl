#ifndef GT_OCTAVE_NOISE_INCLUDED
#define GT_OCTAVE_NOISE_INCLUDED

// Height detail p = amplitude * sum_k beta^-k * GradientNoise(f_k q + offset_k), eq. 12-13 with N
// octaves, the last one weighted by the fraction of octaveCount. Mirrors Runtime/Core/OctaveNoise.cs
// (C# OctaveNoise.Evaluate == HLSL OctaveNoise). f_0 = frequency, f_{k+1} = f_k * alpha in float.

#include "GradientNoise.hlsl"

#define GT_MAX_OCTAVES 16

// noise = _Noise = (amplitude, frequency, alpha, beta). octaveCount must already be clamped to
// [0, N] (OctaveCount does). gradient = d p / d q in terrain units.
float OctaveNoise(TerrainPoint p, float4 noise, float octaveCount, out float2 gradient)
{
    float f = noise.y, w = 1.0, invBeta = 1.0 / noise.w;
    float n = 0.0;
    float2 g = 0.0;
    [loop] for (uint k = 0u; k < GT_MAX_OCTAVES; ++k)
    {
        float fade = saturate(octaveCount - float(k));
        if (fade <= 0.0) break;
        float2 gk;
        float nk = GradientNoiseAtPoint(p, f, GradientNoiseStreamOffset(k), gk);
        float wk = w * fade;
        n += wk * nk;
        g += gk * (wk * f);
        f *= noise.z;
        w *= invBeta;
    }
    gradient = g * noise.x;
    return noise.x * n;
}

// Octaves whose wavelength 1 / (frequency alpha^k) is at least two vertex spacings
// (2 rangeWidth / verticesAcross): 1 + log_alpha(verticesAcross / (2 rangeWidth frequency)),
// clamped to [0, maxOctaves]. Uniform per frame, so every vertex uses the same count.
float OctaveCount(float rangeWidth, float verticesAcross, float4 noise, float maxOctaves)
{
    float k = 1.0 + log2(verticesAcross / (2.0 * rangeWidth * noise.y)) / log2(noise.z);
    return clamp(k, 0.0, maxOctaves);
}

#endif // GT_OCTAVE_NOISE_INCLUDED
