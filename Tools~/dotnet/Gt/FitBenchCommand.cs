using System;
using System.Diagnostics;
using System.Globalization;
using System.IO;
using GregoryTerrain.Rig.Legacy;

namespace GregoryTerrain.Rig
{
    /// <summary>
    /// gt fit-bench's measurements, one fit per process so each peak memory is its own:
    ///   fit-bench --dem FILE.hgt --patches P [--c1 | --legacy]   error (m, % of relief), G1 angle, time, memory
    ///   fit-bench --size N --patches P [--c1 | --legacy]         time and memory on an N x N synthetic heightmap
    /// --ls: the shipped fitter's least-squares optimum alone (FitObjective.LeastSquares), without the max bound.
    /// Last columns: the bilinear baseline's max and RMS, the fit's ratios to them, reweighting rounds.
    /// Fitters: the shipped Gregory-net least squares (default), the previous C1-spline least squares
    /// (--c1, Legacy/C1HeightmapFitter.cs), the interpolating fitter before it (--legacy).
    /// Prints one tab-separated line (wall and CPU seconds: CPU time is what to compare on a shared machine); Tools~/rig/fit-bench.sh runs the grid of cases and tabulates.
    /// Peak memory is the process's high-water mark (VmHWM) after the fit minus the one before it,
    /// with the heights already allocated and touched: what the fit itself adds.
    /// </summary>
    static class FitBenchCommand
    {
        public static int Run(Args a)
        {
            int patches = a.Int("patches");
            bool legacy = a.Flag("legacy"), c1 = a.Flag("c1"), lsOnly = a.Flag("ls");
            string dem = a.String("dem", "");
            double[] z;
            int w, h;
            double widthMetres;
            if (dem.Length > 0)
            {
                byte[] bytes = File.ReadAllBytes(dem);
                w = 0; h = 0;
                RawHeightmap.InferSize(Path.GetFileName(dem), bytes.Length, RawSampleFormat.Int16BigEndian, ref w, ref h);
                z = RawHeightmap.Decode(Path.GetFileName(dem), bytes, w, h, RawSampleFormat.Int16BigEndian, RawHeightmap.SrtmVoid);
                HeightmapVoids.Fill(z, w, h);
                // SRTM3 tile at 48.5 N: 1200 steps of 3 arc-seconds east-west.
                widthMetres = (w - 1) * 92.6 * Math.Cos(48.5 * Math.PI / 180);
            }
            else
            {
                w = h = a.Int("size");
                z = Synthetic(w);
                widthMetres = 1;
            }
            // JIT both fitters on a small map first, so the timed fit is the fit alone.
            var warm = new double[33 * 33];
            HeightmapFitter.Fit(warm, 33, 33, 4, 4);
            LegacyHeightmapFitter.Fit(warm, 33, 33, 4, 4);
            C1HeightmapFitter.Fit(warm, 33, 33, 4, 4);
            long before = PeakBytes();
            TimeSpan cpu0 = Process.GetCurrentProcess().TotalProcessorTime;
            var sw = Stopwatch.StartNew();
            PatchGrid grid;
            double max, rms;
            int iterations = 0, rounds = 0;
            if (legacy)
            {
                LegacyHeightmapFit f = LegacyHeightmapFitter.Fit(z, w, h, patches, patches);
                grid = f.Grid; max = f.MaxError; rms = f.RmsError;
            }
            else if (c1)
            {
                C1HeightmapFit f = C1HeightmapFitter.Fit(z, w, h, patches, patches);
                grid = f.Grid; max = f.MaxError; rms = f.RmsError;
            }
            else
            {
                HeightmapFit f = HeightmapFitter.Fit(z, w, h, patches, patches, null, default, lsOnly ? FitObjective.LeastSquares : FitObjective.BoundedMax);
                grid = f.Grid; max = f.MaxError; rms = f.RmsError; iterations = f.Iterations; rounds = f.ReweightRounds;
            }
            double seconds = sw.Elapsed.TotalSeconds;
            double cpuSeconds = (Process.GetCurrentProcess().TotalProcessorTime - cpu0).TotalSeconds;
            long extra = PeakBytes() - before;
            double lo = double.MaxValue, hi = double.MinValue;
            foreach (double v in z) { lo = Math.Min(lo, v); hi = Math.Max(hi, v); }
            double angle = double.NaN;
            if (dem.Length > 0)
            {
                // Angles in consistent units: z over the tile's width in metres (the unit square's x).
                PatchGrid s = grid.Clone();
                foreach (GregoryPatch p in s.Patches)
                    for (int k = 0; k < GregoryPatch.SlotCount; k++) p[k] = new Double3(p[k].x, p[k].y, p[k].z / widthMetres);
                angle = ContinuityMeasure.MaxNormalAngleDegrees(s, 9);
            }
            // The bilinear baseline on the same lattice (after the timing: not part of any fit's cost).
            BilinearBaseline.Measure(z, w, h, patches, patches, out double bMax, out double bRms);
            Console.WriteLine(string.Format(CultureInfo.InvariantCulture,
                "{0}\t{1}x{2}\t{3}\t{4:F2}\t{5:F3}\t{6:F2}\t{7:F3}\t{8:E1}\t{9:F2}\t{10:F2}\t{11:F0}\t{12:F1}\t{13}\t{14:F2}\t{15:F3}\t{16:F3}\t{17:F3}\t{18}",
                legacy ? "legacy" : c1 ? "c1-spline" : lsOnly ? "gregory-ls" : "gregory-net", w, h, patches, max, rms, 100 * max / (hi - lo), 100 * rms / (hi - lo),
                angle, seconds, cpuSeconds, extra / 1048576.0, (double)extra / ((double)w * h), iterations,
                bMax, bRms, max / bMax, rms / bRms, rounds));
            return 0;
        }

        /// <summary>A rough synthetic terrain: sines over five octaves, about 0.1 high.</summary>
        static double[] Synthetic(int n)
        {
            var z = new double[(long)n * n];
            for (int r = 0; r < n; r++)
            {
                double y = (double)r / (n - 1);
                for (int c = 0; c < n; c++)
                {
                    double x = (double)c / (n - 1), s = 0, amp = 0.05, f = 2;
                    for (int o = 0; o < 5; o++, amp *= 0.5, f *= 2.3)
                        s += amp * Math.Sin(f * 6.2831853 * x + 1.3 * o) * Math.Cos(f * 5.1 * y + 0.7 * o);
                    z[(long)r * n + c] = s;
                }
            }
            return z;
        }

        /// <summary>VmHWM of this process in bytes (Linux), or 0 where /proc is missing.</summary>
        static long PeakBytes()
        {
            const string status = "/proc/self/status";
            if (!File.Exists(status)) return 0;
            foreach (string line in File.ReadAllLines(status))
                if (line.StartsWith("VmHWM:", StringComparison.Ordinal))
                    return long.Parse(line.Substring(6).Trim().Split(' ')[0], CultureInfo.InvariantCulture) * 1024;
            return 0;
        }
    }
}
