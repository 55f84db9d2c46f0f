using System;

namespace GregoryTerrain
{
    /// <summary>
    /// The difference <c>S(u0 + du, v0 + dv) - S(u0, v0)</c> of one Gregory patch, computed from the
    /// reference point (u0, v0) and the small step (du, dv) directly, never as the difference of two
    /// absolute evaluations, whose rounding is pixels at deep zoom (precision.md): every term here is
    /// proportional to the step, so the result carries float's relative precision of the step. Mirrors <c>GregoryDifferenceEvaluate</c> in
    /// Shaders/Library/GregoryDifference.hlsl (float overload); the double overload is the reference.
    ///
    /// <para><b>Bernstein differences</b> are exact Taylor polynomials (a cubic has three nonzero
    /// derivatives): <c>B(u0 + du) - B(u0) = du (B' + du (B''/2 + du B'''/6))</c>.</para>
    /// <para><b>Products</b>: <c>A B - A0 B0 = dA B + A0 dB</c> with <c>B = B0 + dB</c>.</para>
    /// <para><b>Pair ratios</b> <c>t = a / (a + b)</c> (GregoryBasis): <c>t - t0 = (da b0 - a0 db) / ((a + b)(a0 + b0))</c>,
    /// whose numerator is formed from the precise steps da = +-du, db = +-dv. When either denominator
    /// is 0 (a pair's own corner, where that end's Bernstein weight is 0) or underflows, the plain
    /// <c>t - t0</c> of the guarded ratios is used: the weight it multiplies is then 0 or tiny.</para>
    /// </summary>
    internal static class GregoryDifference
    {
        /// <summary>
        /// <c>S(u0 + du, v0 + dv) - S(u0, v0)</c> in float, the shaders' arithmetic. (u0, v0) and
        /// (u0 + du, v0 + dv) should lie in [0, 1]^2 (the blend has poles outside); the caller clamps.
        /// </summary>
        public static Float3 Evaluate(ReadOnlySpan<Float3> cp, float u0, float v0, float du, float dv)
        {
            CheckCount(cp.Length);
            Span<float> bu = stackalloc float[4], dbu = stackalloc float[4];
            Span<float> bv = stackalloc float[4], dbv = stackalloc float[4];
            BernsteinDifference(u0, du, bu, dbu);
            BernsteinDifference(v0, dv, bv, dbv);
            Float3 sum = new Float3(0f, 0f, 0f);
            for (int i = 0; i < 4; i++)
                for (int j = 0; j < 4; j++)
                {
                    bool interior = (i == 1 || i == 2) && (j == 1 || j == 2);
                    if (interior) continue;
                    // d(Bu Bv) = dBu (Bv0 + dBv) + Bu0 dBv
                    float dw = dbu[i] * (bv[j] + dbv[j]) + bu[i] * dbv[j];
                    sum += dw * cp[4 * i + j];
                }
            float su0 = 1f - u0, sv0 = 1f - v0;
            sum += Pair(cp, 1, 1, u0, v0, du, dv, bu, dbu, bv, dbv);
            sum += Pair(cp, 1, 2, u0, sv0, du, -dv, bu, dbu, bv, dbv);
            sum += Pair(cp, 2, 1, su0, v0, -du, dv, bu, dbu, bv, dbv);
            sum += Pair(cp, 2, 2, su0, sv0, -du, -dv, bu, dbu, bv, dbv);
            return sum;
        }

        /// <summary>The double reference of <see cref="Evaluate(ReadOnlySpan{Float3}, float, float, float, float)"/>.</summary>
        public static Double3 Evaluate(ReadOnlySpan<Double3> cp, double u0, double v0, double du, double dv)
        {
            CheckCount(cp.Length);
            Span<double> bu = stackalloc double[4], dbu = stackalloc double[4];
            Span<double> bv = stackalloc double[4], dbv = stackalloc double[4];
            BernsteinDifference(u0, du, bu, dbu);
            BernsteinDifference(v0, dv, bv, dbv);
            Double3 sum = new Double3(0.0, 0.0, 0.0);
            for (int i = 0; i < 4; i++)
                for (int j = 0; j < 4; j++)
                {
                    bool interior = (i == 1 || i == 2) && (j == 1 || j == 2);
                    if (interior) continue;
                    double dw = dbu[i] * (bv[j] + dbv[j]) + bu[i] * dbv[j];
                    sum += dw * cp[4 * i + j];
                }
            double su0 = 1.0 - u0, sv0 = 1.0 - v0;
            sum += Pair(cp, 1, 1, u0, v0, du, dv, bu, dbu, bv, dbv);
            sum += Pair(cp, 1, 2, u0, sv0, du, -dv, bu, dbu, bv, dbv);
            sum += Pair(cp, 2, 1, su0, v0, -du, dv, bu, dbu, bv, dbv);
            sum += Pair(cp, 2, 2, su0, sv0, -du, -dv, bu, dbu, bv, dbv);
            return sum;
        }

