// URP's real passes of GregoryTerrain.shader, compiled against Unity's 2022.3 libraries and drawn by
// the harness on lavapipe with every binding filled by name from one scene (Tools~/rig/pipeline_pass.py):
// the sample grid, RigScene's zoom view, a sun 30 degrees up. One run draws DepthOnly's depth,
// ForwardLit's colour, ForwardLit's GT_DEBUG_NORMALS view of the same surface, ForwardLit's colour from
// DXC's SPIR-V, Built-in's ForwardBase colour, and URP's shadowed frame (ShadowCaster's map from the
// sun, ForwardLit's _MAIN_LIGHT_SHADOWS variant: PipelinePassShadowTests.cs); the tests grade them, and
// compare the two pipelines where their lighting models agree. They fail (never skip) when gt-cli, the harness, glslang, spirv-cross or lavapipe is missing.
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
    [TestFixture, Parallelizable(ParallelScope.Self)]
    public partial class PipelinePassGpuTests
    {
        /// <summary>The scene's arguments (pipeline_pass.py's defaults, written out so a reader sees them).</summary>
        static readonly string[] Scene = { "--sun-elevation", "30", "--sun-azimuth", "-140", "--light-color", "1,0.96,0.9",
                                             "--shadow-sun-elevation", "12", "--shadow-sun-azimuth", "90" };

        // The harness's clear colour (sky, Tools~/harness/README.md), and what an 8-bit channel may round by.
        static readonly double[] Sky = { 0.55, 0.70, 0.90 };
        const double Quantum = 2.0 / 255.0;

        string _out, _log;
        RigPng _depth, _lit, _normals, _litDxc, _builtinLit;
        JsonElement _litManifest, _builtinManifest;
        double[] _albedo, _sun, _light;
        double _ambient;
        List<int> _covered;

        [OneTimeSetUp]
        public void Draw()
        {
            string root = HarnessRun.PackageRoot();
            Assert.That(File.Exists(HarnessRun.HarnessPath()), Is.True, "gt-harness not built (run Tools~/gt setup)");
            Assert.That(File.Exists(HarnessRun.LavapipeIcd), Is.True, "lavapipe is not installed");
            _out = Path.Combine(root, ".build", "rigtests-pipeline-pass");
            var args = new List<string> { Path.Combine(root, "Tools~", "rig", "pipeline_pass.py"), "--out", _out };
            args.AddRange(Scene);
            var clock = Stopwatch.StartNew();
            HarnessRun r = HarnessRun.Start("python3", args,
                new Dictionary<string, string> { ["MESA_SHADER_CACHE_DIR"] = Path.Combine(root, ".build", "mesa-shader-cache") });
            _log = r.Stdout + r.Stderr;
            TestContext.Progress.WriteLine($"pipeline_pass.py: {clock.Elapsed.TotalSeconds:F1} s");
            Assert.That(r.ExitCode, Is.EqualTo(0), "pipeline_pass.py failed:\n" + _log);
            _depth = RigPng.Read(Path.Combine(_out, "depth.png"));
            _lit = RigPng.Read(Path.Combine(_out, "lit.png"));
            _normals = RigPng.Read(Path.Combine(_out, "normals.png"));
            _litDxc = RigPng.Read(Path.Combine(_out, "lit_dxc.png"));
            _builtinLit = RigPng.Read(Path.Combine(_out, "builtin_lit.png"));
            _litManifest = Manifest("lit");
            _builtinManifest = Manifest("builtin_lit");
            _sun = _litManifest.GetProperty("sun").EnumerateArray().Select(e => e.GetDouble()).ToArray();
            _light = _litManifest.GetProperty("light_color").EnumerateArray().Select(e => e.GetDouble()).ToArray();
            string shading = File.ReadAllText(Path.Combine(root, "Shaders", "Terrain", "TerrainShading.hlsl"));
            _albedo = Regex.Match(shading, @"GT_DEFAULT_ALBEDO = float3\(([^)]*)\)").Groups[1].Value.Split(',')
                .Select(s => double.Parse(s, CultureInfo.InvariantCulture)).ToArray();
            _ambient = double.Parse(Regex.Match(shading, @"GT_AMBIENT = ([0-9.]+);").Groups[1].Value, CultureInfo.InvariantCulture);
            Assert.That(_albedo.Length, Is.EqualTo(3), "GT_DEFAULT_ALBEDO in TerrainShading.hlsl");
            // Depth written: DepthOnly writes the pixel's depth to R (ColorMask R; about 2/255 here).
            _covered = Enumerable.Range(0, _depth.Width * _depth.Height).Where(p => !IsSky(_depth, p, 0)).ToList();
            Assert.That(_covered.Count, Is.GreaterThan(_depth.Width * _depth.Height / 5), "the terrain covers a fifth of the picture or more");
        }

        static bool IsSky(RigPng png, int p, int c) => Math.Abs(png.Rgba[4 * p + c] - Sky[c] * 255) <= 1;

        JsonElement Manifest(string picture) =>
            JsonDocument.Parse(File.ReadAllText(Path.Combine(_out, picture, "manifest.json"))).RootElement;

        static string[] Strings(JsonElement e) => e.EnumerateArray().Select(x => x.GetString()).ToArray();

        double Channel(RigPng png, int pixel, int c) => png.Rgba[4 * pixel + c] / 255.0;

        /// <summary>Towards the sun dotted with the pixel's world normal, decoded from the normals view.</summary>
        double NDotL(int p) => PipelinePassRun.NormalsViewDot(_normals, p, _sun);

        double Luminance(int p) => (Channel(_lit, p, 0) + Channel(_lit, p, 1) + Channel(_lit, p, 2)) / 3;

        [Test]
        public void EveryMemberTheStagesRead_IsFilledByTheScene_AndEveryDefaultIsListed()
        {
            foreach (string picture in new[] { "depth", "lit", "normals", "lit_dxc", "builtin_lit", "shadow_map", "lit_shadows" })
            {
                JsonElement m = Manifest(picture);
                string[] defaults = Strings(m.GetProperty("defaults")), filled = Strings(m.GetProperty("filled"));
                string[] read = m.GetProperty("reads").EnumerateObject().SelectMany(s => Strings(s.Value)).Distinct().ToArray();
                TestContext.Out.WriteLine($"{picture}: {filled.Length} filled, {defaults.Length} defaulted: {string.Join(", ", defaults)}");
                TestContext.Out.WriteLine($"{picture}: read by the stages: {string.Join(", ", read)}");
                Assert.That(Strings(m.GetProperty("defaulted_read")), Is.Empty, picture + ": a member some stage reads was left to its default");
                Assert.That(read.Where(r => !filled.Contains(r)), Is.Empty, picture + ": read but not filled by the scene");
                Assert.That(_log, Does.Contain("defaults " + defaults.Length + ": "), "the run prints the defaults");
            }
            string[] frag = Strings(_litManifest.GetProperty("reads").GetProperty("frag"));
            Assert.That(frag, Does.Contain("$Global._MainLightColor").And.Contain("$Global._MainLightPosition"),
                "ForwardLit's fragment stage reads URP's main light (GetMainLight)");
            string[] builtinFrag = Strings(_builtinManifest.GetProperty("reads").GetProperty("frag"));
            Assert.That(builtinFrag, Does.Contain("$Global._LightColor0").And.Contain("$Global._WorldSpaceLightPos0"),
                "ForwardBase's fragment stage reads Built-in's main light");
        }

        [Test]
        public void NoPixelIsNaNOrInf_AndEveryCoveredPixelIsLitTerrainWithinLambertsBounds()
        {
            // UNORM8 stores NaN as 0 and +Inf as 1 (Vulkan's float -> normalized conversion), so a NaN or
            // Inf pixel falls outside albedo * ambient .. albedo * (ambient + light): both bounds are checked
            // on every covered pixel, and no uncovered pixel may be drawn.
            int below = 0, above = 0, drawnOutside = 0, firstBad = -1;
            var covered = new HashSet<int>(_covered);
            for (int p = 0; p < _lit.Width * _lit.Height; p++)
            {
                bool isSky = Enumerable.Range(0, 3).All(c => IsSky(_lit, p, c));
                if (!covered.Contains(p)) { drawnOutside += isSky ? 0 : 1; continue; }
                for (int c = 0; c < 3; c++)
                {
                    double v = Channel(_lit, p, c);
                    bool lo = v < _albedo[c] * _ambient - Quantum, hi = v > _albedo[c] * (_ambient + _light[c]) + Quantum;
                    below += lo ? 1 : 0;
                    above += hi ? 1 : 0;
                    if ((lo || hi) && firstBad < 0) firstBad = p;
                }
            }
            string where = firstBad < 0 ? "" : $"; first at ({firstBad % _lit.Width}, {firstBad / _lit.Width}) = " +
                                                 string.Join(",", Enumerable.Range(0, 3).Select(c => _lit.Rgba[4 * firstBad + c]));
            TestContext.Out.WriteLine($"covered {_covered.Count} of {_lit.Width * _lit.Height}; channels below {below}, above {above}, drawn outside {drawnOutside}{where}");
            Assert.That(below, Is.Zero, "channels below albedo * ambient (a NaN reads 0)" + where);
            Assert.That(above, Is.Zero, "channels above albedo * (ambient + light colour) (an Inf reads 1)" + where);
            Assert.That(drawnOutside, Is.Zero, "ForwardLit drew pixels DepthOnly did not cover");
        }

        [Test]
        public void TheLitPicture_IsLambertOfThePassesOwnNormals_WithTheScenesSun()
        {
            // Per pixel: albedo * (ambient + light * saturate(N.L)) with N from the same pass's normals view.
            // The normals are 8-bit (N.L off by up to ~0.006), the colour 8-bit: 3/255 bounds one pixel.
            var errors = new List<double>();
            foreach (int p in _covered)
            {
                double nl = Math.Max(0, NDotL(p));
                for (int c = 0; c < 3; c++)
                    errors.Add(Math.Abs(Channel(_lit, p, c) - _albedo[c] * (_ambient + _light[c] * nl)));
            }
            errors.Sort();
            double mean = errors.Average(), p99 = errors[(int)(0.99 * (errors.Count - 1))], max = errors.Last();
            TestContext.Out.WriteLine($"|lit - Lambert(normals)|: mean {mean * 255:F2}/255, 99th percentile {p99 * 255:F2}/255, max {max * 255:F2}/255");
            Assert.That(mean, Is.LessThan(1.0 / 255), "mean error against Lambert of the pass's normals");
            Assert.That(p99, Is.LessThan(2.0 / 255), "99th percentile error");
            Assert.That(max, Is.LessThan(3.0 / 255), "largest error");
        }

        [Test]
        public void SunlitSlopes_AreBrighterThanSlopesFacingAway_AndTheBrightnessIsInRange()
        {
            var lit = _covered.Where(p => NDotL(p) > 0.7).Select(Luminance).ToList();
            var away = _covered.Where(p => NDotL(p) < 0.3).Select(Luminance).ToList();
            double all = _covered.Select(Luminance).Average();
            TestContext.Out.WriteLine($"N.L > 0.7: {lit.Count} pixels, mean {(lit.Count > 0 ? lit.Average() : double.NaN):F3}; " +
                                      $"N.L < 0.3: {away.Count} pixels, mean {(away.Count > 0 ? away.Average() : double.NaN):F3}; covered mean {all:F3}");
            Assert.That(lit.Count, Is.GreaterThan(_covered.Count / 50), "slopes facing the sun (N.L > 0.7) cover 2% of the terrain or more");
            Assert.That(away.Count, Is.GreaterThan(_covered.Count / 50), "slopes turned away (N.L < 0.3) cover 2% of the terrain or more");
            // Lambert puts them 0.4 * albedo * light = 0.2 apart at least; 0.15 leaves room for 8 bits.
            Assert.That(lit.Average() - away.Average(), Is.GreaterThan(0.15), "sunlit minus turned-away mean brightness");
            // albedo ~0.53 times (0.2 + N.L): a sun 30 degrees up over gentle hills lights N.L ~0.5 on average.
            Assert.That(all, Is.InRange(0.25, 0.50), "mean brightness of the terrain");
        }

        [Test]
        public void DxcsSpirv_DrawsTheSamePictureAsGlslangs()
        {
            // Two compilers of the same pass (Unity ships FXC; neither is it): their pictures may differ
            // by float rounding, one 8-bit step at most.
            int differing = _lit.PixelsDifferingFrom(_litDxc, 1);
            int largest = Enumerable.Range(0, _lit.Rgba.Length).Max(i => Math.Abs(_lit.Rgba[i] - _litDxc.Rgba[i]));
            TestContext.Out.WriteLine($"glslang vs DXC: largest channel difference {largest}/255, pixels differing by more than 1/255: {differing}");
            Assert.That(differing, Is.Zero, "pixels whose glslang and DXC colours differ by more than 1/255");
        }

        [Test]
        public void BuiltinsForwardBase_DrawsUrpsForwardLitPicture_WhereTheirLightingAgrees()
        {
            // Both adapters light by Lambert with the package's constant ambient (GT_AMBIENT; neither
            // defines GT_AMBIENT_PROBE), the same main light (URP's _MainLightPosition/_MainLightColor,
            // Built-in's _WorldSpaceLightPos0/_LightColor0) and the same surface: the pictures differ by
            // float rounding at most, one 8-bit step, and cover the same pixels.
            int largest = 0, over = 0, firstBad = -1;
            foreach (int p in _covered)
                for (int c = 0; c < 3; c++)
                {
                    int d = Math.Abs(_lit.Rgba[4 * p + c] - _builtinLit.Rgba[4 * p + c]);
                    largest = Math.Max(largest, d);
                    if (d > 1) { over++; if (firstBad < 0) firstBad = p; }
                }
            var covered = new HashSet<int>(_covered);
            int drawnOutside = Enumerable.Range(0, _lit.Width * _lit.Height)
                .Count(p => !covered.Contains(p) && !Enumerable.Range(0, 3).All(c => IsSky(_builtinLit, p, c)));
            string where = firstBad < 0 ? "" : $"; first at ({firstBad % _lit.Width}, {firstBad / _lit.Width}): URP " +
                string.Join(",", Enumerable.Range(0, 3).Select(c => _lit.Rgba[4 * firstBad + c])) + ", Built-in " +
                string.Join(",", Enumerable.Range(0, 3).Select(c => _builtinLit.Rgba[4 * firstBad + c]));
            TestContext.Out.WriteLine($"URP vs Built-in over {_covered.Count} covered pixels: largest channel difference {largest}/255, " +
                                      $"channels differing by more than 1/255: {over}, Built-in pixels outside URP's coverage: {drawnOutside}{where}");
            Assert.That(over, Is.Zero, "covered channels whose URP and Built-in colours differ by more than 1/255" + where);
            Assert.That(drawnOutside, Is.Zero, "Built-in drew pixels URP's DepthOnly did not cover");
        }
    }
}
