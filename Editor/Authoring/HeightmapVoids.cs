using System;

namespace GregoryTerrain
{
    /// <summary>
    /// Fills voids (NaN samples: no data) of a height array before fitting, so that a void becomes a
    /// smooth surface between its known neighbours instead of a spike. Pull-push: average the known
    /// samples down a pyramid of halved resolutions, then fill each level's voids from the level
    /// above, interpolated bilinearly. Every filled value is a weighted mean of known samples, so it
    /// stays within their range. O(samples) time, about 2.7 doubles a sample of extra memory.
    /// </summary>
    internal static class HeightmapVoids
    {
        /// <summary>
        /// Replaces every NaN of the W x H array in place and returns how many there were. Throws if
        /// every sample is a void (nothing to fill from) or a sample is infinite.
        /// </summary>
        public static int Fill(double[] heights, int width, int height)
        {
            if (heights == null) throw new ArgumentNullException(nameof(heights));
            if (width < 1 || height < 1 || (long)width * height != heights.Length)
                throw new ArgumentException($"heights.Length = {heights.Length}, need width * height = {(long)width * height} (width = {width}, height = {height}).", nameof(heights));
            int voids = 0;
            for (int k = 0; k < heights.Length; k++)
            {
                if (double.IsNaN(heights[k])) voids++;
                else if (double.IsInfinity(heights[k]))
                    throw new ArgumentException($"heights[{k}] (column {k % width}, row {k / width}) = {heights[k]} is infinite, not a void (NaN) or a height.", nameof(heights));
            }
            if (voids == 0) return 0;
            if (voids == heights.Length) throw new ArgumentException($"all {voids} samples are voids: nothing to fill them from.", nameof(heights));

            var sums = new double[heights.Length];
            var weights = new double[heights.Length];
            for (int k = 0; k < heights.Length; k++)
                if (!double.IsNaN(heights[k])) { sums[k] = heights[k]; weights[k] = 1; }
            FillLevel(sums, weights, width, height);
            for (int k = 0; k < heights.Length; k++)
                if (double.IsNaN(heights[k])) heights[k] = sums[k] / weights[k];
            return voids;
        }

        /// <summary>
        /// Recursive pull-push on weighted sums: afterwards every cell has weight > 0, and cells that
        /// had weight 0 hold the level above's mean, interpolated.
        /// </summary>
        static void FillLevel(double[] sums, double[] weights, int w, int h)
        {
            bool any = false;
            for (int k = 0; k < weights.Length && !any; k++) any = weights[k] == 0;
            if (!any) return;
            int cw = (w + 1) / 2, ch = (h + 1) / 2;
            var cs = new double[cw * ch];
            var cwt = new double[cw * ch];
            for (int r = 0; r < h; r++)
                for (int c = 0; c < w; c++)
                {
                    int k = r * w + c, ck = (r / 2) * cw + c / 2;
                    // Means, not sums, go up (weights capped at 1), so a half-known cell counts as known.
                    cs[ck] += sums[k] / Math.Max(weights[k], 1e-300) * Math.Min(weights[k], 1);
                    cwt[ck] += Math.Min(weights[k], 1);
                }
            if (cw == w && ch == h)
                throw new InvalidOperationException("pull-push did not shrink: no known sample.");
            FillLevel(cs, cwt, cw, ch);
            for (int r = 0; r < h; r++)
                for (int c = 0; c < w; c++)
                {
                    int k = r * w + c;
                    if (weights[k] > 0) continue;
                    // Bilinear in the coarse level: coarse cell (i, j) has its centre at fine (2i + 0.5, 2j + 0.5).
                    double fx = Math.Max(0, Math.Min(cw - 1, (c - 0.5) / 2)), fy = Math.Max(0, Math.Min(ch - 1, (r - 0.5) / 2));
                    int x0 = (int)fx, y0 = (int)fy, x1 = Math.Min(x0 + 1, cw - 1), y1 = Math.Min(y0 + 1, ch - 1);
                    double tx = fx - x0, ty = fy - y0;
                    double m00 = cs[y0 * cw + x0] / cwt[y0 * cw + x0], m10 = cs[y0 * cw + x1] / cwt[y0 * cw + x1];
                    double m01 = cs[y1 * cw + x0] / cwt[y1 * cw + x0], m11 = cs[y1 * cw + x1] / cwt[y1 * cw + x1];
                    sums[k] = (1 - ty) * ((1 - tx) * m00 + tx * m10) + ty * ((1 - tx) * m01 + tx * m11);
                    weights[k] = 1;
                }
        }
    }
}