        /// <summary>
        /// Cubic Bernstein values at t0 (<paramref name="b"/>) and their exact differences
        /// <c>B_i(t0 + dt) - B_i(t0)</c> (<paramref name="db"/>) as Taylor polynomials in dt, built on
        /// <see cref="GregoryBasis.Bernstein(float, Span{float}, Span{float})"/> (values and B').
        /// </summary>
        public static void BernsteinDifference(float t0, float dt, Span<float> b, Span<float> db)
        {
            GregoryBasis.Bernstein(t0, b, db);
            float s = 1f - t0;
            // db holds B' at t0; the inner terms are B''/2 and B'''/6 at t0.
            db[0] = dt * (db[0] + dt * (3f * s + dt * -1f));
            db[1] = dt * (db[1] + dt * (3f * (t0 - 2f * s) + dt * 3f));
            db[2] = dt * (db[2] + dt * (3f * (s - 2f * t0) + dt * -3f));
            db[3] = dt * (db[3] + dt * (3f * t0 + dt * 1f));
        }

        /// <summary>The double reference of <see cref="BernsteinDifference(float, float, Span{float}, Span{float})"/>.</summary>
        public static void BernsteinDifference(double t0, double dt, Span<double> b, Span<double> db)
        {
            GregoryBasis.Bernstein(t0, b, db);
            double s = 1.0 - t0;
            db[0] = dt * (db[0] + dt * (3.0 * s + dt * -1.0));
            db[1] = dt * (db[1] + dt * (3.0 * (t0 - 2.0 * s) + dt * 3.0));
            db[2] = dt * (db[2] + dt * (3.0 * (s - 2.0 * t0) + dt * -3.0));
            db[3] = dt * (db[3] + dt * (3.0 * t0 + dt * 1.0));
        }

        /// <summary>
        /// Difference of pair (i, j)'s two terms, <c>d(W t) P_ij0 + d(W s) P_ij1</c>, with
        /// a0, b0 the distances from the pair's corner at the reference and da, db their steps.
        /// d(W t) = dW t + W0 dt and d(W s) = dW s - W0 dt (s = 1 - t).
        /// </summary>
        static Float3 Pair(ReadOnlySpan<Float3> cp, int i, int j, float a0, float b0, float da, float db,
            ReadOnlySpan<float> bu, ReadOnlySpan<float> dbu, ReadOnlySpan<float> bv, ReadOnlySpan<float> dbv)
        {
            float a = a0 + da, b = b0 + db;
            float den = a + b, den0 = a0 + b0;
            float t = den > 0f ? a / den : 0.5f;
            float s = den > 0f ? b / den : 0.5f;
            float denProduct = den * den0;
            float dt;
            if (denProduct > 0f) dt = (da * b0 - a0 * db) / denProduct;
            else dt = t - (den0 > 0f ? a0 / den0 : 0.5f);
            float w0 = bu[i] * bv[j];
            float dw = dbu[i] * (bv[j] + dbv[j]) + bu[i] * dbv[j];
            int first = 4 * i + j, second = 16 + 2 * (i - 1) + (j - 1);
            return (dw * t + w0 * dt) * cp[first] + (dw * s - w0 * dt) * cp[second];
        }

        static Double3 Pair(ReadOnlySpan<Double3> cp, int i, int j, double a0, double b0, double da, double db,
            Span<double> bu, Span<double> dbu, Span<double> bv, Span<double> dbv)
        {
            double a = a0 + da, b = b0 + db;
            double den = a + b, den0 = a0 + b0;
            double t = den > 0.0 ? a / den : 0.5;
            double s = den > 0.0 ? b / den : 0.5;
            double denProduct = den * den0;
            double dt;
            if (denProduct > 0.0) dt = (da * b0 - a0 * db) / denProduct;
            else dt = t - (den0 > 0.0 ? a0 / den0 : 0.5);
            double w0 = bu[i] * bv[j];
            double dw = dbu[i] * (bv[j] + dbv[j]) + bu[i] * dbv[j];
            int first = 4 * i + j, second = 16 + 2 * (i - 1) + (j - 1);
            return (dw * t + w0 * dt) * cp[first] + (dw * s - w0 * dt) * cp[second];
        }

        static void CheckCount(int n)
        {
            if (n != GregoryPatch.SlotCount)
                throw new ArgumentException($"cp.Length = {n}, a Gregory patch has {GregoryPatch.SlotCount} control points.", "cp");
        }
    }
}
