using System;
using System.Globalization;

namespace GregoryTerrain
{
    /// <summary>
    /// Chiyokura-Kimura G1 joins (the paper's eq. 7-9; internals.md, "The Gregory patch"). Along a shared edge with edge vectors
    /// C0, C1, C2 (differences of consecutive boundary points, in the edge's parameter direction), the
    /// neighbour's cross-boundary vectors A0..A3 and this side's B0..B3 (each the difference from an
    /// edge point to the next point inwards), the two patches share a tangent plane all along the
    /// edge when <c>B(t) = k(t) A(t) + h(t) C(t)</c> with k, h linear in t.
    ///
    /// <para><b>Scalar choices.</b> k0, h0 (at t = 0) and k1, h1 (at t = 1) are not free: B0, B3 and
    /// A0, A3 are fixed by the boundary curves, so they are the least-squares solution of
    /// <c>B0 = k0 A0 + h0 C0</c> (and <c>B3 = k1 A3 + h1 C2</c>), which is exact when the corner's
    /// tangent plane is consistent (A0, B0, C0 coplanar); the residual is checked. k is negative
    /// (A and B point away from the edge on opposite sides): for a height field on grid lines with
    /// linear x, y it is <c>-width_B / width_A</c> and h = 0, i.e. equal slopes across the edge.</para>
    ///
    /// <para><b>The neighbour's side.</b> Eq. 7-9 assume A linear in t (<c>A1 = (2 A0 + A3)/3</c>,
    /// <c>A2 = (A0 + 2 A3)/3</c>) because k(t) A(t) must stay cubic. When k0 = k1 (to
    /// <see cref="ConstantKTolerance"/>) the product is cubic for any A, so <see cref="MakeG1"/> keeps
    /// the neighbour's own A1, A2 (a fitter's data) and eq. 8-9 still give an exact G1 join; otherwise
    /// it rewrites the neighbour's interior points to the linear A.</para>
    /// </summary>
    internal static partial class G1Builder
    {
        /// <summary>Relative difference of k0 and k1 below which k is treated as constant.</summary>
        public const double ConstantKTolerance = 1e-9;

        /// <summary>Eq. 7: the linear cross-boundary field's inner vectors A1 = (2 A0 + A3)/3, A2 = (A0 + 2 A3)/3.</summary>
        public static void LinearCrossBoundary(Double3 a0, Double3 a3, out Double3 a1, out Double3 a2)
        {
            a1 = (2.0 * a0 + a3) / 3.0;
            a2 = (a0 + 2.0 * a3) / 3.0;
        }

        /// <summary>Eq. 7-9 with the linear A of eq. 7: B0..B3 from A0, A3, C0..C2 and k0, k1, h0, h1.</summary>
        public static void CrossBoundary(Double3 a0, Double3 a3, Double3 c0, Double3 c1, Double3 c2,
            double k0, double k1, double h0, double h1,
            out Double3 b0, out Double3 b1, out Double3 b2, out Double3 b3)
        {
            LinearCrossBoundary(a0, a3, out Double3 a1, out Double3 a2);
            CrossBoundary(a0, a1, a2, a3, c0, c1, c2, k0, k1, h0, h1, out b0, out b1, out b2, out b3);
        }

        /// <summary>
        /// Eq. 8-9 with given A1, A2 (G1 exactly when A1, A2 are eq. 7's, or when k0 = k1):
        /// <c>B0 = k0 A0 + h0 C0</c>, <c>B1 = ((k1-k0) A0 + 3 k0 A1 + 2 h0 C1 + h1 C0)/3</c>,
        /// <c>B2 = (3 k1 A2 - (k1-k0) A3 + h0 C2 + 2 h1 C1)/3</c>, <c>B3 = k1 A3 + h1 C2</c>.
        /// </summary>
        public static void CrossBoundary(Double3 a0, Double3 a1, Double3 a2, Double3 a3, Double3 c0, Double3 c1, Double3 c2,
            double k0, double k1, double h0, double h1,
            out Double3 b0, out Double3 b1, out Double3 b2, out Double3 b3)
        {
            b0 = k0 * a0 + h0 * c0;
            b1 = ((k1 - k0) * a0 + 3.0 * k0 * a1 + 2.0 * h0 * c1 + h1 * c0) / 3.0;
            b2 = (3.0 * k1 * a2 - (k1 - k0) * a3 + h0 * c2 + 2.0 * h1 * c1) / 3.0;
            b3 = k1 * a3 + h1 * c2;
        }

        /// <summary>
        /// Least-squares (k, h) with <c>b ~ k a + h c</c> (2x2 normal equations); <paramref name="residual"/>
        /// is <c>|b - k a - h c|</c>. Throws if a and c are (nearly) parallel or zero.
        /// </summary>
        public static void SolveCornerScalars(Double3 a, Double3 b, Double3 c, out double k, out double h, out double residual)
        {
            double aa = GMath.dot(a, a), ac = GMath.dot(a, c), cc = GMath.dot(c, c);
            double ab = GMath.dot(a, b), cb = GMath.dot(c, b);
            double det = aa * cc - ac * ac;
            // det = |a|^2 |c|^2 sin^2(angle): relative test so the units of a and c do not matter.
            if (!(det > 1e-24 * aa * cc) || aa == 0 || cc == 0)
                throw new ArgumentException(string.Format(CultureInfo.InvariantCulture,
                    "cross-boundary vector a = {0} and edge vector c = {1} are parallel or zero: no tangent plane.", a, c), nameof(a));
            k = (ab * cc - cb * ac) / det;
            h = (cb * aa - ab * ac) / det;
            residual = GMath.length(b - k * a - h * c);
        }
    }
}
