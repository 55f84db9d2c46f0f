using System;
using static GregoryTerrain.GMath;

namespace GregoryTerrain
{
    /// <summary>
    /// Position and true first derivatives of a Gregory patch at (u, v):
    /// <c>S = sum_k w_k P_k</c>, <c>dS/du = sum_k dw_k/du P_k</c>, <c>dS/dv = sum_k dw_k/dv P_k</c>
    /// with the weights of <see cref="GregoryBasis"/>. Float overload = the shaders' arithmetic, the
    /// same sum in tensor form (mirrors <c>GregoryEvaluate</c> in <c>Shaders/Library/GregoryEval.hlsl</c>);
    /// double = the reference, the 20 weights summed.
    ///
    /// <para>At the four corners exactly one weight is 1 and all others are exactly 0 (the Bernstein
    /// polynomials are exact there and the pair guard gives 0 * 0.5), so the position equals the
    /// corner control point exactly in both precisions (in tensor form: each row sum and the sum of
    /// the rows is 1 * one value + 0 * the others).</para>
    /// </summary>
    internal static class GregoryEval
    {
        /// <summary>
        /// Evaluates the patch with control points <paramref name="cp"/> (20, slot order) in float, as the
        /// shaders do: each interior pair blended into one point, then the bicubic tensor product row by
        /// row (mirrors HLSL <c>GregoryEvaluate</c> step for step). The same surface as the 20 weights of
        /// <see cref="GregoryBasis"/>, which the double overload sums (the reference).
        /// </summary>
        public static void Evaluate(ReadOnlySpan<Float3> cp, float u, float v,
            out Float3 position, out Float3 dPdu, out Float3 dPdv)
        {
            CheckCount(cp.Length);
            u = saturate(u);
            v = saturate(v);
            Span<float> bu = stackalloc float[4], du = stackalloc float[4], bv = stackalloc float[4], dv = stackalloc float[4];
            GregoryBasis.Bernstein(u, bu, du);
            GregoryBasis.Bernstein(v, bv, dv);
            float su = 1f - u;
            float sv = 1f - v;
            // Everything from the differences to the base corner (the derivative weights sum to 0, the
            // position's to 1), not from the points, or a tiny patch far from the origin cancels away;
            // the position is corner + its sum, exact at each corner (see GregoryEval.hlsl).
            Float3 corner = BaseCorner(cp, u, v);
            Span<Float3> d = stackalloc Float3[16];
            for (int k = 0; k < 16; k++)
                d[k] = cp[k] - corner;
            Float3 extraU = Float3.zero, extraV = Float3.zero;
            EvaluatePair(d[5], cp[16] - corner, u, v, su * su, sv * sv, 1f, 1f, out d[5], ref extraU, ref extraV);
            EvaluatePair(d[6], cp[17] - corner, u, sv, su * su, v * v, 1f, -1f, out d[6], ref extraU, ref extraV);
            EvaluatePair(d[9], cp[18] - corner, su, v, u * u, sv * sv, -1f, 1f, out d[9], ref extraU, ref extraV);
            EvaluatePair(d[10], cp[19] - corner, su, sv, u * u, v * v, -1f, -1f, out d[10], ref extraU, ref extraV);
            position = Float3.zero;
            dPdu = extraU;
            dPdv = extraV;
            for (int j = 0; j < 4; j++)
            {
                Float3 rowD = bu[0] * d[j] + bu[1] * d[4 + j] + bu[2] * d[8 + j] + bu[3] * d[12 + j];
                Float3 rowU = du[0] * d[j] + du[1] * d[4 + j] + du[2] * d[8 + j] + du[3] * d[12 + j];
                position += bv[j] * rowD;
                dPdu += bv[j] * rowU;
                dPdv += dv[j] * rowD;
            }
            position += corner;
        }

        /// <summary>HLSL <c>GregoryBaseCorner</c>: the corner of (u, v)'s quadrant (slot 0, 3, 12 or 15).</summary>
        static Float3 BaseCorner(ReadOnlySpan<Float3> cp, float u, float v) =>
            u < 0.5f ? (v < 0.5f ? cp[0] : cp[3]) : (v < 0.5f ? cp[12] : cp[15]);

        /// <summary>
        /// Interior pair of the tensor form (HLSL <c>GregoryEvaluatePair</c>): the blended point
        /// <c>t P0 + s P1</c> (<c>t = a / (a + b)</c>, 0.5 at the pair's corner) as a difference to the
        /// base corner (<paramref name="d0"/> = P0 - corner), and the pair's share
        /// <c>(W dt/du, W dt/dv) (P0 - P1)</c> of the derivatives, with <see cref="GregoryBasis"/>'s
        /// cancellation-free <c>W dt/du = sigmaU K (a s) s</c>.
        /// </summary>
        static void EvaluatePair(Float3 d0, Float3 d1, float a, float b, float ru, float rv,
            float sigmaU, float sigmaV, out Float3 qd, ref Float3 extraU, ref Float3 extraV)
        {
            float den = a + b;
            float t = den > 0f ? a / den : 0.5f;
            float s = den > 0f ? b / den : 0.5f;
            float K = 9f * ru * rv;
            float gu = sigmaU * K * (a * s) * s;
            float gv = -sigmaV * K * (b * t) * t;
            qd = t * d0 + s * d1;
            Float3 e = d0 - d1;
            extraU += gu * e;
            extraV += gv * e;
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
