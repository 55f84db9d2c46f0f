// A unit normal in two numbers, for interpolants: Lambert's azimuthal equal-area projection about
// +y, the disk of radius 2. Mirrors Runtime/Core/Library/NormalEncoding.cs.
//
// Why this map: it is smooth everywhere but at n = -y, so interpolating the two numbers across a
// triangle behaves like interpolating the normal, on terrain's slopes and cliffs alike (an
// octahedral map folds at the horizon, y = 0, and a triangle whose normals straddle it reads
// garbage). The one trap is a triangle whose normals point almost straight down (the ceiling of an
// overhang): it interpolates across the pole.
#ifndef GT_NORMAL_ENCODING_INCLUDED
#define GT_NORMAL_ENCODING_INCLUDED

// e = n.xz * k, k = sqrt(2 / (1 + n.y)) = sqrt(2 (1 - n.y)) / |n.xz| for a unit n. Each form where
// it is well conditioned: the first cancels near n = -y, where a normal's own rounding
// (|n| = 1 +- 1e-7) divided by 1 + n.y cost 1e-3 of error 2.6 degrees from straight down; the
// second cancels near n = +y, terrain's most common normal. At n = -y exactly e is (0, 0): finite.
float2 LambertEncodeNormal(float3 n)
{
    float k;
    if (n.y >= 0.0)
        k = rsqrt(0.5 + 0.5 * n.y);
    else
        k = sqrt(2.0 * (1.0 - n.y)) / max(length(n.xz), 1e-30);
    return n.xz * k;
}

// n = (e.x sqrt(1 - f / 4), 1 - f / 2, e.y sqrt(1 - f / 4)), f = |e|^2: unit length for |e| <= 2; an
// interpolated e is inside the disk, so this stays a unit vector up to rounding.
float3 LambertDecodeNormal(float2 e)
{
    float f = dot(e, e);
    float2 xz = e * sqrt(max(1.0 - 0.25 * f, 0.0));
    return float3(xz.x, 1.0 - 0.5 * f, xz.y);
}

#endif // GT_NORMAL_ENCODING_INCLUDED
