using System;
using static GregoryTerrain.GMath;

namespace GregoryTerrain
{
    /// <summary>
    /// The 20 basis weights of a bicubic Gregory patch and their u- and v-derivatives:
    /// <c>S(u,v) = sum_k w_k(u,v) P_k</c> in the slot order of <see cref="GregoryPatch"/>.
    /// Two overloads: float (every step rounded to float, as the shaders do; mirrors
    /// <c>Shaders/Library/GregoryBasis.hlsl</c> line for line) and double (the reference).
    ///
    /// <para><b>The interior pairs.</b> Slot pair (P_ij0, P_ij1), i, j in {1, 2}, is blended with the
    /// weight <c>t = a / (a + b)</c> of P_ij0 and <c>s = b / (a + b)</c> of P_ij1, where
    /// <c>a = u</c> (i = 1) or <c>1 - u</c> (i = 2) and <c>b = v</c> (j = 1) or <c>1 - v</c> (j = 2)
    /// (internals.md; this is eq. 5 with the quotient split into two weights). Both are ratios in
    /// [0, 1], never 0/0 except at the one corner where a = b = 0; there the Bernstein weight
    /// <c>W = B_i(u) B_j(v)</c> of the pair is exactly 0, so any finite t works and we use 0.5.</para>
    ///
    /// <para><b>Derivatives without small divisors.</b> Write <c>B_i(u) = 3 a R_u</c> with
    /// <c>R_u = (1-u)^2</c> (i = 1) or <c>u^2</c> (i = 2), likewise <c>B_j(v) = 3 b R_v</c>, so
    /// <c>W = 9 a b R_u R_v = K a b</c>. With <c>da/du = sigma_u = +-1</c>, the quotient rule gives
    /// <c>W dt/du = sigma_u K a b * b / (a+b)^2 = sigma_u K (a s) s</c> and
    /// <c>W dt/dv = -sigma_v K a b * a / (a+b)^2 = -sigma_v K (b t) t</c>:
    /// the factor a b of W cancels the (a+b)^2, leaving products of numbers in [0, 9]. Nothing is
    /// divided by a small number, nothing overflows, and every term tends to 0 at the pair's corner
    /// (they are bounded by K a and K b), so weights and derivatives are finite and continuous down to
    /// subnormal distances from the corner. Since s = 1 - t, <c>d(W s) = dW s - W dt</c>.</para>
    ///
    /// <para>u and v are clamped to [0, 1] first: the rational blend has poles outside the unit
    /// square (e.g. u + v = 0), and callers that compute u from a global point may land a rounding
    /// error outside.</para>
    /// </summary>
    internal static class GregoryBasis
    {
        public const int WeightCount = GregoryPatch.SlotCount;

        /// <summary>Cubic Bernstein polynomials B3_0..B3_3 at t and their derivatives (spans of length 4).</summary>
        public static void Bernstein(float t, Span<float> b, Span<float> d)
        {
            float s = 1f - t;
            b[0] = s * s * s;
            b[1] = 3f * t * s * s;
            b[2] = 3f * t * t * s;
            b[3] = t * t * t;
            d[0] = -3f * s * s;
            d[1] = 3f * s * (s - 2f * t);
            d[2] = 3f * t * (2f * s - t);
            d[3] = 3f * t * t;
        }

        /// <summary>Cubic Bernstein polynomials B3_0..B3_3 at t and their derivatives (spans of length 4).</summary>
        public static void Bernstein(double t, Span<double> b, Span<double> d)
        {
            double s = 1.0 - t;
            b[0] = s * s * s;
            b[1] = 3.0 * t * s * s;
            b[2] = 3.0 * t * t * s;
            b[3] = t * t * t;
            d[0] = -3.0 * s * s;
            d[1] = 3.0 * s * (s - 2.0 * t);
            d[2] = 3.0 * t * (2.0 * s - t);
            d[3] = 3.0 * t * t;
        }

        /// <summary>
        /// The 20 weights <paramref name="w"/> and their derivatives <paramref name="wu"/> = dw/du,
        /// <paramref name="wv"/> = dw/dv at (u, v), in float arithmetic (each span length 20).
        /// </summary>
        public static void Weights(float u, float v, Span<float> w, Span<float> wu, Span<float> wv)
        {
            CheckLengths(w.Length, wu.Length, wv.Length);
            u = saturate(u);
            v = saturate(v);
            Span<float> bu = stackalloc float[4], du = stackalloc float[4];
            Span<float> bv = stackalloc float[4], dv = stackalloc float[4];
            Bernstein(u, bu, du);
            Bernstein(v, bv, dv);

            // Tensor-product (Bezier) weights for the 16 grid slots; the 4 interior ones are
            // overwritten by their pairs below.
            for (int i = 0; i < 4; i++)
                for (int j = 0; j < 4; j++)
                {
                    int k = 4 * i + j;
                    w[k] = bu[i] * bv[j];
                    wu[k] = du[i] * bv[j];
                    wv[k] = bu[i] * dv[j];
                }

            float su = 1f - u, sv = 1f - v;
            // Pair (i, j): a, R_u and sigma_u from i; b, R_v and sigma_v from j (see the class comment).
            Pair(1, 1, u, v, su * su, sv * sv, +1f, +1f, bu, du, bv, dv, w, wu, wv);
            Pair(1, 2, u, sv, su * su, v * v, +1f, -1f, bu, du, bv, dv, w, wu, wv);
            Pair(2, 1, su, v, u * u, sv * sv, -1f, +1f, bu, du, bv, dv, w, wu, wv);
            Pair(2, 2, su, sv, u * u, v * v, -1f, -1f, bu, du, bv, dv, w, wu, wv);
        }

