using System;
using System.Globalization;

namespace GregoryTerrain
{
    internal static partial class G1Builder
    {
        /// <summary>
        /// Makes every shared edge of <paramref name="grid"/> G1 by setting the interior points on both
        /// sides (eq. 7-9, see the class comment for the choices). The grid must be valid
        /// (<see cref="PatchGrid.Validate"/>) and its corners consistent: at each end of each shared
        /// edge, B must lie in the plane of A and C to <paramref name="relativeTolerance"/> times
        /// <c>|B|</c>. The lower-index patch (left, below) is the A side. Boundary points are never
        /// changed; all scalars are solved and checked before any point is written, so a throw leaves
        /// the grid as it was. Grid-border edges are left alone.
        /// </summary>
        public static void MakeG1(PatchGrid grid, double relativeTolerance = 1e-9)
        {
            if (grid == null) throw new ArgumentNullException(nameof(grid));
            if (!(relativeTolerance >= 0))
                throw new ArgumentException($"relativeTolerance = {relativeTolerance} must be >= 0.", nameof(relativeTolerance));
            grid.Validate();

            int n = grid.Columns, m = grid.Rows;
            // Shared edges: vertical ones (i, j)|(i+1, j), then horizontal ones (i, j)|(i, j+1).
            var jobs = new EdgeJob[(n - 1) * m + n * (m - 1)];
            int count = 0;
            for (int j = 0; j < m; j++)
                for (int i = 0; i + 1 < n; i++)
                    jobs[count++] = Prepare(grid.Patch(i, j), PatchSide.U1, grid.Patch(i + 1, j), PatchSide.U0, Where(i, j, i + 1, j), relativeTolerance, false);
            for (int j = 0; j + 1 < m; j++)
                for (int i = 0; i < n; i++)
                    jobs[count++] = Prepare(grid.Patch(i, j), PatchSide.V1, grid.Patch(i, j + 1), PatchSide.V0, Where(i, j, i, j + 1), relativeTolerance, false);
            for (int e = 0; e < count; e++) jobs[e].Apply();
        }

        static string Where(int i0, int j0, int i1, int j1) =>
            string.Format(CultureInfo.InvariantCulture, "edge between patch ({0}, {1}) and patch ({2}, {3})", i0, j0, i1, j1);

        /// <summary>The solved scalars and the new interior points of one shared edge, not yet written.</summary>
        struct EdgeJob
        {
            public GregoryPatch PatchA, PatchB;
            public PatchSide SideA, SideB;
            public Double3 A1, A2, B1, B2;

            public void Apply()
            {
                Double3 e1 = PatchA[PatchEdge.EdgeSlot(SideA, 1)], e2 = PatchA[PatchEdge.EdgeSlot(SideA, 2)];
                PatchA[PatchEdge.InnerSlot(SideA, 1)] = e1 + A1;
                PatchA[PatchEdge.InnerSlot(SideA, 2)] = e2 + A2;
                PatchB[PatchEdge.InnerSlot(SideB, 1)] = e1 + B1;
                PatchB[PatchEdge.InnerSlot(SideB, 2)] = e2 + B2;
            }
        }

        static Double3 Cross(GregoryPatch p, PatchSide side, int k) => p[PatchEdge.InnerSlot(side, k)] - p[PatchEdge.EdgeSlot(side, k)];

        /// <summary>
        /// One shared edge's new interior points. The A side's inner vectors are kept when k is
        /// constant and B's derived from them; with <paramref name="symmetric"/> both sides move
        /// instead, each by the least change that meets <c>B_k = k A_k + r_k</c> (k = 1, 2): with
        /// e the residual, <c>A_k += k e / (1 + k^2)</c>, <c>B_k -= e / (1 + k^2)</c>. A brush uses it so
        /// a stroke on either side of an edge shapes it alike. A non-constant k falls back to eq. 7-9.
        /// </summary>
        static EdgeJob Prepare(GregoryPatch a, PatchSide sideA, GregoryPatch b, PatchSide sideB, string where, double tol, bool symmetric)
        {
            Double3 e0 = a[PatchEdge.EdgeSlot(sideA, 0)], e1 = a[PatchEdge.EdgeSlot(sideA, 1)];
            Double3 e2 = a[PatchEdge.EdgeSlot(sideA, 2)], e3 = a[PatchEdge.EdgeSlot(sideA, 3)];
            Double3 c0 = e1 - e0, c1 = e2 - e1, c2 = e3 - e2;
            Double3 a0 = Cross(a, sideA, 0), a3 = Cross(a, sideA, 3);
            Double3 b0 = Cross(b, sideB, 0), b3 = Cross(b, sideB, 3);
            double k0, h0, k1, h1;
            try
            {
                SolveCornerScalars(a0, b0, c0, out k0, out h0, out double r0);
                CheckResidual(r0, b0, tol, where, "start (t = 0)");
                SolveCornerScalars(a3, b3, c2, out k1, out h1, out double r1);
                CheckResidual(r1, b3, tol, where, "end (t = 1)");
            }
            catch (ArgumentException ex) when (!ex.Message.StartsWith("grid: ", StringComparison.Ordinal))
            {
                throw new ArgumentException("grid: " + where + ": " + ex.Message, "grid", ex);
            }

            Double3 a1, a2;
            if (Math.Abs(k1 - k0) <= ConstantKTolerance * Math.Max(Math.Abs(k0), Math.Abs(k1)))
            {
                // k constant: k A(t) is cubic for any A, keep the neighbour's own inner vectors.
                a1 = Cross(a, sideA, 1);
                a2 = Cross(a, sideA, 2);
            }
            else
            {
                LinearCrossBoundary(a0, a3, out a1, out a2);
            }
            CrossBoundary(a0, a1, a2, a3, c0, c1, c2, k0, k1, h0, h1, out _, out Double3 nb1, out Double3 nb2, out _);
            if (symmetric && Math.Abs(k1 - k0) <= ConstantKTolerance * Math.Max(Math.Abs(k0), Math.Abs(k1)))
            {
                Double3 r1 = Cross(b, sideB, 1) - nb1, r2 = Cross(b, sideB, 2) - nb2;
                double s1 = 1.0 / (1.0 + k0 * k0), s2 = 1.0 / (1.0 + k1 * k1);
                a1 = a1 + (k0 * s1) * r1;
                a2 = a2 + (k1 * s2) * r2;
                // Recomputed from the moved A rather than B + e s: the same formula MakeG1 applies, so
                // the join is exact to the last bit of eq. 8-9 and not to a rounding of the projection.
                CrossBoundary(a0, a1, a2, a3, c0, c1, c2, k0, k1, h0, h1, out _, out nb1, out nb2, out _);
            }
            return new EdgeJob { PatchA = a, PatchB = b, SideA = sideA, SideB = sideB, A1 = a1, A2 = a2, B1 = nb1, B2 = nb2 };
        }

        static void CheckResidual(double residual, Double3 b, double tol, string where, string end)
        {
            if (residual > tol * GMath.length(b))
                throw new ArgumentException(string.Format(CultureInfo.InvariantCulture,
                    "grid: {0}: at its {1} the cross-boundary vector {2} is off the neighbours' tangent plane by {3:R} (more than {4:R} x |B|): corner tangent planes are not consistent.",
                    where, end, b, residual, tol), "grid");
        }
    }
}
