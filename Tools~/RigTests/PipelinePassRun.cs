// One run of a pipeline-pass script (Tools~/rig/pipeline_pass*.py) for the pipeline-pass fixtures, and what
// they read back: its manifests and the package's default albedo.
using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text.Json;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    static class PipelinePassRun
    {
        /// <summary>Runs Tools~/rig/SCRIPT with --out .build/OUTNAME and the scene's arguments (Mesa's shader
        /// cache in .build); fails, never skips, when the harness or lavapipe is missing or the run fails.
        /// Returns the output folder and the run's log.</summary>
        public static (string Out, string Log) Draw(string script, string outName, IEnumerable<string> scene)
        {
            string root = HarnessRun.PackageRoot();
            Assert.That(File.Exists(HarnessRun.HarnessPath()), Is.True, "gt-harness not built (run Tools~/gt setup)");
            Assert.That(File.Exists(HarnessRun.LavapipeIcd), Is.True, "lavapipe is not installed");
            string output = Path.Combine(root, ".build", outName);
            var args = new List<string> { Path.Combine(root, "Tools~", "rig", script), "--out", output };
            args.AddRange(scene);
            var clock = Stopwatch.StartNew();
            HarnessRun r = HarnessRun.Start("python3", args,
                new Dictionary<string, string> { ["MESA_SHADER_CACHE_DIR"] = Path.Combine(root, ".build", "mesa-shader-cache") });
            string log = r.Stdout + r.Stderr;
            TestContext.Progress.WriteLine($"{script}: {clock.Elapsed.TotalSeconds:F1} s");
            Assert.That(r.ExitCode, Is.EqualTo(0), script + " failed:\n" + log);
            return (output, log);
        }

        public static JsonElement Manifest(string output, string picture) =>
            JsonDocument.Parse(File.ReadAllText(Path.Combine(output, picture, "manifest.json"))).RootElement;

        public static string[] Strings(JsonElement e) => e.EnumerateArray().Select(x => x.GetString()).ToArray();

        /// <summary>Over the covered pixels, no channel below lo[c] or above hi[c] (UNORM8 stores a NaN as 0 and
        /// an Inf as 1, so bounds on both sides catch them); elsewhere, nothing but sky (printed, then asserted,
        /// naming the first pixel out of bounds). bounds: the bounds in words, for the messages.</summary>
        public static void AssertWithinBounds(RigPng png, IEnumerable<int> covered, double[] lo, double[] hi,
                                              Func<RigPng, int, bool> isSky, string bounds)
        {
            int below = 0, above = 0, drawnOutside = 0, firstBad = -1;
            var inside = new HashSet<int>(covered);
            for (int p = 0; p < png.Width * png.Height; p++)
            {
                if (!inside.Contains(p)) { drawnOutside += isSky(png, p) ? 0 : 1; continue; }
                for (int c = 0; c < 3; c++)
                {
                    double v = png.Rgba[4 * p + c] / 255.0;
                    below += v < lo[c] ? 1 : 0;
                    above += v > hi[c] ? 1 : 0;
                    if ((v < lo[c] || v > hi[c]) && firstBad < 0) firstBad = p;
                }
            }
            string where = firstBad < 0 ? "" : $"; first at ({firstBad % png.Width}, {firstBad / png.Width}) = " +
                                                 string.Join(",", Enumerable.Range(0, 3).Select(c => png.Rgba[4 * firstBad + c]));
            TestContext.Out.WriteLine($"covered {inside.Count}; channels outside {bounds}: below {below}, above {above}; drawn outside the cover {drawnOutside}{where}");
            Assert.That(below, Is.Zero, $"channels below {bounds} (a NaN reads 0){where}");
            Assert.That(above, Is.Zero, $"channels above {bounds} (an Inf reads 1){where}");
            Assert.That(drawnOutside, Is.Zero, "pixels drawn outside the covered ones");
        }

        /// <summary>Over the covered pixels, |a / scaleA - b| per channel (0..1): the largest, how many exceed
        /// tolerance, and the first that does with both colours (for the messages; names: a's and b's).</summary>
        public static (double Largest, int Over, string Where) Difference(RigPng a, double scaleA, RigPng b, IEnumerable<int> covered,
                                                                          double tolerance, string nameA, string nameB)
        {
            int over = 0, firstBad = -1;
            double largest = 0;
            foreach (int p in covered)
                for (int c = 0; c < 3; c++)
                {
                    double d = Math.Abs(a.Rgba[4 * p + c] / 255.0 / scaleA - b.Rgba[4 * p + c] / 255.0);
                    largest = Math.Max(largest, d);
                    if (d > tolerance) { over++; if (firstBad < 0) firstBad = p; }
                }
            string where = firstBad < 0 ? "" : $"; first at ({firstBad % a.Width}, {firstBad / a.Width}): {nameA} " +
                string.Join(",", Enumerable.Range(0, 3).Select(c => a.Rgba[4 * firstBad + c])) + $", {nameB} " +
                string.Join(",", Enumerable.Range(0, 3).Select(c => b.Rgba[4 * firstBad + c]));
            return (largest, over, where);
        }

        /// <summary>Per covered pixel and channel: |picture - scale x albedo x (ambient + light x saturate(N.L))|,
        /// Lambert with the pipeline's exposure (scale) and N.L at the pixel from nDotL.</summary>
        public static List<double> LambertErrors(RigPng png, IEnumerable<int> covered, Func<int, double> nDotL,
                                                 double scale, double[] albedo, double ambient, double[] light)
        {
            var errors = new List<double>();
            foreach (int p in covered)
            {
                double nl = Math.Max(0, nDotL(p));
                for (int c = 0; c < 3; c++)
                    errors.Add(Math.Abs(png.Rgba[4 * p + c] / 255.0 - scale * albedo[c] * (ambient + light[c] * nl)));
            }
            return errors;
        }

        /// <summary>Per-channel errors of a picture against its expected colours, 8-bit pictures: the mean under
        /// 1/255, the 99th percentile under 2/255 and the largest under 3/255 (printed, then asserted).</summary>
        public static void AssertWithinEightBitSteps(List<double> errors, string what)
        {
            errors.Sort();
            double mean = errors.Average(), p99 = errors[(int)(0.99 * (errors.Count - 1))], max = errors.Last();
            TestContext.Out.WriteLine($"{what}: mean {mean * 255:F2}/255, 99th percentile {p99 * 255:F2}/255, max {max * 255:F2}/255");
            Assert.That(mean, Is.LessThan(1.0 / 255), what + ": mean error");
            Assert.That(p99, Is.LessThan(2.0 / 255), what + ": 99th percentile error");
            Assert.That(max, Is.LessThan(3.0 / 255), what + ": largest error");
        }

        /// <summary>TerrainShading.hlsl's GT_DEFAULT_ALBEDO and GT_AMBIENT, as the shader has them.</summary>
        public static (double[] Albedo, double Ambient) Shading()
        {
            string shading = File.ReadAllText(Path.Combine(HarnessRun.PackageRoot(), "Shaders", "Terrain", "TerrainShading.hlsl"));
            double[] albedo = Regex.Match(shading, @"GT_DEFAULT_ALBEDO = float3\(([^)]*)\)").Groups[1].Value.Split(',')
                .Select(s => double.Parse(s, CultureInfo.InvariantCulture)).ToArray();
            Assert.That(albedo.Length, Is.EqualTo(3), "GT_DEFAULT_ALBEDO in TerrainShading.hlsl");
            return (albedo, double.Parse(Regex.Match(shading, @"GT_AMBIENT = ([0-9.]+);").Groups[1].Value, CultureInfo.InvariantCulture));
        }
    }
}
