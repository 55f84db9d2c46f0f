using System;
using System.Globalization;
using System.Threading;

namespace GregoryTerrain
{
    /// <summary>What <see cref="PatchRegionFit.Fit"/> returns: the edit and how well the edited region reproduces the heightmap.</summary>
    internal sealed class RegionFitResult
    {
        /// <summary>The changed patches (the region and, along its border, its neighbours' interior points at most).</summary>
        public PatchEdit Edit { get; }
        /// <summary>Largest |surface - heightmap| over the region's samples after the edit, in the heights' units.</summary>
        public double MaxError { get; }
        /// <summary>Root mean square of the same.</summary>
        public double RmsError { get; }
        /// <summary>Samples the region was fitted to (per row, rows).</summary>
        public int SampleWidth { get; }
        public int SampleHeight { get; }

        public RegionFitResult(PatchEdit edit, double maxError, double rmsError, int sampleWidth, int sampleHeight)
        {
            Edit = edit ?? throw new ArgumentNullException(nameof(edit));
            MaxError = maxError; RmsError = rmsError; SampleWidth = sampleWidth; SampleHeight = sampleHeight;
        }
    }

    /// <summary>
    /// Refits a rectangle of patches to a new heightmap and leaves the rest of the grid alone:
    /// <list type="number">
    /// <item>the heightmap (W x H samples over the whole unit square, the fitter's convention) is
    /// resampled bilinearly over the region, at least as densely as given and at least 4 samples a
    /// patch, mapping the region's grid lines onto the fitter's uniform ones;</item>
    /// <item><see cref="HeightmapFitter.Fit"/> (the fitter's public entry) fits the region's patch
    /// count to it;</item>
    /// <item>the fitted heights replace the region's net nodes except those on its border with
    /// untouched patches, which keep their bits (the surface stays continuous); the points next to
    /// that border continue the neighbours' slope (corner lines, NetEdit.RepairCorners) and the
    /// border edges are rejoined G1 with the neighbour's side kept. A region on the grid's own border
    /// takes the fit there too.</item>
    /// </list>
    /// So the region's outer ring of net nodes is the old surface's: a new heightmap that differs from
    /// the old one at the border blends into it within the border patches. x, y of the control points
    /// are kept; heights only change.
    /// </summary>
    internal static class PatchRegionFit
    {
        /// <summary>
        /// The edit refitting <paramref name="region"/> of <paramref name="grid"/> to the heightmap, with
        /// progress in [0, 1] and cancellation (OperationCanceledException). Throws ArgumentException
        /// naming the field and value on bad input. Never changes the grid: apply the edit.
        /// </summary>
        public static RegionFitResult Fit(PatchGrid grid, PatchRect region, double[] heights, int width, int height,
            IProgress<float> progress = null, CancellationToken cancellationToken = default)
        {
            if (grid == null) throw new ArgumentNullException(nameof(grid));
            region.Check(grid.Columns, grid.Rows, nameof(region));
            HeightmapFitter.CheckHeights(heights, width, height);
            int n = grid.Columns, m = grid.Rows, cols = region.Columns, rows = region.Rows;
            double[] xl = Lines(grid.XLines, region.I0, cols), yl = Lines(grid.YLines, region.J0, rows);
            int sw = SampleCount(width, xl, cols), sh = SampleCount(height, yl, rows);
            var sub = new double[(long)sw * sh > int.MaxValue ? throw new ArgumentException(F("the region needs {0} x {1} samples, too many for one array.", sw, sh), nameof(region)) : sw * sh];
            for (int r = 0; r < sh; r++)
            {
                if ((r & 63) == 0) cancellationToken.ThrowIfCancellationRequested();
                double y = Map(yl, (double)r / (sh - 1));
                for (int c = 0; c < sw; c++) sub[r * sw + c] = Bilinear(heights, width, height, Map(xl, (double)c / (sw - 1)), y);
            }
            progress?.Report(0.05f);
            var inner = progress == null ? null : new Progress(f => progress.Report(0.05f + 0.8f * f));
            HeightmapFit fit = HeightmapFitter.Fit(sub, sw, sh, cols, rows, inner, cancellationToken);
            cancellationToken.ThrowIfCancellationRequested();

            // The fitted net into the region, its border with untouched patches kept.
            var edit = new NetEdit(grid, new PatchRect(Math.Max(0, region.I0 - 1), Math.Max(0, region.J0 - 1),
                Math.Min(n - 1, region.I1 + 1), Math.Min(m - 1, region.J1 + 1)));
            int a0 = 3 * region.I0, a1 = 3 * (region.I1 + 1), b0 = 3 * region.J0, b1 = 3 * (region.J1 + 1);
            int ea0 = region.I0 > 0 ? a0 + 1 : a0, ea1 = region.I1 + 1 < n ? a1 - 1 : a1;
            int eb0 = region.J0 > 0 ? b0 + 1 : b0, eb1 = region.J1 + 1 < m ? b1 - 1 : b1;
            bool Editable(int a, int b) => a >= ea0 && a <= ea1 && b >= eb0 && b <= eb1;
            for (int b = eb0; b <= eb1; b++)
                for (int a = ea0; a <= ea1; a++)
                {
                    int la = a - a0, lb = b - b0, fi = Math.Min(la / 3, cols - 1), fj = Math.Min(lb / 3, rows - 1);
                    edit.SetNodeZ(a, b, fit.Grid.Patch(fi, fj)[GregoryPatch.Slot(la - 3 * fi, lb - 3 * fj)].z);
                }
            // The pairs' second points: the fit's patches are Bezier patches (pairs coincide).
            for (int j = region.J0; j <= region.J1; j++)
                for (int i = region.I0; i <= region.I1; i++)
                    foreach (int first in FirstSlots)
                        edit.SetZ(i, j, GregoryPatch.SecondOfPair(first), edit.Patch(i, j)[first].z);
            edit.RepairCorners(region.I0, region.J0, region.I1 + 1, region.J1 + 1, Editable);
            edit.JoinEdges((i, j, vertical) =>
            {
                bool lowIn = region.Contains(i, j), highIn = vertical ? region.Contains(i + 1, j) : region.Contains(i, j + 1);
                return lowIn && highIn ? EdgeRule.Symmetric : lowIn ? EdgeRule.KeepHigh : EdgeRule.KeepLow;
            });
            PatchEdit result = edit.ToEdit();
            progress?.Report(0.9f);

            // The error after the edit, at the samples fitted (x, y linear in u, v within a patch).
            double max = 0, sum2 = 0;
            var byIndex = new GregoryPatch[n * m];
            for (int k = 0; k < result.Patches.Length; k++) byIndex[result.Patches[k]] = result.Values[k];
            for (int r = 0; r < sh; r++)
            {
                if ((r & 63) == 0) cancellationToken.ThrowIfCancellationRequested();
                double fy = (double)r / (sh - 1);
                int j = Math.Min((int)(fy * rows), rows - 1);
                double v = Math.Min(1, Math.Max(0, fy * rows - j));
                for (int c = 0; c < sw; c++)
                {
                    double fx = (double)c / (sw - 1);
                    int i = Math.Min((int)(fx * cols), cols - 1);
                    double u = Math.Min(1, Math.Max(0, fx * cols - i));
                    int p = grid.Index(region.I0 + i, region.J0 + j);
                    GregoryPatch patch = byIndex[p] ?? grid.Patches[p];
                    double e = Math.Abs(GregoryEval.Position(patch.Points, u, v).z - sub[r * sw + c]);
                    if (e > max) max = e;
                    sum2 += e * e;
                }
            }
            progress?.Report(1f);
            return new RegionFitResult(result, max, Math.Sqrt(sum2 / ((double)sw * sh)), sw, sh);
        }

