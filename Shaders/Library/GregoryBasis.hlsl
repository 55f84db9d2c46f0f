#ifndef GT_GREGORY_BASIS_INCLUDED
#define GT_GREGORY_BASIS_INCLUDED

// The 20 Gregory basis weights and their u- and v-derivatives; mirrors GregoryBasis.cs (float
// overload) line for line. The derivation (no small divisors, t = 0.5 at a pair's own corner, u and v
// clamped to [0, 1]): that file's summary.

#include "GregoryPatch.hlsl"

// Cubic Bernstein polynomials B3_0..3 at t and their derivatives.
void GregoryBasisBernstein(float t, out float b[4], out float d[4])
{
    float s = 1.0 - t;
    b[0] = s * s * s;
    b[1] = 3.0 * t * s * s;
    b[2] = 3.0 * t * t * s;
    b[3] = t * t * t;
    d[0] = -3.0 * s * s;
    d[1] = 3.0 * s * (s - 2.0 * t);
    d[2] = 3.0 * t * (2.0 * s - t);
    d[3] = 3.0 * t * t;
}

// Weights of interior pair (i, j): slot 4 i + j gets W t, slot 16 + 2 (i-1) + (j-1) gets W s.
void GregoryBasisPair(uint i, uint j, float a, float b, float ru, float rv, float sigmaU, float sigmaV,
    float bu[4], float du[4], float bv[4], float dv[4],
    inout float w[20], inout float wu[20], inout float wv[20])
{
    float den = a + b;
    float t = den > 0.0 ? a / den : 0.5;
    float s = den > 0.0 ? b / den : 0.5;
    float W = bu[i] * bv[j];
    float Wu = du[i] * bv[j];
    float Wv = bu[i] * dv[j];
    float K = 9.0 * ru * rv;
    float gu = sigmaU * K * (a * s) * s;  // W dt/du
    float gv = -sigmaV * K * (b * t) * t; // W dt/dv
    uint first = 4u * i + j;
    uint second = 16u + 2u * (i - 1u) + (j - 1u);
    w[first] = W * t;
    wu[first] = Wu * t + gu;
    wv[first] = Wv * t + gv;
    w[second] = W * s;
    wu[second] = Wu * s - gu;
    wv[second] = Wv * s - gv;
}

// The 20 weights w and their derivatives wu = dw/du, wv = dw/dv at uv.
void GregoryBasisWeights(float2 uv, out float w[20], out float wu[20], out float wv[20])
{
    float u = saturate(uv.x);
    float v = saturate(uv.y);
    float bu[4], du[4], bv[4], dv[4];
    GregoryBasisBernstein(u, bu, du);
    GregoryBasisBernstein(v, bv, dv);

    [unroll] for (uint i = 0u; i < 4u; i++)
    {
        [unroll] for (uint j = 0u; j < 4u; j++)
        {
            uint k = 4u * i + j;
            w[k] = bu[i] * bv[j];
            wu[k] = du[i] * bv[j];
            wv[k] = bu[i] * dv[j];
        }
    }
    // Slots 16..19 are written by the pairs; give them a value first so every element is defined.
    [unroll] for (uint k2 = 16u; k2 < 20u; k2++)
    {
        w[k2] = 0.0;
        wu[k2] = 0.0;
        wv[k2] = 0.0;
    }

    float su = 1.0 - u;
    float sv = 1.0 - v;
    GregoryBasisPair(1u, 1u, u, v, su * su, sv * sv, 1.0, 1.0, bu, du, bv, dv, w, wu, wv);
    GregoryBasisPair(1u, 2u, u, sv, su * su, v * v, 1.0, -1.0, bu, du, bv, dv, w, wu, wv);
    GregoryBasisPair(2u, 1u, su, v, u * u, sv * sv, -1.0, 1.0, bu, du, bv, dv, w, wu, wv);
    GregoryBasisPair(2u, 2u, su, sv, u * u, v * v, -1.0, -1.0, bu, du, bv, dv, w, wu, wv);
}

#endif // GT_GREGORY_BASIS_INCLUDED
