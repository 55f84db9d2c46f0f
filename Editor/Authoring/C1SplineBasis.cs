using System;

namespace GregoryTerrain
{
    /// <summary>
    /// The C1 piecewise cubics on <see cref="Spans"/> equal spans of [0, 1], in the Bezier form a
    /// Gregory grid uses. Knot k (at k / P) carries two coefficients: index 2k is the height z_k
    /// and 2k + 1 the offset d_k = (span / 3) slope, in height units, so span s's Bezier points are
    /// <c>(z_s, z_s + d_s, z_{s+1} - d_{s+1}, z_{s+1})</c>: consecutive spans share z_k and their
    /// neighbouring Bezier points sit symmetrically at z_k -+ d_k, which is C1. A sample at t of span s
    /// depends on the four coefficients 2s .. 2s + 3, so the normal matrix of any sample set is a band
    /// with 3 diagonals above the main one.
    /// </summary>
    internal readonly struct C1SplineBasis
    {
        /// <summary>Diagonals above the main one in a normal matrix of this basis.</summary>
        public const int Bandwidth = 3;

        public int Spans { get; }
        /// <summary>2 (P + 1) coefficients.</summary>
        public int Count => 2 * (Spans + 1);

        public C1SplineBasis(int spans)
        {
            if (spans < 1) throw new ArgumentException($"spans = {spans}, need at least 1.", nameof(spans));
            Spans = spans;
        }

        /// <summary>
        /// Where sample <paramref name="index"/> of <paramref name="samples"/> (at index / (samples - 1))
        /// falls: the span s (its first coefficient is 2 s) and the four weights of coefficients
        /// 2s .. 2s + 3. Integer arithmetic for s and t, so a sample on a knot gets t exactly 0 or 1.
        /// </summary>
        public int Weights(long index, long samples, Span<double> w)
        {
            long n = samples - 1, num = index * Spans;
            long s = num / n;
            if (s >= Spans) s = Spans - 1;
            double t = (double)(num - s * n) / n;
            SpanWeights(t, w);
            return (int)s;
        }

        /// <summary>The weights at parameter t of a span, for (z_s, d_s, z_{s+1}, d_{s+1}).</summary>
        public static void SpanWeights(double t, Span<double> w)
        {
            double u = 1 - t;
            double b0 = u * u * u, b1 = 3 * t * u * u, b2 = 3 * t * t * u, b3 = t * t * t;
            w[0] = b0 + b1;
            w[1] = b1;
            w[2] = b2 + b3;
            w[3] = -b2;
        }

        /// <summary>Bezier point k (0..3) of span s from the coefficients (a row of <see cref="Count"/> values, stride apart).</summary>
        public static double BezierPoint(ReadOnlySpan<double> coefficients, int s, int k, int stride = 1)
        {
            double z0 = coefficients[(2 * s) * stride], d0 = coefficients[(2 * s + 1) * stride];
            double z1 = coefficients[(2 * s + 2) * stride], d1 = coefficients[(2 * s + 3) * stride];
            return k == 0 ? z0 : k == 1 ? z0 + d0 : k == 2 ? z1 - d1 : z1;
        }

        /// <summary>
        /// The normal matrix <c>sum_c w_c w_c^T</c> of <paramref name="samples"/> equally spaced samples,
        /// plus a tiny penalty on the second differences of the Bezier polygon. The penalty vanishes on
        /// straight lines (they stay exact) and only decides what the samples leave open: spans with
        /// fewer samples than coefficients. Its weight is <see cref="SmoothingWeight"/> of the data's trace.
        /// </summary>
        public BandedCholesky NormalMatrix(int samples)
        {
            var a = new BandedCholesky(Count, Bandwidth);
            Span<double> w = stackalloc double[4];
            double trace = 0;
            for (int c = 0; c < samples; c++)
            {
                int s = Weights(c, samples, w);
                for (int p = 0; p < 4; p++)
                {
                    trace += w[p] * w[p];
                    for (int q = p; q < 4; q++) a.Add(2 * s + p, 2 * s + q, w[p] * w[q]);
                }
            }
            // Second differences at the polygon's inner points 3s + 1 and 3s + 2 (at knots they are 0 for
            // a C1 polygon): -z_s - 2 d_s + z_{s+1} - d_{s+1} and z_s + d_s - z_{s+1} + 2 d_{s+1}.
            Span<double> r1 = stackalloc double[] { -1, -2, 1, -1 };
            Span<double> r2 = stackalloc double[] { 1, 1, -1, 2 };
            double penaltyTrace = Spans * (1 + 4 + 1 + 1 + 1 + 1 + 1 + 4);
            double lambda = SmoothingWeight * trace / penaltyTrace;
            for (int s = 0; s < Spans; s++)
                for (int p = 0; p < 4; p++)
                    for (int q = p; q < 4; q++)
                        a.Add(2 * s + p, 2 * s + q, lambda * (r1[p] * r1[q] + r2[p] * r2[q]));
            return a;
        }

        /// <summary>Relative weight of the second-difference penalty (see <see cref="NormalMatrix"/>).</summary>
        public const double SmoothingWeight = 1e-6;
    }
}
