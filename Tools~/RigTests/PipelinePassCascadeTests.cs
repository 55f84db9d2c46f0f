// URP's cascaded main-light shadow in the rig's frame (pipeline_pass.py --only lit_cascades, draw_cascades): the
// ShadowCaster drawn once per cascade into its tile of URP's atlas (2 cascades: 2048 x 1024, 4: 2048^2, 1024^2 tiles),
// then ForwardLit's _MAIN_LIGHT_SHADOWS_CASCADE variant sampling it with the spheres and matrices URP 14 sets. Checked:
// the cascade the GPU picks at each sunlit pixel (read from two more pictures over atlases whose tiles are all
// occluding or all clear by the index's bits) is Shadows.hlsl's ComputeCascadeIndex of the pixel's world position,
// and the shadow falls where a CPU ray toward the sun on TerrainSurfaceQuery's surface says, as for one cascade
// (PipelinePassShadowTests). Not in gt test (about a minute of drawing a cascade count): gt pipeline_pass_all runs
// this category after its variants (Tools~/rig/README.md, "Every variant"). Fails, never skips.
using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.Json;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    [TestFixture(4), TestFixture(2), Category(AllVariantsLane)]
    public class PipelinePassCascadeTests
    {
        /// <summary>The category gt test leaves out and gt pipeline_pass_all runs (Tools~/rig/test.sh, pipeline_pass_all.sh).</summary>
        public const string AllVariantsLane = "AllVariants";
        const double MinNDotL = 0.25, Quantum = 2.0 / 255.0;

        readonly int _count;
        string _out;
        RigPng _lit, _normals;
        RigPng[] _bits;
        JsonElement _cascades;
        double[] _albedo, _sun, _light;
        double _ambient;
        List<int> _chosen;
        float[] _depth;     // ForwardLit's own depth (the world positions)
        double[,] _clipToWorld;

        public PipelinePassCascadeTests(int count) => _count = count;

        [OneTimeSetUp]
        public void Draw()
        {
            (_out, _) = PipelinePassRun.Draw("pipeline_pass.py", $"rigtests-pipeline-pass-cascades-{_count}",
                new[] { "--only", "lit_cascades", "--only", "normals", "--cascades", _count.ToString(),
                        "--shadow-sun-elevation", "12", "--shadow-sun-azimuth", "90", "--light-color", "1,0.96,0.9" });
            _lit = RigPng.Read(Path.Combine(_out, "lit_cascades.png"));
            _normals = RigPng.Read(Path.Combine(_out, "normals.png"));
            _bits = new[] { 0, 1 }.Select(b => RigPng.Read(Path.Combine(_out, $"lit_cascades_bit{b}.png"))).ToArray();
            _depth = PipelinePassRun.ReadDepth(_out, "lit_cascades_depth.f32");
            _cascades = JsonDocument.Parse(File.ReadAllText(Path.Combine(_out, "cascades.json"))).RootElement;
            _clipToWorld = PipelinePassRun.Inverse(PipelinePassRun.Matrix(_cascades.GetProperty("camera_view_proj")));
            JsonElement m = PipelinePassRun.Manifest(_out, "lit_cascades");
            _sun = PipelinePassRun.Doubles(m.GetProperty("sun"));
            _light = PipelinePassRun.Doubles(m.GetProperty("light_color"));
            (_albedo, _ambient) = PipelinePassRun.Shading();
            // Every third covered pixel in x and y that the sun lights without the map (N.L >= MinNDotL).
            int w = _lit.Width;
            _chosen = PipelinePassRun.Covered(_lit).Where(p => p % w % 3 == 0 && p / w % 3 == 0 && NDotL(p) >= MinNDotL).ToList();
        }

        double NDotL(int p) => PipelinePassRun.NormalsViewDot(_normals, p, _sun);

        /// <summary>The light's share left at the pixel over albedo x light: N.L unshadowed, 0 in shadow.</summary>
        double DirectShare(RigPng png, int p) =>
            Enumerable.Range(0, 3).Average(c => (png.Rgba[4 * p + c] / 255.0 - _albedo[c] * _ambient) / (_albedo[c] * _light[c]));

        bool Shadowed(RigPng png, int p) => DirectShare(png, p) < 0.5 * NDotL(p);

        double[] Centre(int i) => PipelinePassRun.Doubles(_cascades.GetProperty("centers")[i]);
        double Radius(int i) => _cascades.GetProperty("radii")[i].GetDouble();

        /// <summary>Shadows.hlsl's ComputeCascadeIndex (squared distance to each sphere's centre below its squared radius, the
        /// first such cascade; the count when none) and how close the point lies to the sphere that decides it, relative.</summary>
        (int Index, double Margin) CascadeIndex(double[] world)
        {
            double margin = double.MaxValue;
            for (int i = 0; i < _count; i++)
            {
                double d2 = Enumerable.Range(0, 3).Sum(c => Math.Pow(world[c] - Centre(i)[c], 2)), r2 = Radius(i) * Radius(i);
                margin = Math.Min(margin, Math.Abs(d2 - r2) / r2);
                if (d2 < r2) return (i, margin);
            }
            return (_count, margin);
        }

        double[] WorldAt(int p)
        {
            double[] world = PipelinePassRun.Mul(_clipToWorld,
                new[] { (p % _lit.Width + 0.5) / _lit.Width * 2 - 1, 1 - (p / _lit.Width + 0.5) / _lit.Height * 2, _depth[p], 1.0 });
            return world.Take(3).Select(x => x / world[3]).ToArray();
        }

        [Test]
        public void TheCascadeEachPixelSamples_IsUrpsComputeCascadeIndex()
        {
            var perCascade = new int[_count + 1];
            int compared = 0, differ = 0, nearSphere = 0;
            string first = null;
            foreach (int p in _chosen)
            {
                var (cpu, margin) = CascadeIndex(WorldAt(p));
                // A point within 1e-4 of a sphere's squared radius (about 0.15 mm at these radii) may fall either side
                // after the depth's float32 rounding: left out.
                if (margin < 1e-4) { nearSphere++; continue; }
                int gpu = (Shadowed(_bits[0], p) ? 1 : 0) + (Shadowed(_bits[1], p) ? 2 : 0);
                compared++;
                perCascade[cpu]++;
                if (gpu != cpu) { differ++; first ??= $"pixel ({p % _lit.Width}, {p / _lit.Width}): GPU cascade {gpu}, ComputeCascadeIndex {cpu}"; }
            }
            TestContext.Out.WriteLine($"{_count} cascades: {compared} sunlit pixels compared ({nearSphere} within 1e-4 of a sphere left out); " +
                                      $"per ComputeCascadeIndex {string.Join(", ", perCascade.Select((n, i) => $"{i}: {n}"))}; GPU differs at {differ}" +
                                      (first != null ? "; first " + first : ""));
            Assert.That(perCascade.Count(n => n >= compared / 100), Is.GreaterThanOrEqualTo(2), "the terrain spans two cascades or more");
            Assert.That(perCascade[_count], Is.Zero, "a pixel within the shadow distance outside every sphere");
            Assert.That(differ, Is.Zero, "pixels whose cascade on the GPU is not ComputeCascadeIndex's");
        }

        [Test]
        public void EachUsedTile_IsTheShadowCastersDepthFromTheSun_AndNothingIsDefaulted()
        {
            int tile = _cascades.GetProperty("tile").GetInt32();
            Assert.That((_cascades.GetProperty("width").GetInt32(), _cascades.GetProperty("height").GetInt32(), tile),
                Is.EqualTo(_count == 2 ? (2048, 1024, 1024) : (2048, 2048, 1024)), "URP's atlas and tile for the cascade count");
            var used = new HashSet<int>(_chosen.Select(p => CascadeIndex(WorldAt(p)).Index));
            foreach (int i in used)
                PipelinePassRun.AssertShadowMapWritten(_out, $"cascade_map_{i}.f32", tile, _cascades.GetProperty("texels")[i].GetDouble(), $"cascade {i}'s tile");
            JsonElement m = PipelinePassRun.Manifest(_out, "lit_cascades");
            Assert.That(PipelinePassRun.Strings(m.GetProperty("filled")), Does.Contain("LightShadows._CascadeShadowSplitSphereRadii")
                .And.Contain("LightShadows._CascadeShadowSplitSpheres0").And.Contain("_MainLightShadowmapTexture"));
            Assert.That(PipelinePassRun.Strings(m.GetProperty("defaulted_read")), Is.Empty, "a member ForwardLit reads was left to its default");
            for (int i = 0; i < _count; i++)
                Assert.That(PipelinePassRun.Strings(PipelinePassRun.Manifest(_out, $"cascade_map_{i}").GetProperty("defaulted_read")), Is.Empty);
        }

        [Test]
        public void TheRidgesShadow_FallsWhereACpuRayTowardTheSunSays()
        {
            // Each pixel's cascade sets its edge margin and its rays' start, as PipelinePassShadowTests sets them for one
            // cascade: 3 of that cascade's texels across the light, over N.L >= MinNDotL; rays start 2 texels out.
            var samples = new List<PipelinePassRun.ShadowSample>();
            double texel = 0, edge = 0;
            foreach (var cascade in _chosen.GroupBy(p => CascadeIndex(WorldAt(p)).Index))
            {
                double t = _cascades.GetProperty("texels")[cascade.Key].GetDouble();
                samples.AddRange(PipelinePassRun.ShadowSamples(_out, "lit_cascades_depth.f32", _cascades, _sun, _lit.Width, _lit.Height,
                    cascade, 2 * t, 3 * t / MinNDotL, p => Shadowed(_lit, p)));
                TestContext.Out.WriteLine($"cascade {cascade.Key}: {cascade.Count()} sampled pixels, texel {t:G3} world units");
                (texel, edge) = (Math.Max(texel, t), Math.Max(edge, 3 * t / MinNDotL));
            }
            PipelinePassRun.AssertShadowAgreement(samples, edge, texel, $"URP's shadow, {_count} cascades");
            double worstAmbient = samples.Where(s => s.Gpu).Select(s => Enumerable.Range(0, 3)
                .Max(c => Math.Abs(_lit.Rgba[4 * s.Pixel + c] / 255.0 - _albedo[c] * _ambient))).DefaultIfEmpty(double.NaN).Max();
            TestContext.Out.WriteLine($"shadowed pixels' largest |colour - albedo x ambient| {worstAmbient * 255:F2}/255");
            Assert.That(worstAmbient, Is.LessThanOrEqualTo(Quantum), "a shadowed pixel keeps the ambient term only");
        }
    }
}
