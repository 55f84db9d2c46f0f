#ifndef GT_GREGORY_DIFFERENCE_INCLUDED
#define GT_GREGORY_DIFFERENCE_INCLUDED

// S(u0 + du, v0 + dv) - S(u0, v0) of one Gregory patch from the reference (u0, v0) and the step
// (du, dv) directly, never as the difference of two absolute evaluations; mirrors
// GregoryDifference.cs (float overload), whose summary gives the terms. Every term is proportional
// to the step, so the result keeps float's relative precision of the step itself.

#include "GregoryBasis.hlsl"

void GregoryBernsteinDifference(float t0, float dt, out float b[4], out float db[4])
{
    GregoryBasisBernstein(t0, b, db);
    float s = 1.0 - t0;
    // db holds B' at t0; the inner terms are B''/2 and B'''/6 at t0.
    db[0] = dt * (db[0] + dt * (3.0 * s + dt * -1.0));
    db[1] = dt * (db[1] + dt * (3.0 * (t0 - 2.0 * s) + dt * 3.0));
    db[2] = dt * (db[2] + dt * (3.0 * (s - 2.0 * t0) + dt * -3.0));
    db[3] = dt * (db[3] + dt * (3.0 * t0 + dt * 1.0));
}

float3 GregoryDifferencePair(float3 cp[20], uint i, uint j, float a0, float b0, float da, float db,
    float bu[4], float dbu[4], float bv[4], float dbv[4])
{
    float a = a0 + da;
    float b = b0 + db;
    float den = a + b;
    float den0 = a0 + b0;
    float t = den > 0.0 ? a / den : 0.5;
    float s = den > 0.0 ? b / den : 0.5;
    float denProduct = den * den0;
    float dt = denProduct > 0.0 ? (da * b0 - a0 * db) / denProduct : t - (den0 > 0.0 ? a0 / den0 : 0.5);
    float w0 = bu[i] * bv[j];
    float dw = dbu[i] * (bv[j] + dbv[j]) + bu[i] * dbv[j];
    uint first = 4u * i + j;
    uint second = 16u + 2u * (i - 1u) + (j - 1u);
    return (dw * t + w0 * dt) * cp[first] + (dw * s - w0 * dt) * cp[second];
}

float3 GregoryDifferenceEvaluate(float3 cp[20], float2 uv0, float2 duv)
{
    float bu[4], dbu[4], bv[4], dbv[4];
    GregoryBernsteinDifference(uv0.x, duv.x, bu, dbu);
    GregoryBernsteinDifference(uv0.y, duv.y, bv, dbv);
    float3 sum = float3(0.0, 0.0, 0.0);
    [unroll] for (uint i = 0u; i < 4u; i++)
    {
        [unroll] for (uint j = 0u; j < 4u; j++)
        {
            bool interior = (i == 1u || i == 2u) && (j == 1u || j == 2u);
            if (!interior)
                sum += (dbu[i] * (bv[j] + dbv[j]) + bu[i] * dbv[j]) * cp[4u * i + j];
        }
    }
    float su0 = 1.0 - uv0.x;
    float sv0 = 1.0 - uv0.y;
    sum += GregoryDifferencePair(cp, 1u, 1u, uv0.x, uv0.y, duv.x, duv.y, bu, dbu, bv, dbv);
    sum += GregoryDifferencePair(cp, 1u, 2u, uv0.x, sv0, duv.x, -duv.y, bu, dbu, bv, dbv);
    sum += GregoryDifferencePair(cp, 2u, 1u, su0, uv0.y, -duv.x, duv.y, bu, dbu, bv, dbv);
    sum += GregoryDifferencePair(cp, 2u, 2u, su0, sv0, -duv.x, -duv.y, bu, dbu, bv, dbv);
    return sum;
}

#endif // GT_GREGORY_DIFFERENCE_INCLUDED
