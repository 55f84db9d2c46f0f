#ifndef GT_GREGORY_EVAL_INCLUDED
#define GT_GREGORY_EVAL_INCLUDED

// Position and true first derivatives of a Gregory patch; mirrors GregoryEval.cs (float overload).
// Exact at the four corners: one weight is 1, all others exactly 0.

#include "GregoryBasis.hlsl"

void GregoryEvaluate(float3 cp[20], float2 uv, out float3 position, out float3 dPdu, out float3 dPdv)
{
    float w[20], wu[20], wv[20];
    GregoryBasisWeights(uv, w, wu, wv);
    // Start from slot 0's term (not from zero), as the C# does: a corner value is returned untouched.
    position = w[0] * cp[0];
    // The derivative weights sum to 0, so the derivatives are sums of control-point differences
    // from slot 0. Summing the differences avoids the cancellation of summing the points: on a
    // patch 1e-6 wide at coordinates near 0.5, the points' terms are ~1e6 times the result and
    // float kept only ~5% of it (normals off by 0.04); the differences are exact there (Sterbenz).
    dPdu = float3(0.0, 0.0, 0.0);
    dPdv = float3(0.0, 0.0, 0.0);
    [unroll] for (uint k = 1u; k < 20u; k++)
    {
        float3 d = cp[k] - cp[0];
        position += w[k] * cp[k];
        dPdu += wu[k] * d;
        dPdv += wv[k] * d;
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