        static readonly int[] FirstSlots = { GregoryPatch.P110, GregoryPatch.P120, GregoryPatch.P210, GregoryPatch.P220 };

        /// <summary>The region's count + 1 grid lines starting at line <paramref name="start"/>.</summary>
        static double[] Lines(double[] lines, int start, int count)
        {
            var l = new double[count + 1];
            Array.Copy(lines, start, l, 0, count + 1);
            return l;
        }

        /// <summary>Samples along one side: as dense as the heightmap over the region, at least 4 a patch (plus one).</summary>
        static int SampleCount(int samples, double[] lines, int patches)
        {
            double span = lines[patches] - lines[0];
            long dense = (long)Math.Ceiling((samples - 1) * span) + 1;
            return (int)Math.Min(int.MaxValue / 2, Math.Max(4L * patches + 1, dense));
        }

        /// <summary>Fitter parameter f in [0, 1] to the terrain coordinate: patch k of the fit spans lines[k]..lines[k+1].</summary>
        static double Map(double[] lines, double f)
        {
            int count = lines.Length - 1;
            double s = f * count;
            int k = Math.Min((int)s, count - 1);
            return lines[k] + (lines[k + 1] - lines[k]) * (s - k);
        }

        /// <summary>The heightmap at (x, y) of the unit square, bilinear between samples (c, r) at (c/(W-1), r/(H-1)).</summary>
        static double Bilinear(double[] h, int w, int hh, double x, double y)
        {
            double fx = Math.Min(Math.Max(x, 0), 1) * (w - 1), fy = Math.Min(Math.Max(y, 0), 1) * (hh - 1);
            int c = Math.Min((int)fx, w - 2), r = Math.Min((int)fy, hh - 2);
            double tx = fx - c, ty = fy - r;
            return (1 - ty) * ((1 - tx) * h[r * w + c] + tx * h[r * w + c + 1]) + ty * ((1 - tx) * h[(r + 1) * w + c] + tx * h[(r + 1) * w + c + 1]);
        }

        /// <summary>A progress sink on the calling thread (System.Progress posts to a synchronization context, which would reorder reports).</summary>
        sealed class Progress : IProgress<float>
        {
            readonly Action<float> _report;
            public Progress(Action<float> report) => _report = report;
            public void Report(float value) => _report(value);
        }

        static string F(string format, params object[] args) => string.Format(CultureInfo.InvariantCulture, format, args);
    }
}
