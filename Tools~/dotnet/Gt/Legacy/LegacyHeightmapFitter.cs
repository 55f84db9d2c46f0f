// The fitter shipped before issue 27 (git show 5bbbfe0:Runtime/Core/Grid/HeightmapFitter.cs), kept
// only so gt fit-bench can put it side by side with the least-squares fit. Not shipped.
using System;
using System.Globalization;
using System.Threading;

namespace GregoryTerrain.Rig.Legacy
{
    /// <summary>What <see cref="HeightmapFitter.Fit"/> returns: the G1 grid and how well it reproduces the samples.</summary>
    internal sealed class LegacyHeightmapFit
    {
        public PatchGrid Grid { get; }
        /// <summary>Largest |surface height - sample| over all samples, in terrain units.</summary>
        public double MaxError { get; }
        /// <summary>Root mean square of (surface height - sample) over all samples.</summary>
        public double RmsError { get; }

        public LegacyHeightmapFit(PatchGrid grid, double maxError, double rmsError)
        {
            Grid = grid;
            MaxError = maxError;
            RmsError = rmsError;
        }
    }

    /// <summary>
    /// Builds an n x m G1 grid of Gregory patches from a height array (W x H doubles, row-major,
    /// sample (c, r) at <c>(c/(W-1), r/(H-1))</c>, heights in terrain units):
    /// <list type="number">
    /// <item>uniform grid lines; heights and gradients at the grid vertices from a C1 bicubic
    /// interpolant of the samples (<see cref="LegacyHeightmapInterpolant"/>);</item>
    /// <item>each patch's x, y are linear in u, v (control points on thirds of the region), so the
    /// surface is a height field over the grid and a sample's (u, v) is exact;</item>
    /// <item>boundary curves: cubic Hermite from the vertex heights and slopes (Bezier points at
    /// <c>z +- (width/3) slope</c>);</item>
    /// <item>interior points: along each edge, the cross-boundary slope is the cubic that takes the
    /// interpolant's slope at the edge's vertices and at t = 1/3, 2/3;</item>
    /// <item><see cref="G1Builder.MakeG1"/> then makes every shared edge exactly G1 (with linear x, y
    /// it finds k = -width ratio, h = 0, constant k, and keeps these cubic slopes).</item>
    /// </list>
    /// </summary>
    internal static class LegacyHeightmapFitter
    {
        /// <summary>
        /// Fits the grid; reports progress in [0, 1] and honours cancellation (throws
        /// OperationCanceledException and returns nothing half-built).
        /// </summary>
        public static LegacyHeightmapFit Fit(double[] heights, int width, int height, int columns, int rows,
            IProgress<float> progress = null, CancellationToken cancellationToken = default)
        {
            CheckHeights(heights, width, height);
            PatchGrid.CheckShape(columns, rows);
            var interp = new LegacyHeightmapInterpolant(heights, width, height);
            double[] xl = PatchGrid.UniformLines(columns), yl = PatchGrid.UniformLines(rows);
            PatchGrid grid = PatchGrid.CreateFlat(columns, rows, xl, yl);

            // 1. Vertex heights and gradients.
            var vz = new double[columns + 1, rows + 1];
            var vzx = new double[columns + 1, rows + 1];
            var vzy = new double[columns + 1, rows + 1];
            for (int j = 0; j <= rows; j++)
            {
                cancellationToken.ThrowIfCancellationRequested();
                for (int i = 0; i <= columns; i++)
                    interp.Sample(xl[i], yl[j], out vz[i, j], out vzx[i, j], out vzy[i, j]);
            }
            progress?.Report(0.1f);

            // 2. Boundary curves and interior points, patch by patch.
            for (int j = 0; j < rows; j++)
            {
                cancellationToken.ThrowIfCancellationRequested();
                for (int i = 0; i < columns; i++)
                    BuildPatch(grid, i, j, vz, vzx, vzy, interp);
                progress?.Report(0.1f + 0.5f * (j + 1) / rows);
            }

            // 3. Exact G1 across every shared edge.
            cancellationToken.ThrowIfCancellationRequested();
            G1Builder.MakeG1(grid);
            progress?.Report(0.7f);

            // 4. Fit error against every sample.
            double max = 0, sum2 = 0;
            for (int r = 0; r < height; r++)
            {
                cancellationToken.ThrowIfCancellationRequested();
                double y = (double)r / (height - 1);
                for (int c = 0; c < width; c++)
                {
                    double x = (double)c / (width - 1);
                    int p = grid.FindPatch(x, y);
                    Region reg = grid.RegionOf(p);
                    double u = (x - reg.a) / reg.Width, v = (y - reg.b) / reg.Height;
                    double err = GregoryEval.Position(grid.Patches[p].Points, u, v).z - heights[r * width + c];
                    max = Math.Max(max, Math.Abs(err));
                    sum2 += err * err;
                }
                if ((r & 15) == 15 || r == height - 1) progress?.Report(0.7f + 0.3f * (r + 1) / height);
            }
            return new LegacyHeightmapFit(grid, max, Math.Sqrt(sum2 / ((double)width * height)));
        }

