using System;
using System.Globalization;
using System.Threading;

namespace GregoryTerrain
{
    /// <summary>
    /// "Resample grid to N x M": N x M patches fitted (<see cref="HeightmapFitter.Fit"/>) to samples of
    /// the old surface, whose x, y must be linear in u, v per patch (fitted, flat, sculpted and joined grids are).
    /// </summary>
    internal static class ResampleAuthoring
    {
        /// <summary>Samples per patch side of the finer of the two grids: enough for the fitter's 7 unknowns a patch.</summary>
        public const int SamplesPerPatch = 6;
        /// <summary>The most samples a side (16.8 M samples in all).</summary>
        public const int MaxSamples = 4097;

        /// <summary>The fit, its MaxError and RmsError against the old surface (height units); cancelling throws OperationCanceledException.</summary>
        public static HeightmapFit Resample(PatchGrid old, int columns, int rows, IProgress<float> progress = null, CancellationToken cancellationToken = default)
        {
            if (old == null) throw new ArgumentNullException(nameof(old));
            PatchGrid.CheckShape(columns, rows);
            int width = SampleCount(Math.Max(columns, old.Columns)), height = SampleCount(Math.Max(rows, old.Rows));
            double[] heights = Sample(old, width, height, cancellationToken);
            return HeightmapFitter.Fit(heights, width, height, columns, rows, progress, cancellationToken);
        }

        /// <summary>Heights of <paramref name="grid"/> at <c>(c / (W-1), r / (H-1))</c>, row-major, as the fitter reads samples.</summary>
        public static double[] Sample(PatchGrid grid, int width, int height, CancellationToken cancellationToken = default)
        {
            if (width < 2 || height < 2)
                throw new ArgumentException(string.Format(CultureInfo.InvariantCulture, "samples {0} x {1}, need at least 2 x 2.", width, height), nameof(width));
            var z = new double[width * height];
            for (int r = 0; r < height; r++)
            {
                cancellationToken.ThrowIfCancellationRequested();
                double y = r / (double)(height - 1);
                for (int c = 0; c < width; c++) z[r * width + c] = Height(grid, c / (double)(width - 1), y);
            }
            return z;
        }

        /// <summary>The surface's height at (x, y) of the unit square.</summary>
        public static double Height(PatchGrid grid, double x, double y)
        {
            int p = grid.FindPatch(x, y);
            Region region = grid.RegionOf(p);
            return GregoryEval.Position(grid.Patches[p].Points, (x - region.a) / region.Width, (y - region.b) / region.Height).z;
        }

        static int SampleCount(int patches) => Math.Min(MaxSamples, patches * SamplesPerPatch + 1);
    }
}
