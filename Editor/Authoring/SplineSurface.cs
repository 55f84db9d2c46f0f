using System;
using System.Threading;

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
        /// The least-squares C1 spline through a W x H heightmap (sample (c, r) at
        /// <c>(c/(W-1), r/(H-1))</c>), inputs already checked. Gridded samples and a tensor-product
        /// basis make the normal equations separable, <c>G_y C G_x = S_y^T Z S_x</c>: one pass over the
        /// samples (4 multiply-adds each) builds the right-hand side, then two band solves (bandwidth
        /// 3) per axis. Time O(W H + P Q), memory O(P Q). <see cref="HeightmapFitter"/> starts its
        /// Gregory-net fit from it.
        /// </summary>
        public static SplineSurface Fit(double[] heights, int width, int height, int columns, int rows,
            IProgress<float> progress, CancellationToken ct, float progressEnd = 1f)
        {
            var bx = new C1SplineBasis(columns);
            var by = new C1SplineBasis(rows);
            int nx = bx.Count, ny = by.Count;
            var xSpan = new int[width];
            var xw = new double[4 * width];
            for (int c = 0; c < width; c++) xSpan[c] = bx.Weights(c, width, new Span<double>(xw, 4 * c, 4));
            // Right-hand side V = S_y^T Z S_x (ny x nx), one row of samples at a time.
            var v = new double[ny * nx];
            var u = new double[nx];
            Span<double> wy = stackalloc double[4];
            for (int r = 0; r < height; r++)
            {
                if ((r & 63) == 0)
                {
                    ct.ThrowIfCancellationRequested();
                    progress?.Report(progressEnd * r / height);
                }
                Array.Clear(u, 0, nx);
                int row = r * width;
                for (int c = 0; c < width; c++)
                {
                    double z = heights[row + c];
                    int o = 2 * xSpan[c], w = 4 * c;
                    u[o] += xw[w] * z;
                    u[o + 1] += xw[w + 1] * z;
                    u[o + 2] += xw[w + 2] * z;
                    u[o + 3] += xw[w + 3] * z;
                }
                int sy = by.Weights(r, height, wy);
                for (int p = 0; p < 4; p++)
                {
                    double f = wy[p];
                    int dst = (2 * sy + p) * nx;
                    for (int k = 0; k < nx; k++) v[dst + k] += f * u[k];
                }
            }
            ct.ThrowIfCancellationRequested();
            progress?.Report(progressEnd);
            return Solve(bx, by, v, width, height);
        }

        /// <summary>
        /// The least-squares spline from its right-hand side <c>V = S_y^T Z S_x</c> (Ny x Nx,
        /// overwritten): <c>C = G_y^-1 V G_x^-1</c>, the y solve on whole rows, then the x solve row
        /// by row. <see cref="GregoryNet.SplineRightHandSide"/> gets V from the Gregory fit's own pass.
        /// </summary>
        public static SplineSurface Solve(C1SplineBasis bx, C1SplineBasis by, double[] v, int width, int height) =>
            Solve(bx, by, v, by.NormalMatrix(height), bx.NormalMatrix(width));

        /// <summary><see cref="Solve(C1SplineBasis, C1SplineBasis, double[], int, int)"/> with the two normal matrices given (factored on first use, so they can be reused).</summary>
        public static SplineSurface Solve(C1SplineBasis bx, C1SplineBasis by, double[] v, BandedCholesky gy, BandedCholesky gx)
        {
            SolveInPlace(bx.Count, by.Count, v, gy, gx);
            return new SplineSurface(bx, by, v);
        }

        /// <summary>V to G_y^-1 V G_x^-1 in place (Ny x Nx, row-major).</summary>
        public static void SolveInPlace(int nx, int ny, double[] v, BandedCholesky gy, BandedCholesky gx)
        {
            gy.SolveRows(v, nx);
            for (int ky = 0; ky < ny; ky++) gx.Solve(new Span<double>(v, ky * nx, nx));
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
