#ifndef GT_GREGORY_EVAL_INCLUDED
#define GT_GREGORY_EVAL_INCLUDED

// Position and true first derivatives of a Gregory patch; mirrors GregoryEval.cs (float overload).
// Exact at the four corners: one weight is 1, all others exactly 0.

#include "GregoryBasis.hlsl"

void GregoryEvaluate(float3 cp[20], float2 uv, out float3 position, out float3 dPdu, out float3 dPdv)
{
    float w[20], wu[20], wv[20];
    GregoryBasisWeights(uv, w, wu, wv);
    // Start from slot 0's term (not from zero), as the C# does.
    position = w[0] * cp[0];
    dPdu = wu[0] * cp[0];
    dPdv = wv[0] * cp[0];
    [unroll] for (uint k = 1u; k < 20u; k++)
    {
        position += w[k] * cp[k];
        dPdu += wu[k] * cp[k];
        dPdv += wv[k] * cp[k];
    }
}

// Unit normal normalize(cross(dP/du, dP/dv)); zero where the patch is degenerate (as GMath.normalize).
float3 GregoryNormal(float3 cp[20], float2 uv)
{
    float3 position, dPdu, dPdv;
    GregoryEvaluate(cp, uv, position, dPdu, dPdv);
    float3 n = cross(dPdu, dPdv);
    float l = length(n);
    return l > 0.0 ? n / l : float3(0.0, 0.0, 0.0);
}

#endif // GT_GREGORY_EVAL_INCLUDED