        static void BuildPatch(PatchGrid grid, int i, int j, double[,] vz, double[,] vzx, double[,] vzy, LegacyHeightmapInterpolant interp)
        {
            GregoryPatch p = grid.Patch(i, j);
            double x0 = grid.XLines[i], x1 = grid.XLines[i + 1], y0 = grid.YLines[j], y1 = grid.YLines[j + 1];
            double wx = x1 - x0, wy = y1 - y0;
            // Boundary z: the Hermite-Bezier points of each edge. Each value depends only on the edge's
            // own vertices and lines, so both neighbours compute identical bits.
            for (int k = 0; k < 4; k++)
            {
                SetZ(p, GregoryPatch.Slot(k, 0), HermiteZ(vz[i, j], vzx[i, j], vz[i + 1, j], vzx[i + 1, j], wx, k));
                SetZ(p, GregoryPatch.Slot(k, 3), HermiteZ(vz[i, j + 1], vzx[i, j + 1], vz[i + 1, j + 1], vzx[i + 1, j + 1], wx, k));
                SetZ(p, GregoryPatch.Slot(0, k), HermiteZ(vz[i, j], vzy[i, j], vz[i, j + 1], vzy[i, j + 1], wy, k));
                SetZ(p, GregoryPatch.Slot(3, k), HermiteZ(vz[i + 1, j], vzy[i + 1, j], vz[i + 1, j + 1], vzy[i + 1, j + 1], wy, k));
            }
            // Interior: cubic cross-boundary slope per edge. Inwards is +x on u = 0, -x on u = 1, etc.
            double ya = PatchGrid.Third(y0, y1, 1), yb = PatchGrid.Third(y0, y1, 2);
            double xa = PatchGrid.Third(x0, x1, 1), xb = PatchGrid.Third(x0, x1, 2);
            SetCross(p, PatchSide.U0, +wx / 3, vzx[i, j], SlopeX(interp, x0, ya), SlopeX(interp, x0, yb), vzx[i, j + 1]);
            SetCross(p, PatchSide.U1, -wx / 3, vzx[i + 1, j], SlopeX(interp, x1, ya), SlopeX(interp, x1, yb), vzx[i + 1, j + 1]);
            SetCross(p, PatchSide.V0, +wy / 3, vzy[i, j], SlopeY(interp, xa, y0), SlopeY(interp, xb, y0), vzy[i + 1, j]);
            SetCross(p, PatchSide.V1, -wy / 3, vzy[i, j + 1], SlopeY(interp, xa, y1), SlopeY(interp, xb, y1), vzy[i + 1, j + 1]);
        }

        static double SlopeX(LegacyHeightmapInterpolant f, double x, double y) { f.Sample(x, y, out _, out double d, out _); return d; }
        static double SlopeY(LegacyHeightmapInterpolant f, double x, double y) { f.Sample(x, y, out _, out _, out double d); return d; }

        static void SetZ(GregoryPatch p, int slot, double z) => p[slot] = new Double3(p[slot].x, p[slot].y, z);

        /// <summary>Bezier point k of the cubic Hermite curve with end heights za, zb and slopes sa, sb over a span of width w.</summary>
        static double HermiteZ(double za, double sa, double zb, double sb, double w, int k) =>
            k == 0 ? za : k == 1 ? za + w / 3 * sa : k == 2 ? zb - w / 3 * sb : zb;

        /// <summary>
        /// Sets the z of the edge's inner points k = 1, 2 so that the cross-boundary slope along the
        /// edge is the cubic with Bernstein coefficients g0..g3 that equals the slopes s0, s1, s2, s3
        /// at t = 0, 1/3, 2/3, 1 (g0 = s0, g3 = s3; g1, g2 from the 2x2 system at 1/3 and 2/3, whose
        /// Bernstein values are (8, 12, 6, 1)/27 and (1, 6, 12, 8)/27). step = signed width / 3.
        /// </summary>
        static void SetCross(GregoryPatch p, PatchSide side, double step, double s0, double s1, double s2, double s3)
        {
            double r1 = 27 * s1 - 8 * s0 - s3, r2 = 27 * s2 - s0 - 8 * s3;
            double g1 = (2 * r1 - r2) / 18, g2 = (2 * r2 - r1) / 18;
            SetZ(p, PatchEdge.InnerSlot(side, 1), p[PatchEdge.EdgeSlot(side, 1)].z + step * g1);
            SetZ(p, PatchEdge.InnerSlot(side, 2), p[PatchEdge.EdgeSlot(side, 2)].z + step * g2);
        }

        /// <summary>Throws unless heights is W x H (W, H >= 2) and every sample is finite.</summary>
        public static void CheckHeights(double[] heights, int width, int height)
        {
            if (heights == null) throw new ArgumentNullException(nameof(heights));
            if (width < 2) throw new ArgumentException($"width = {width}, need at least 2 samples.", nameof(width));
            if (height < 2) throw new ArgumentException($"height = {height}, need at least 2 samples.", nameof(height));
            if ((long)width * height != heights.Length)
                throw new ArgumentException($"heights.Length = {heights.Length}, need width * height = {(long)width * height}.", nameof(heights));
            for (int k = 0; k < heights.Length; k++)
                if (!GMath.isfinite(heights[k]))
                    throw new ArgumentException(string.Format(CultureInfo.InvariantCulture,
                        "heights[{0}] (column {1}, row {2}) = {3} is not finite.", k, k % width, k / width, heights[k]), nameof(heights));
        }
    }
}
