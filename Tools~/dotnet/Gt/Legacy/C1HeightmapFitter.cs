// The C1 spline fitter shipped before the Gregory-net fit (git show 6a48267:Runtime/Core/Grid/HeightmapFitter.cs),
// kept only so gt fit-bench can put it side by side with the shipped fit. Not shipped. Its spline
// (SplineSurface.Fit) stays in Core as the shipped fit's starting point; this adds its grid and error pass.
using System;
using System.Threading;

namespace GregoryTerrain.Rig.Legacy
{
    /// <summary>What <see cref="C1HeightmapFitter.Fit"/> returns: the C1 grid and its error.</summary>
    internal sealed class C1HeightmapFit
    {
        public PatchGrid Grid { get; }
        public double MaxError { get; }
        public double RmsError { get; }

        public C1HeightmapFit(PatchGrid grid, double maxError, double rmsError)
        {
            Grid = grid;
            MaxError = maxError;
            RmsError = rmsError;
        }
    }

    /// <summary>Least squares in the C1 bicubic splines on the grid lines; the Bezier net is the grid (pairs coincident).</summary>
    internal static class C1HeightmapFitter
    {
        public static C1HeightmapFit Fit(double[] heights, int width, int height, int columns, int rows)
        {
            HeightmapFitter.CheckInputs(heights, width, height, columns, rows);
            SplineSurface surface = SplineSurface.Fit(heights, width, height, columns, rows, null, CancellationToken.None);
            PatchGrid grid = surface.ToPatchGrid();
            C1SplineBasis bx = surface.X, by = surface.Y;
            int nx = bx.Count;
            double[] v = surface.Coefficients;
            var xSpan = new int[width];
            var xw = new double[4 * width];
            for (int c = 0; c < width; c++) xSpan[c] = bx.Weights(c, width, new Span<double>(xw, 4 * c, 4));
            Span<double> wy = stackalloc double[4];
            var q = new double[nx];
            double max = 0, sum2 = 0;
            for (int r = 0; r < height; r++)
            {
                int sy = by.Weights(r, height, wy);
                for (int k = 0; k < nx; k++)
                    q[k] = wy[0] * v[(2 * sy) * nx + k] + wy[1] * v[(2 * sy + 1) * nx + k]
                         + wy[2] * v[(2 * sy + 2) * nx + k] + wy[3] * v[(2 * sy + 3) * nx + k];
                int row = r * width;
                for (int c = 0; c < width; c++)
                {
                    int o = 2 * xSpan[c], w = 4 * c;
                    double f = xw[w] * q[o] + xw[w + 1] * q[o + 1] + xw[w + 2] * q[o + 2] + xw[w + 3] * q[o + 3];
                    double e = Math.Abs(f - heights[row + c]);
                    if (e > max) max = e;
                    sum2 += e * e;
                }
            }
            return new C1HeightmapFit(grid, max, Math.Sqrt(sum2 / ((double)width * height)));
        }
    }
}
