using System;
using System.Globalization;
using System.IO;
using GregoryTerrain.Rig.Legacy;

namespace GregoryTerrain.Rig
{
    /// <summary>
    /// gt-cli fit-reference --dem FILE.hgt --patches P [--crop N]: could ANY smooth surface with as
    /// many unknowns as the P x P Gregory net reach half the bilinear baseline's RMS on this data?
    /// Prints, for the unknown counts U (the Gregory net's), 9/7 U (the baseline lattice's, about)
    /// and 2 U, 4 U, the RMS of two best approximations with that many unknowns, as ratios to the
    /// bilinear baseline's RMS:
    /// <list type="bullet">
    /// <item>band-limited: the K x K lowest frequencies of the orthonormal DCT-II of the samples
    /// (K^2 = U), whose RMS is exact by Parseval (the least-squares optimum over those cosines);</item>
    /// <item>the least-squares C1 bicubic spline (4 unknowns a vertex) on k x k patches with
    /// 4 (k + 1)^2 closest to U, the best tensor-product cubic with that many coefficients on
    /// uniform knots.</item>
    /// </list>
    /// One tab-separated line per count: label, unknowns, DCT K, DCT RMS, its ratio, spline k, spline
    /// unknowns, spline RMS, its ratio. A rig experiment, not part of the package.
    /// </summary>
    static class FitReferenceCommand
    {
        public static int Run(Args a)
        {
            string dem = a.String("dem");
            int patches = a.Int("patches"), crop = a.Int("crop", 0);
            byte[] bytes = File.ReadAllBytes(dem);
            int w = 0, h = 0;
            RawHeightmap.InferSize(Path.GetFileName(dem), bytes.Length, RawSampleFormat.Int16BigEndian, ref w, ref h);
            double[] z = RawHeightmap.Decode(Path.GetFileName(dem), bytes, w, h, RawSampleFormat.Int16BigEndian, RawHeightmap.SrtmVoid);
            HeightmapVoids.Fill(z, w, h);
            if (crop > 0)
            {
                var c = new double[crop * crop];
                for (int r = 0; r < crop; r++) Array.Copy(z, (long)r * w, c, (long)r * crop, crop);
                z = c; w = h = crop;
            }
            if (!BilinearBaseline.Measure(z, w, h, patches, patches, out double bMax, out double bRms))
                throw new ArgumentException($"--patches {patches}: the baseline lattice is denser than the {w} x {h} samples.");
            int unknowns = new GregoryNet(patches, patches).Count;
            HeightmapFit g = HeightmapFitter.Fit(z, w, h, patches, patches, null, default, FitObjective.LeastSquares);
            Console.WriteLine(string.Format(CultureInfo.InvariantCulture,
                "# {0} {1}x{2}, {3}x{3} patches: baseline RMS {4:F3} m ({5} values), Gregory net least squares RMS {6:F3} m ({7:F3}, {8} unknowns)",
                Path.GetFileName(dem), w, h, patches, bRms, (3 * patches + 1) * (3 * patches + 1), g.RmsError, g.RmsError / bRms, unknowns));
            Console.WriteLine("count\tunknowns\tdct_K\tdct_rms_m\tdct_ratio\tspline_patches\tspline_unknowns\tspline_rms_m\tspline_ratio");
            foreach ((string label, double factor) in new[] { ("U", 1.0), ("9/7 U", 9.0 / 7), ("2 U", 2.0), ("4 U", 4.0) })
            {
                double target = factor * unknowns;
                int K = Math.Min(Math.Min(w, h), (int)Math.Round(Math.Sqrt(target)));
                double dctRms = DctTruncationRms(z, w, h, K);
                int k = Math.Max(1, (int)Math.Round(Math.Sqrt(target / 4)) - 1);
                C1HeightmapFit s = C1HeightmapFitter.Fit(z, w, h, k, k);
                Console.WriteLine(string.Format(CultureInfo.InvariantCulture, "{0}\t{1:F0}\t{2}\t{3:F3}\t{4:F3}\t{5}\t{6}\t{7:F3}\t{8:F3}",
                    label, target, K, dctRms, dctRms / bRms, k, 4 * (k + 1) * (k + 1), s.RmsError, s.RmsError / bRms));
            }
            return 0;
        }

        /// <summary>
        /// RMS of the samples minus their projection on the K x K lowest DCT-II frequencies:
        /// <c>sqrt((|Z|^2 - |D_K Z D_K^T|^2) / N)</c>, D_K the first K rows of the orthonormal DCT.
        /// </summary>
        static double DctTruncationRms(double[] z, int w, int h, int K)
        {
            double[] dx = DctRows(w, K), dy = DctRows(h, K);
            // T = Z D_x^T (h x K), then C = D_y T (K x K).
            var t = new double[(long)h * K];
            for (int r = 0; r < h; r++)
                for (int k = 0; k < K; k++)
                {
                    double s = 0;
                    long row = (long)r * w, drow = (long)k * w;
                    for (int c = 0; c < w; c++) s += z[row + c] * dx[drow + c];
                    t[(long)r * K + k] = s;
                }
            double kept = 0, total = 0;
            foreach (double v in z) total += v * v;
            var col = new double[K];
            for (int ky = 0; ky < K; ky++)
            {
                Array.Clear(col, 0, K);
                for (int r = 0; r < h; r++)
                {
                    double f = dy[(long)ky * h + r];
                    long o = (long)r * K;
                    for (int k = 0; k < K; k++) col[k] += f * t[o + k];
                }
                foreach (double v in col) kept += v * v;
            }
            return Math.Sqrt(Math.Max(0, total - kept) / ((double)w * h));
        }

        /// <summary>The first K rows of the orthonormal n-point DCT-II, row k at k n.</summary>
        static double[] DctRows(int n, int K)
        {
            var d = new double[(long)K * n];
            for (int k = 0; k < K; k++)
            {
                double scale = Math.Sqrt((k == 0 ? 1.0 : 2.0) / n);
                for (int i = 0; i < n; i++) d[(long)k * n + i] = scale * Math.Cos(Math.PI * k * (2 * i + 1) / (2.0 * n));
            }
            return d;
        }
    }
}