        /// <summary>
        /// The 20 weights <paramref name="w"/> and their derivatives <paramref name="wu"/> = dw/du,
        /// <paramref name="wv"/> = dw/dv at (u, v), in double arithmetic (each span length 20).
        /// </summary>
        public static void Weights(double u, double v, Span<double> w, Span<double> wu, Span<double> wv)
        {
            CheckLengths(w.Length, wu.Length, wv.Length);
            u = saturate(u);
            v = saturate(v);
            Span<double> bu = stackalloc double[4], du = stackalloc double[4];
            Span<double> bv = stackalloc double[4], dv = stackalloc double[4];
            Bernstein(u, bu, du);
            Bernstein(v, bv, dv);

            for (int i = 0; i < 4; i++)
                for (int j = 0; j < 4; j++)
                {
                    int k = 4 * i + j;
                    w[k] = bu[i] * bv[j];
                    wu[k] = du[i] * bv[j];
                    wv[k] = bu[i] * dv[j];
                }

            double su = 1.0 - u, sv = 1.0 - v;
            Pair(1, 1, u, v, su * su, sv * sv, +1.0, +1.0, bu, du, bv, dv, w, wu, wv);
            Pair(1, 2, u, sv, su * su, v * v, +1.0, -1.0, bu, du, bv, dv, w, wu, wv);
            Pair(2, 1, su, v, u * u, sv * sv, -1.0, +1.0, bu, du, bv, dv, w, wu, wv);
            Pair(2, 2, su, sv, u * u, v * v, -1.0, -1.0, bu, du, bv, dv, w, wu, wv);
        }

        /// <summary>
        /// Weights of the interior pair (i, j): slot 4 i + j gets W t, slot 16 + 2 (i-1) + (j-1) gets W s.
        /// a, b: the distances (in u and v) from the pair's corner; ru, rv: R_u, R_v; sigmaU, sigmaV: da/du, db/dv.
        /// </summary>
        static void Pair(int i, int j, float a, float b, float ru, float rv, float sigmaU, float sigmaV,
            ReadOnlySpan<float> bu, ReadOnlySpan<float> du, ReadOnlySpan<float> bv, ReadOnlySpan<float> dv, Span<float> w, Span<float> wu, Span<float> wv)
        {
            float den = a + b;
            // den == 0 only at the pair's own corner (a = b = 0), where W = 0: any finite t will do.
            float t = den > 0f ? a / den : 0.5f;
            float s = den > 0f ? b / den : 0.5f;
            float W = bu[i] * bv[j], Wu = du[i] * bv[j], Wv = bu[i] * dv[j];
            float K = 9f * ru * rv;
            float gu = sigmaU * K * (a * s) * s;  // W dt/du
            float gv = -sigmaV * K * (b * t) * t; // W dt/dv
            int first = 4 * i + j, second = 16 + 2 * (i - 1) + (j - 1);
            w[first] = W * t;
            wu[first] = Wu * t + gu;
            wv[first] = Wv * t + gv;
            w[second] = W * s;
            wu[second] = Wu * s - gu;
            wv[second] = Wv * s - gv;
        }

        static void Pair(int i, int j, double a, double b, double ru, double rv, double sigmaU, double sigmaV,
            Span<double> bu, Span<double> du, Span<double> bv, Span<double> dv, Span<double> w, Span<double> wu, Span<double> wv)
        {
            double den = a + b;
            double t = den > 0.0 ? a / den : 0.5;
            double s = den > 0.0 ? b / den : 0.5;
            double W = bu[i] * bv[j], Wu = du[i] * bv[j], Wv = bu[i] * dv[j];
            double K = 9.0 * ru * rv;
            double gu = sigmaU * K * (a * s) * s;
            double gv = -sigmaV * K * (b * t) * t;
            int first = 4 * i + j, second = 16 + 2 * (i - 1) + (j - 1);
            w[first] = W * t;
            wu[first] = Wu * t + gu;
            wv[first] = Wv * t + gv;
            w[second] = W * s;
            wu[second] = Wu * s - gu;
            wv[second] = Wv * s - gv;
        }

        static void CheckLengths(int w, int wu, int wv)
        {
            if (w < WeightCount) throw new ArgumentException($"w.Length = {w}, need {WeightCount}.", nameof(w));
            if (wu < WeightCount) throw new ArgumentException($"wu.Length = {wu}, need {WeightCount}.", nameof(wu));
            if (wv < WeightCount) throw new ArgumentException($"wv.Length = {wv}, need {WeightCount}.", nameof(wv));
        }
    }
}
