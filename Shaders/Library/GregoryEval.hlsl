#ifndef GT_GREGORY_EVAL_INCLUDED
#define GT_GREGORY_EVAL_INCLUDED

// Position and true first derivatives of a Gregory patch; mirrors GregoryEval.cs (float overload).
// Exact at the four corners: there one Bernstein weight of each direction is 1, the others exactly 0.

#include "GregoryBasis.hlsl"

// Interior pair (i, j) of the tensor form: the pair's blended point q = t P0 + s P1 (t = a / (a + b),
// s = b / (a + b), 0.5 each at the pair's corner, where its Bernstein weight is 0), the same from
// cp[0] (qd, with d0 = P0 - cp[0], d1 = P1 - cp[0]), and the pair's share of the derivatives, which
// the blend adds to the tensor sums: (W dt/du, W dt/dv) (P0 - P1) with GregoryBasisPair's
// cancellation-free W dt/du = sigmaU K (a s) s, W dt/dv = -sigmaV K (b t) t, K = 9 ru rv.
void GregoryEvaluatePair(float3 p0, float3 p1, float3 d0, float3 d1, float a, float b, float ru, float rv,
                         float sigmaU, float sigmaV, out float3 q, out float3 qd, inout float3 extraU, inout float3 extraV)
{
    float den = a + b;
    float t = den > 0.0 ? a / den : 0.5;
    float s = den > 0.0 ? b / den : 0.5;
    float K = 9.0 * ru * rv;
    float gu = sigmaU * K * (a * s) * s;
    float gv = -sigmaV * K * (b * t) * t;
    q = t * p0 + s * p1;
    qd = t * d0 + s * d1;
    float3 e = d0 - d1;
    extraU += gu * e;
    extraV += gv * e;
}

// The patch as a bicubic tensor product once each interior pair is blended into one point: per row
// j (slots 4 i + j, i along u) three sums over i, then one over j. The same surface as the 20
// weights of GregoryBasisWeights (which stay the reference), with ~40% fewer live values: the 60
// weights were what made the domain stage slow (performance.md, "Where the domain stage's time
// goes"). Exact at the four corners: every row sum there is 1 * one point + 0 * the others.
void GregoryEvaluate(float3 cp[20], float2 uv, out float3 position, out float3 dPdu, out float3 dPdv)
{
    float u = saturate(uv.x);
    float v = saturate(uv.y);
    float bu[4], du[4], bv[4], dv[4];
    GregoryBasisBernstein(u, bu, du);
    GregoryBasisBernstein(v, bv, dv);
    float su = 1.0 - u;
    float sv = 1.0 - v;
    // Derivatives from the differences to cp[0] (the derivative weights sum to 0): on a patch 1e-6
    // wide at coordinates near 0.5 the points' terms are ~1e6 times the result and float kept only
    // ~5% of it (normals off by 0.04); the differences are exact there (Sterbenz).
    float3 q[16], d[16];
    [unroll] for (uint k = 0u; k < 16u; k++)
    {
        q[k] = cp[k];
        d[k] = cp[k] - cp[0];
    }
    float3 extraU = float3(0.0, 0.0, 0.0);
    float3 extraV = float3(0.0, 0.0, 0.0);
    GregoryEvaluatePair(cp[5], cp[16], cp[5] - cp[0], cp[16] - cp[0], u, v, su * su, sv * sv, 1.0, 1.0, q[5], d[5], extraU, extraV);
    GregoryEvaluatePair(cp[6], cp[17], cp[6] - cp[0], cp[17] - cp[0], u, sv, su * su, v * v, 1.0, -1.0, q[6], d[6], extraU, extraV);
    GregoryEvaluatePair(cp[9], cp[18], cp[9] - cp[0], cp[18] - cp[0], su, v, u * u, sv * sv, -1.0, 1.0, q[9], d[9], extraU, extraV);
    GregoryEvaluatePair(cp[10], cp[19], cp[10] - cp[0], cp[19] - cp[0], su, sv, u * u, v * v, -1.0, -1.0, q[10], d[10], extraU, extraV);
    position = float3(0.0, 0.0, 0.0);
    dPdu = extraU;
    dPdv = extraV;
    [unroll] for (uint j = 0u; j < 4u; j++)
    {
        float3 row = bu[0] * q[j] + bu[1] * q[4u + j] + bu[2] * q[8u + j] + bu[3] * q[12u + j];
        float3 rowD = bu[0] * d[j] + bu[1] * d[4u + j] + bu[2] * d[8u + j] + bu[3] * d[12u + j];
        float3 rowU = du[0] * d[j] + du[1] * d[4u + j] + du[2] * d[8u + j] + du[3] * d[12u + j];
        position += bv[j] * row;
        dPdu += bv[j] * rowU;
        dPdv += dv[j] * rowD;
    }
}

// Unit normal of a surface with these partial derivatives: cross(dPdu, dPdv) / length, zero where
// they are parallel (a degenerate patch) instead of NaN. Takes derivatives, so a caller that has
// added a detail term (the noise gradient) gets the normal of the sum. Mirrors
// GregoryEval.NormalFromDerivatives.
float3 GregoryNormalFromDerivatives(float3 dPdu, float3 dPdv)
{
    float3 n = cross(dPdu, dPdv);
    float l = length(n);
    return l > 0.0 ? n / l : float3(0.0, 0.0, 0.0);
}

// Unit normal normalize(cross(dP/du, dP/dv)) of the patch at uv.
float3 GregoryNormal(float3 cp[20], float2 uv)
{
    float3 position, dPdu, dPdv;
    GregoryEvaluate(cp, uv, position, dPdu, dPdv);
    return GregoryNormalFromDerivatives(dPdu, dPdv);
}

#endif // GT_GREGORY_EVAL_INCLUDED
