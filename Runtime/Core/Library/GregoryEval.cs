using System;
using static GregoryTerrain.GMath;

namespace GregoryTerrain
{
    /// <summary>
    /// Position and true first derivatives of a Gregory patch at (u, v):
    /// <c>S = sum_k w_k P_k</c>, <c>dS/du = sum_k dw_k/du P_k</c>, <c>dS/dv = sum_k dw_k/dv P_k</c>
    /// with the weights of <see cref="GregoryBasis"/>. Float overload = the shaders' arithmetic
    /// (mirrors <c>GregoryEvaluate</c> in <c>Shaders/Library/GregoryEval.hlsl</c>); double = the reference.
    ///
    /// <para>At the four corners exactly one weight is 1 and all others are exactly 0 (the Bernstein
    /// polynomials are exact there and the pair guard gives 0 * 0.5), so the position equals the
    /// corner control point exactly in both precisions.</para>
    /// </summary>
    internal static class GregoryEval
    {
        /// <summary>Evaluates the patch with control points <paramref name="cp"/> (20, slot order) in float.</summary>
        public static void Evaluate(ReadOnlySpan<Float3> cp, float u, float v,
            out Float3 position, out Float3 dPdu, out Float3 dPdv)
        {
            CheckCount(cp.Length);
            Span<float> w = stackalloc float[GregoryBasis.WeightCount];
            Span<float> wu = stackalloc float[GregoryBasis.WeightCount];
            Span<float> wv = stackalloc float[GregoryBasis.WeightCount];
            GregoryBasis.Weights(u, v, w, wu, wv);
            // Start from slot 0's term rather than from zero so a corner value is returned untouched.
            position = w[0] * cp[0];
            // The derivative weights sum to 0: sum the control-point differences from slot 0, not the
            // points, or a tiny patch far from the origin cancels away (see GregoryEval.hlsl).
            dPdu = Float3.zero;
            dPdv = Float3.zero;
            for (int k = 1; k < GregoryBasis.WeightCount; k++)
            {
                Float3 d = cp[k] - cp[0];
                position += w[k] * cp[k];
                dPdu += wu[k] * d;
                dPdv += wv[k] * d;
            }
        }

        /// <summary>Evaluates the patch with control points <paramref name="cp"/> (20, slot order) in double.</summary>
        public static void Evaluate(ReadOnlySpan<Double3> cp, double u, double v,
            out Double3 position, out Double3 dPdu, out Double3 dPdv)
        {
            CheckCount(cp.Length);
            Span<double> w = stackalloc double[GregoryBasis.WeightCount];
            Span<double> wu = stackalloc double[GregoryBasis.WeightCount];
            Span<double> wv = stackalloc double[GregoryBasis.WeightCount];
            GregoryBasis.Weights(u, v, w, wu, wv);
            position = w[0] * cp[0];
            dPdu = Double3.zero;
            dPdv = Double3.zero;
            for (int k = 1; k < GregoryBasis.WeightCount; k++)
            {
                Double3 d = cp[k] - cp[0];
                position += w[k] * cp[k];
                dPdu += wu[k] * d;
                dPdv += wv[k] * d;
            }
        }

        /// <summary>Position only, double (convenience for fitting and measuring).</summary>
        public static Double3 Position(ReadOnlySpan<Double3> cp, double u, double v)
        {
            Evaluate(cp, u, v, out Double3 p, out _, out _);
            return p;
        }

        /// <summary>Unit normal <c>normalize(cross(dP/du, dP/dv))</c> in float (zero where the patch is degenerate).</summary>
        public static Float3 Normal(ReadOnlySpan<Float3> cp, float u, float v)
        {
            Evaluate(cp, u, v, out _, out Float3 du, out Float3 dv);
            return NormalFromDerivatives(du, dv);
        }

        /// <summary>Unit normal <c>normalize(cross(dP/du, dP/dv))</c> in double (zero where the patch is degenerate).</summary>
        public static Double3 Normal(ReadOnlySpan<Double3> cp, double u, double v)
        {
            Evaluate(cp, u, v, out _, out Double3 du, out Double3 dv);
            return NormalFromDerivatives(du, dv);
        }

        /// <summary>
        /// Unit normal of a surface with partial derivatives <paramref name="dPdu"/>, <paramref name="dPdv"/>:
        /// <c>cross(dPdu, dPdv) / length</c>, the zero vector where they are parallel (a degenerate
        /// patch) instead of NaN. Takes derivatives, not control points, so a caller that has already
        /// added a detail term (the noise gradient) gets the normal of the sum. Mirrors HLSL
        /// <c>GregoryNormalFromDerivatives</c> step for step (cross, sqrt of the dot, one division).
        /// </summary>
        public static Float3 NormalFromDerivatives(Float3 dPdu, Float3 dPdv)
        {
            Float3 n = cross(dPdu, dPdv);
            float l = length(n);
            return l > 0f ? n / l : Float3.zero;
        }

        /// <summary>The double reference of <see cref="NormalFromDerivatives(Float3, Float3)"/>.</summary>
        public static Double3 NormalFromDerivatives(Double3 dPdu, Double3 dPdv)
        {
            Double3 n = cross(dPdu, dPdv);
            double l = length(n);
            return l > 0.0 ? n / l : Double3.zero;
        }

        static void CheckCount(int n)
        {
            if (n != GregoryPatch.SlotCount)
                throw new ArgumentException($"cp.Length = {n}, a Gregory patch has {GregoryPatch.SlotCount} control points.", "cp");
        }
    }
}
