#ifndef GT_GREGORY_EVAL_INCLUDED
#define GT_GREGORY_EVAL_INCLUDED

// Position and true first derivatives of a Gregory patch; mirrors GregoryEval.cs (float overload).
// Exact at the four corners: there one Bernstein weight of each direction is 1, the others exactly 0.

#include "GregoryBasis.hlsl"

// Interior pair (i, j) of the tensor form: the pair's blended point t P0 + s P1 (t = a / (a + b),
// s = b / (a + b), 0.5 each at the pair's corner, where its Bernstein weight is 0) as a difference to
// the base corner (d0 = P0 - base, d1 = P1 - base), and the pair's share of the derivatives, which
// the blend adds to the tensor sums: (W dt/du, W dt/dv) (P0 - P1) with GregoryBasisPair's
// cancellation-free W dt/du = sigmaU K (a s) s, W dt/dv = -sigmaV K (b t) t, K = 9 ru rv.
void GregoryEvaluatePair(float3 d0, float3 d1, float a, float b, float ru, float rv,
                         float sigmaU, float sigmaV, out float3 qd, inout float3 extraU, inout float3 extraV)
{
    float den = a + b;
    float t = den > 0.0 ? a / den : 0.5;
    float s = den > 0.0 ? b / den : 0.5;
    float K = 9.0 * ru * rv;
    float gu = sigmaU * K * (a * s) * s;
    float gv = -sigmaV * K * (b * t) * t;
    qd = t * d0 + s * d1;
    float3 e = d0 - d1;
    extraU += gu * e;
    extraV += gv * e;
}

// The corner of uv's quadrant (slot 0, 3, 12 or 15): GregoryEvaluate's base point.
float3 GregoryBaseCorner(float3 cp[20], float u, float v)
{
    return u < 0.5 ? (v < 0.5 ? cp[0] : cp[3]) : (v < 0.5 ? cp[12] : cp[15]);
}

// The patch as a bicubic tensor product once each interior pair is blended into one point: per row
// j (slots 4 i + j, i along u) sums over i, then one over j; the same surface as GregoryBasisWeights.
// Summed from the differences to the base corner (the derivative weights sum to 0, the position's
// to 1): on a tiny patch far from 0 the points' terms would swamp the derivatives in float, while
// the differences are exact (Sterbenz). The position is base + its sum (one set of row sums for the
// position and dP/dv), exact at each corner, the base being the corner of uv's quadrant.
void GregoryEvaluate(float3 cp[20], float2 uv, out float3 position, out float3 dPdu, out float3 dPdv)
{
    float u = saturate(uv.x);
    float v = saturate(uv.y);
    float bu[4], du[4], bv[4], dv[4];
    GregoryBasisBernstein(u, bu, du);
    GregoryBasisBernstein(v, bv, dv);
    float su = 1.0 - u;
    float sv = 1.0 - v;
    float3 corner = GregoryBaseCorner(cp, u, v);
    float3 d[16];
    [unroll] for (uint k = 0u; k < 16u; k++)
        d[k] = cp[k] - corner;
    float3 extraU = float3(0.0, 0.0, 0.0);
    float3 extraV = float3(0.0, 0.0, 0.0);
    GregoryEvaluatePair(d[5], cp[16] - corner, u, v, su * su, sv * sv, 1.0, 1.0, d[5], extraU, extraV);
    GregoryEvaluatePair(d[6], cp[17] - corner, u, sv, su * su, v * v, 1.0, -1.0, d[6], extraU, extraV);
    GregoryEvaluatePair(d[9], cp[18] - corner, su, v, u * u, sv * sv, -1.0, 1.0, d[9], extraU, extraV);
    GregoryEvaluatePair(d[10], cp[19] - corner, su, sv, u * u, v * v, -1.0, -1.0, d[10], extraU, extraV);
    position = float3(0.0, 0.0, 0.0);
    dPdu = extraU;
    dPdv = extraV;
    [unroll] for (uint j = 0u; j < 4u; j++)
    {
        float3 rowD = bu[0] * d[j] + bu[1] * d[4u + j] + bu[2] * d[8u + j] + bu[3] * d[12u + j];
        float3 rowU = du[0] * d[j] + du[1] * d[4u + j] + du[2] * d[8u + j] + du[3] * d[12u + j];
        position += bv[j] * rowD;
        dPdu += bv[j] * rowU;
        dPdv += dv[j] * rowD;
    }
    position += corner;
}

// Unit normal cross(dPdu, dPdv) / length, zero (not NaN) where they are parallel. Takes derivatives,
// so a noise gradient added first counts. Mirrors GregoryEval.NormalFromDerivatives.
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
