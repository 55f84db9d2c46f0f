using System;

namespace GregoryTerrain
{
    /// <summary>
    /// A C1 bicubic height field on a uniform P x Q grid of the unit square: the tensor product of
    /// two <see cref="C1SplineBasis"/>, coefficients <c>C[ky * Nx + kx]</c> (Ny = 2 (Q + 1) rows,
    /// Nx = 2 (P + 1) columns). Its Bezier net of (3P + 1) x (3Q + 1) heights is the control net of
    /// the Gregory grid <see cref="ToPatchGrid"/> builds, whose interior pairs coincide.
    /// </summary>
    internal sealed class SplineSurface
    {
        public C1SplineBasis X { get; }
        public C1SplineBasis Y { get; }
        /// <summary>Row-major Ny x Nx coefficients, in height units.</summary>
        public double[] Coefficients { get; }

        public SplineSurface(C1SplineBasis x, C1SplineBasis y, double[] coefficients)
        {
            if (coefficients == null) throw new ArgumentNullException(nameof(coefficients));
            if (coefficients.Length != x.Count * y.Count)
                throw new ArgumentException($"coefficients.Length = {coefficients.Length}, need {y.Count} x {x.Count}.", nameof(coefficients));
            X = x;
            Y = y;
            Coefficients = coefficients;
        }

        /// <summary>
        /// The (3P + 1) x (3Q + 1) Bezier heights, row-major (row = index along y): x first per
        /// coefficient row, then y per column, so a point shared by two patches is one number.
        /// </summary>
        public double[] BezierNet()
        {
            int nx = X.Count, ny = Y.Count, bx = 3 * X.Spans + 1, by = 3 * Y.Spans + 1;
            var rows = new double[ny * bx];
            for (int ky = 0; ky < ny; ky++)
            {
                ReadOnlySpan<double> c = new ReadOnlySpan<double>(Coefficients, ky * nx, nx);
                for (int a = 0; a < bx; a++)
                    rows[ky * bx + a] = C1SplineBasis.BezierPoint(c, Math.Min(a / 3, X.Spans - 1), a - 3 * Math.Min(a / 3, X.Spans - 1));
            }
            var net = new double[by * bx];
            for (int b = 0; b < by; b++)
            {
                int s = Math.Min(b / 3, Y.Spans - 1), k = b - 3 * s;
                for (int a = 0; a < bx; a++)
                    net[b * bx + a] = C1SplineBasis.BezierPoint(new ReadOnlySpan<double>(rows, a, rows.Length - a), s, k, bx);
            }
            return net;
        }

        /// <summary>The P x Q Gregory grid on uniform lines: x, y linear in u, v, z from <see cref="BezierNet"/>.</summary>
        public PatchGrid ToPatchGrid()
        {
            int P = X.Spans, Q = Y.Spans, bx = 3 * P + 1;
            double[] net = BezierNet();
            PatchGrid grid = PatchGrid.CreateFlat(P, Q);
            for (int j = 0; j < Q; j++)
                for (int i = 0; i < P; i++)
                {
                    GregoryPatch p = grid.Patch(i, j);
                    for (int a = 0; a < 4; a++)
                        for (int b = 0; b < 4; b++)
                        {
                            int slot = GregoryPatch.Slot(a, b);
                            p[slot] = new Double3(p[slot].x, p[slot].y, net[(3 * j + b) * bx + 3 * i + a]);
                        }
                    PatchGrid.SetSecondPointsToFirst(p);
                }
            return grid;
        }
    }
}
