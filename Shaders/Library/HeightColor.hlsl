#ifndef GT_HEIGHT_COLOR_INCLUDED
#define GT_HEIGHT_COLOR_INCLUDED

// Height colour, eq. 14-15. Mirrors Runtime/Core/Library/HeightColor.cs.
// heightColor = _HeightColor = (gamma, noise amplitude, noise frequency, 0).

#include "GradientNoise.hlsl"

#define GT_COLOR_NOISE_STREAM 0x436F6C72u

// s = saturate(l + z / gamma)
float HeightColorWeight(float l, float z, float gamma)
{
    return saturate(l + z / gamma);
}

// colour = high s + low (1 - s), linear RGB (B and C of eq. 15), of a weight already computed: the
// vertex stages compute s and the fragment stage interpolates it (TerrainVaryings).
float3 HeightColorOfWeight(float s, float3 low, float3 high)
{
    return high * s + low * (1.0 - s);
}

// l: one octave of gradient noise at its own frequency and offset, times its own amplitude.
float HeightColorNoise(TerrainPoint p, float4 heightColor)
{
    float2 unused;
    return heightColor.y * GradientNoiseAtPoint(p, heightColor.z, GradientNoiseStreamOffset(GT_COLOR_NOISE_STREAM), unused);
}

// HeightColorNoise of a point without a hi part (originHi = 0): the same value bit for bit, without
// TwoProduct (GradientNoiseAtLocal).
float HeightColorNoiseAtLocal(float2 local, float4 heightColor)
{
    float2 unused;
    return heightColor.y * GradientNoiseAtLocal(local, heightColor.z, GradientNoiseStreamOffset(GT_COLOR_NOISE_STREAM), unused);
}

#endif // GT_HEIGHT_COLOR_INCLUDED
