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
using System.Threading.Tasks;
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

        /// <summary>The rig scene's sky colour (pipeline_pass.py's clear), 0-1 per channel.</summary>
        public static readonly double[] Sky = { 0.55, 0.70, 0.90 };

        /// <summary>Whether pixel p holds the sky's clear colour within one step in every channel.</summary>
        public static bool IsSky(RigPng png, int p) => Enumerable.Range(0, 3).All(c => Math.Abs(png.Rgba[4 * p + c] - Sky[c] * 255) <= 1);

        /// <summary>The pixels a picture covers: every one that is not the sky.</summary>
        public static List<int> Covered(RigPng png) => Enumerable.Range(0, png.Width * png.Height).Where(p => !IsSky(png, p)).ToList();

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

        public static double[] Doubles(JsonElement e) => e.EnumerateArray().Select(x => x.GetDouble()).ToArray();

        /// <summary>A 4x4 matrix written by the scripts as four rows.</summary>
        public static double[,] Matrix(JsonElement e)
        {
            var rows = e.EnumerateArray().Select(Doubles).ToArray();
            var m = new double[4, 4];
            for (int r = 0; r < 4; r++) for (int c = 0; c < 4; c++) m[r, c] = rows[r][c];
            return m;
        }

        public static double[,] Inverse(double[,] m)
        {
            var a = new double[4, 8];
            for (int r = 0; r < 4; r++) for (int c = 0; c < 4; c++) { a[r, c] = m[r, c]; a[r, 4 + c] = r == c ? 1 : 0; }
            for (int c = 0; c < 4; c++)
            {
                int p = Enumerable.Range(c, 4 - c).OrderByDescending(r => Math.Abs(a[r, c])).First();
                for (int k = 0; k < 8; k++) (a[c, k], a[p, k]) = (a[p, k], a[c, k]);
                double pivot = a[c, c];
                for (int k = 0; k < 8; k++) a[c, k] /= pivot;
                for (int r = 0; r < 4; r++)
                    if (r != c) { double f = a[r, c]; for (int k = 0; k < 8; k++) a[r, k] -= f * a[c, k]; }
            }
            var inv = new double[4, 4];
            for (int r = 0; r < 4; r++) for (int c = 0; c < 4; c++) inv[r, c] = a[r, 4 + c];
            return inv;
        }

        public static double[] Mul(double[,] m, double[] v) =>
            Enumerable.Range(0, 4).Select(r => Enumerable.Range(0, 4).Sum(c => m[r, c] * v[c])).ToArray();

        /// <summary>The world normal an octahedral normal texel holds (URP's _GBUFFER_NORMALS_OCT target and HDRP's
        /// normal buffer pack it alike): two 12-bit coordinates in RGB 8:8:8, decoded as SRP Core's Packing.hlsl does
        /// (Packing.hlsl:560-575 Unpack888ToFloat2: R and B's low 4 bits the first, G and B's high 4 bits the second, / 4095;
        /// then * 2 - 1 and UnpackNormalOctQuadEncode, lines 71-83; URP: DeclareNormalsTexture.hlsl:25-28).</summary>
        public static double[] OctahedralNormal(RigPng png, int p)
        {
            int r = png.Rgba[4 * p], g = png.Rgba[4 * p + 1], b = png.Rgba[4 * p + 2];
            double x = ((b & 15) << 8 | r) / 4095.0 * 2 - 1, y = ((b >> 4) << 8 | g) / 4095.0 * 2 - 1;
            double z = 1 - Math.Abs(x) - Math.Abs(y), t = Math.Max(-z, 0);
            x += x >= 0 ? -t : t;
            y += y >= 0 ? -t : t;
            double len = Math.Sqrt(x * x + y * y + z * z);
            return new[] { x / len, y / len, z / len };
        }

        /// <summary>
        /// Angles in degrees between the normal a pass wrote (decoded) and Core's at the same place, at every
        /// step-th covered pixel in x and y: the pixel's world position from the pass's own depth (DEPTH: the
        /// harness's --depth-out, W x H float32, top row first) through the inverse of the camera's
        /// view-projection (VIEW: camera_view_proj, object_to_world), then terrain (x, y) = object (x, z);
        /// Core's unit normal there (TerrainSurfaceQuery.SampleNormal on grid.json, no noise: the scene packs
        /// amplitude 0) taken to world space as the shaders take it (GT_ObjectToWorldNormal: n times the
        /// world-to-object matrix's 3x3). Pixels whose position lies outside the unit square are counted apart.
        /// </summary>
        public static (List<double> Angles, int Outside, string Worst) NormalAngles(string output, string depthFile, string viewFile, RigPng png,
                                                                      Func<int, double[]> decoded, int step)
        {
            byte[] depth = File.ReadAllBytes(Path.Combine(output, depthFile));
            int w = png.Width, h = png.Height;
            Assert.That(depth.Length, Is.EqualTo(4 * w * h), depthFile + ": the pass's W * H depth");
            JsonElement view = JsonDocument.Parse(File.ReadAllText(Path.Combine(output, viewFile))).RootElement;
            double[,] clipToWorld = Inverse(Matrix(view.GetProperty("camera_view_proj")));
            double[,] worldToObject = Inverse(Matrix(view.GetProperty("object_to_world")));
            var query = new TerrainSurfaceQuery(PatchGridJson.ReadFile(Path.Combine(output, "grid.json")), null);
            var angles = new List<double>();
            int outside = 0;
            string worst = "";
            double worstAngle = -1;
            for (int py = 0; py < h; py += step)
                for (int px = 0; px < w; px += step)
                {
                    int p = py * w + px;
                    float d = BitConverter.ToSingle(depth, 4 * p);
                    if (!(d > 0)) continue;                       // reversed depth's clear: nothing drawn
                    double[] world = Mul(clipToWorld, new[] { (px + 0.5) / w * 2 - 1, 1 - (py + 0.5) / h * 2, d, 1.0 });
                    double[] o = Mul(worldToObject, world.Select(x => x / world[3]).ToArray());
                    Double3 n = query.SampleNormal(o[0], o[2]);
                    if (n.x == 0 && n.y == 0 && n.z == 0) { outside++; continue; }
                    double[] nObject = { n.x, n.z, n.y };         // terrain (x, y, z up) -> object (x, height, y)
                    double[] core = Enumerable.Range(0, 3).Select(j => Enumerable.Range(0, 3).Sum(i => nObject[i] * worldToObject[i, j])).ToArray();
                    double coreLength = Math.Sqrt(core.Sum(x => x * x));
                    double[] gpu = decoded(p);
                    double cos = Enumerable.Range(0, 3).Sum(c => gpu[c] * core[c] / coreLength);
                    double angle = double.IsNaN(cos) ? double.NaN : Math.Acos(Math.Clamp(cos, -1, 1)) * 180 / Math.PI;
                    angles.Add(angle);
                    if (!(angle <= worstAngle))
                    {
                        worstAngle = double.IsNaN(angle) ? double.PositiveInfinity : angle;
                        worst = $"worst {angle:F3} deg at pixel ({px}, {py}), terrain ({o[0]:F4}, {o[2]:F4}), " +
                                $"GPU ({string.Join(", ", gpu.Select(x => x.ToString("F4")))}), Core ({string.Join(", ", core.Select(x => (x / coreLength).ToString("F4")))})";
                    }
                }
            return (angles, outside, worst);
        }

        /// <summary>One sampled pixel's shadow verdicts: the GPU's (from the picture) and the CPU ray test's, and whether
        /// the CPU's verdict changes within the edge margin (such pixels are left out of the agreement).</summary>
        public struct ShadowSample
        {
            public int Pixel;
            public bool Gpu, Cpu, NearEdge;
        }

        /// <summary>
        /// Classifies the pixels by the GPU's verdict (gpuShadowed) and the CPU ray test's, in parallel: each pixel's world
        /// position from the forward pass's depth (DEPTH: W x H float32, top row first) through the inverse of VIEW's
        /// camera_view_proj, then a ray toward the sun on TerrainSurfaceQuery's exact surface (grid.json), starting
        /// startWorld past the surface (beyond the pipeline's bias); a pixel whose verdict changes within edgeWorld
        /// (world units, terrain (x, y) steps either way) is NearEdge. Pixels with no depth are skipped.
        /// </summary>
        public static List<ShadowSample> ShadowSamples(string output, string depthFile, JsonElement view, double[] sun, int width, int height,
                                                       IEnumerable<int> pixels, double startWorld, double edgeWorld, Func<int, bool> gpuShadowed)
        {
            byte[] depthBytes = File.ReadAllBytes(Path.Combine(output, depthFile));
            Assert.That(depthBytes.Length, Is.EqualTo(4 * width * height), depthFile + ": the forward pass's W * H depth");
            double[,] clipToWorld = Inverse(Matrix(view.GetProperty("camera_view_proj")));
            double[,] worldToObject = Inverse(Matrix(view.GetProperty("object_to_world")));
            // Object space is (x, height, y) of terrain space; the object-to-world scale is uniform.
            double[] sunObject = Mul(worldToObject, new[] { sun[0], sun[1], sun[2], 0.0 });
            var sunTerrain = new Double3(sunObject[0], sunObject[2], sunObject[1]);
            double worldPerTerrain = 1.0 / Math.Sqrt(sunObject.Take(3).Sum(x => x * x));
            var query = new TerrainSurfaceQuery(PatchGridJson.ReadFile(Path.Combine(output, "grid.json")), null);
            double start = startWorld / worldPerTerrain, reach = edgeWorld / worldPerTerrain;   // terrain units

            bool Shadowed(double x, double y, double z) =>
                query.Raycast(new TerrainRay(new Double3(x, y, z) + sunTerrain * (start / GMath.length(sunTerrain)), sunTerrain, 10.0),
                              out _, 1e-7) == TerrainRayStatus.Hit;

            int[] chosen = pixels.ToArray();
            var samples = new ShadowSample?[chosen.Length];
            Parallel.For(0, chosen.Length, new ParallelOptions { MaxDegreeOfParallelism = 2 }, k =>
            {
                int p = chosen[k];
                float d = BitConverter.ToSingle(depthBytes, 4 * p);
                if (!(d > 0)) return;
                double[] world = Mul(clipToWorld, new[] { (p % width + 0.5) / width * 2 - 1, 1 - (p / width + 0.5) / height * 2, d, 1.0 });
                double[] o = Mul(worldToObject, world.Select(x => x / world[3]).ToArray());
                double x0 = o[0], y0 = o[2], z0 = o[1];
                bool cpu = Shadowed(x0, y0, z0);
                bool near = false;
                foreach (var (dx, dy) in new[] { (1, 0), (-1, 0), (0, 1), (0, -1) })
                {
                    double x = x0 + dx * reach, y = y0 + dy * reach, z = query.SampleHeight(x, y);
                    if (double.IsNaN(z) || Shadowed(x, y, z) != cpu) { near = true; break; }
                }
                samples[k] = new ShadowSample { Pixel = p, Gpu = gpuShadowed(p), Cpu = cpu, NearEdge = near };
            });
            return samples.Where(s => s.HasValue).Select(s => s.Value).ToList();
        }

        /// <summary>Away from shadow edges, the GPU's shadow and the CPU ray test agree at 99% of the samples or more, and
        /// neither side's shadow has more than 5% the other lacks (most pixels are sunlit, so the overall figure alone would
        /// pass a map that shadows nothing); the CPU shadows 3% or more, most samples are away from edges. Printed, then asserted.</summary>
        public static void AssertShadowAgreement(List<ShadowSample> samples, double edgeWorld, double texel, string what)
        {
            var away = samples.Where(s => !s.NearEdge).ToList();
            int agree = away.Count(s => s.Gpu == s.Cpu), cpuShadowed = away.Count(s => s.Cpu);
            int gpuOnly = away.Count(s => s.Gpu && !s.Cpu), cpuOnly = away.Count(s => s.Cpu && !s.Gpu);
            double fraction = away.Count > 0 ? (double)agree / away.Count : 0;
            TestContext.Out.WriteLine($"{what} vs CPU ray test: {samples.Count} sampled sunlit pixels, {away.Count} farther than " +
                                      $"{edgeWorld:G3} world units ({edgeWorld / texel:F0} texels) from a CPU shadow edge; " +
                                      $"CPU shadowed {cpuShadowed}; agree {agree} ({100 * fraction:F2}%), GPU-only {gpuOnly}, CPU-only {cpuOnly}; " +
                                      $"near edges (left out) {samples.Count - away.Count}");
            Assert.That(cpuShadowed, Is.GreaterThan(away.Count / 33), "the CPU puts 3% or more of the sunlit terrain away from edges in the ridges' shadow");
            Assert.That(away.Count, Is.GreaterThan(samples.Count / 2), "most sampled pixels are away from edges");
            Assert.That(fraction, Is.GreaterThanOrEqualTo(0.99), "pixels away from shadow edges where the GPU's shadow and the CPU ray test agree");
            Assert.That(cpuOnly, Is.LessThanOrEqualTo(cpuShadowed / 20), "pixels the CPU shadows and the GPU lights");
            Assert.That(gpuOnly, Is.LessThanOrEqualTo(away.Count(s => s.Gpu) / 20), "pixels the GPU shadows and the CPU lights");
        }

        /// <summary>A shadow caster's N x N map (FILE: the harness's --depth-out): every depth within [0, 1] and the terrain
        /// covering half a percent of the light's view or more (printed, then asserted; what: the map's name).</summary>
        public static void AssertShadowMapWritten(string output, string file, int n, double texel, string what)
        {
            byte[] map = File.ReadAllBytes(Path.Combine(output, file));
            Assert.That(map.Length, Is.EqualTo(4 * n * n), file);
            var depth = Enumerable.Range(0, n * n).Select(i => BitConverter.ToSingle(map, 4 * i)).ToArray();
            int written = depth.Count(x => x != 0), outside = depth.Count(x => !(x >= 0 && x <= 1));
            TestContext.Out.WriteLine($"{what} {n}x{n}: {written} texels written ({100.0 * written / (n * n):F2}%), depth " +
                                      $"{depth.Where(x => x != 0).DefaultIfEmpty().Min():F4}..{depth.Max():F4}; texel {texel:G3} world units");
            Assert.That(outside, Is.Zero, "depth outside [0, 1]");
            Assert.That(written, Is.GreaterThan(n * n / 200), "the terrain covers half a percent of the light's view or more");
        }

        /// <summary>A unit direction dotted with pixel p's world normal, decoded from a normals view (GT_DEBUG_NORMALS: the
        /// normal x 0.5 + 0.5 in 8 bits, renormalized).</summary>
        public static double NormalsViewDot(RigPng normals, int p, double[] direction)
        {
            var n = Enumerable.Range(0, 3).Select(c => normals.Rgba[4 * p + c] / 255.0 * 2 - 1).ToArray();
            double len = Math.Sqrt(n.Sum(x => x * x));
            return Enumerable.Range(0, 3).Sum(c => n[c] / len * direction[c]);
        }

        /// <summary>A W x H float32 depth file (the harness's --depth-out) under output.</summary>
        public static float[] ReadDepth(string output, string file)
        {
            byte[] bytes = File.ReadAllBytes(Path.Combine(output, file));
            return Enumerable.Range(0, bytes.Length / 4).Select(i => BitConverter.ToSingle(bytes, 4 * i)).ToArray();
        }

        /// <summary>Mean, 99th percentile and largest of the angles (a NaN counts as 180 degrees), printed.</summary>
        public static (double Mean, double P99, double Max) AngleFigures(List<double> angles, string what)
        {
            var sorted = angles.Select(a => double.IsNaN(a) ? 180 : a).OrderBy(a => a).ToList();
            Assert.That(sorted, Is.Not.Empty, what + ": no covered pixel sampled");
            double mean = sorted.Average(), p99 = sorted[(int)(0.99 * (sorted.Count - 1))], max = sorted.Last();
            TestContext.Out.WriteLine($"{what}: {sorted.Count} pixels, angle to Core's normal mean {mean:F3} deg, 99th percentile {p99:F3} deg, " +
                                      $"max {max:F3} deg, NaN {angles.Count(double.IsNaN)}");
            return (mean, p99, max);
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
