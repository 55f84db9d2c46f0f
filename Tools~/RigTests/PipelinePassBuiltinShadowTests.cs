// Built-in's directional shadow as Built-in draws it in Forward on desktop (Tools~/rig/pipeline_pass.py, --only
// builtin_lit_shadows): the Built-in ShadowCaster pass drawn from the sun into a 2048^2 map (unity_LightShadowBias),
// the same pass drawn from the camera into the depth texture, the screen-space collect (unity_WorldToShadow[0], a
// comparison under reversed depth) into _ShadowMapTexture, then ForwardBase's SHADOWS_SCREEN variant (DXC's SPIR-V:
// glslang cannot compile a DX9 sampler2D lookup) sampling it at the pixel. The shadow's place is checked against Core
// as PipelinePassShadowTests checks URP's (PipelinePassRun.ShadowSamples / AssertShadowAgreement). Fails, never skips.
using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.Json;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    [TestFixture, Parallelizable(ParallelScope.Self)]
    public class PipelinePassBuiltinShadowTests
    {
        /// <summary>The shadowed frame: gt pipeline_pass's shadow sun (12 degrees up, from +x), written out; normals: the
        /// same surface's world normals (URP's ForwardLit GT_DEBUG_NORMALS, which Built-in's ForwardBase matches).</summary>
        static readonly string[] Scene = { "--only", "builtin_lit_shadows", "--only", "normals", "--shadow-sun-elevation", "12",
                                           "--shadow-sun-azimuth", "90", "--light-color", "1,0.96,0.9" };
        const double MinNDotL = 0.25, Quantum = 2.0 / 255.0;

        string _out;
        RigPng _lit, _normals;
        JsonElement _shadow;
        double[] _albedo, _sun, _light;
        double _ambient, _texel, _edge;
        List<int> _covered;
        List<PipelinePassRun.ShadowSample> _samples;

        [OneTimeSetUp]
        public void Draw()
        {
            (_out, _) = PipelinePassRun.Draw("pipeline_pass.py", "rigtests-pipeline-pass-builtin-shadow", Scene);
            _lit = RigPng.Read(Path.Combine(_out, "builtin_lit_shadows.png"));
            _normals = RigPng.Read(Path.Combine(_out, "normals.png"));
            _shadow = JsonDocument.Parse(File.ReadAllText(Path.Combine(_out, "shadow.json"))).RootElement;
            JsonElement m = PipelinePassRun.Manifest(_out, "builtin_lit_shadows");
            _sun = PipelinePassRun.Doubles(m.GetProperty("sun"));
            _light = PipelinePassRun.Doubles(m.GetProperty("light_color"));
            (_albedo, _ambient) = PipelinePassRun.Shading();
            _covered = PipelinePassRun.Covered(_lit);
            _texel = _shadow.GetProperty("texel").GetDouble();
            // How far the map may move an edge on the receiver, across the light: point sampling (half a texel either way,
            // 1) and the casters' depth bias (1 texel along the light, which moves an edge by up to 1 / tan(12 degrees)
            // texels on the ground but not its outline in the light's view), 1 more for the collect's screen-space
            // position; stretched by 1 / N.L up to 1 / MinNDotL = 4: 3 texels x 4, as for URP. Rays start 2 texels out.
            _edge = 3 * _texel / MinNDotL;
            int w = _lit.Width;
            var chosen = _covered.Where(p => p % w % 3 == 0 && p / w % 3 == 0 && NDotL(p) >= MinNDotL);
            _samples = PipelinePassRun.ShadowSamples(_out, "builtin_lit_shadows_depth.f32", _shadow, _sun, _lit.Width, _lit.Height, chosen,
                2 * _texel, _edge, p => DirectShare(p) < 0.5 * NDotL(p));
        }


        double NDotL(int p) => PipelinePassRun.NormalsViewDot(_normals, p, _sun);

        /// <summary>The light's share at the pixel over albedo x light: N.L unshadowed, 0 in shadow.</summary>
        double DirectShare(int p) =>
            Enumerable.Range(0, 3).Average(c => (_lit.Rgba[4 * p + c] / 255.0 - _albedo[c] * _ambient) / (_albedo[c] * _light[c]));

        [Test]
        public void TheScreenSpaceShadow_IsCollectedFromTheCastersMapAndTheCamerasDepth_ForwardBaseFromDxc()
        {
            PipelinePassRun.AssertShadowMapWritten(_out, "builtin_shadow_map.f32", _shadow.GetProperty("resolution").GetInt32(), _texel, "shadow map");
            // The depth texture pass (glslang's SPIR-V) and ForwardBase (DXC's) tessellate and place the same surface: the
            // collect reads the receiver's own depth, to float rounding (the two compilers order the arithmetic apart).
            byte[] cameraDepth = File.ReadAllBytes(Path.Combine(_out, "builtin_camera_depth.f32"));
            byte[] forwardDepth = File.ReadAllBytes(Path.Combine(_out, "builtin_lit_shadows_depth.f32"));
            Assert.That(cameraDepth.Length, Is.EqualTo(4 * _lit.Width * _lit.Height));
            var pixels = Enumerable.Range(0, cameraDepth.Length / 4).Select(i => (Camera: BitConverter.ToSingle(cameraDepth, 4 * i), Forward: BitConverter.ToSingle(forwardDepth, 4 * i))).ToList();
            int coverageDiffers = pixels.Count(d => (d.Camera > 0) != (d.Forward > 0));
            int differ = pixels.Count(d => d.Camera != d.Forward);
            double largest = pixels.Where(d => d.Camera > 0 && d.Forward > 0).Max(d => Math.Abs(d.Camera - d.Forward) / d.Forward);
            TestContext.Out.WriteLine($"_CameraDepthTexture vs ForwardBase's depth: {differ} of {pixels.Count} pixels differ, coverage at {coverageDiffers}, " +
                                      $"largest relative difference {largest:G3}");
            Assert.That(coverageDiffers, Is.Zero, "the depth texture covers ForwardBase's pixels");
            Assert.That(largest, Is.LessThan(1e-5), "the depth texture holds ForwardBase's depth (float32 rounding)");
            foreach (string picture in new[] { "builtin_shadow_map", "builtin_camera_depth", "builtin_lit_shadows" })
                Assert.That(PipelinePassRun.Strings(PipelinePassRun.Manifest(_out, picture).GetProperty("defaulted_read")), Is.Empty,
                    picture + ": a member some stage reads was left to its default");
            JsonElement caster = PipelinePassRun.Manifest(_out, "builtin_shadow_map");
            Assert.That(PipelinePassRun.Strings(caster.GetProperty("reads").GetProperty("tese")), Does.Contain("$Global.unity_LightShadowBias"),
                "the caster's domain stage applies UnityApplyLinearShadowBias");
            Assert.That(string.Join(" ", PipelinePassRun.Strings(caster.GetProperty("state"))), Does.Contain("--color-mask 0"));
            JsonElement lit = PipelinePassRun.Manifest(_out, "builtin_lit_shadows");
            Assert.That(lit.GetProperty("compiler").GetString(), Is.EqualTo("dxc"));
            JsonElement image = lit.GetProperty("bindings").EnumerateArray().Single(b => b.GetProperty("name").GetString() == "_ShadowMapTexture.t");
            Assert.That(image.GetProperty("file").GetString(), Does.EndWith("builtin_screen_shadow.f32"), "the collected screen-space shadow");
        }

        [Test]
        public void NoPixelIsNaNOrInf_AndAShadowedPixelKeepsTheAmbientOnly()
        {
            double[] lo = Enumerable.Range(0, 3).Select(c => _albedo[c] * _ambient - Quantum).ToArray();
            double[] hi = Enumerable.Range(0, 3).Select(c => _albedo[c] * (_ambient + _light[c]) + Quantum).ToArray();
            PipelinePassRun.AssertWithinBounds(_lit, _covered, lo, hi, PipelinePassRun.IsSky, "albedo x (ambient .. ambient + light)");
            var shadowed = _samples.Where(s => s.Gpu).ToList();
            double worstShadowed = shadowed.Select(s => Enumerable.Range(0, 3).Max(c => Math.Abs(_lit.Rgba[4 * s.Pixel + c] / 255.0 - _albedo[c] * _ambient)))
                .DefaultIfEmpty(double.NaN).Max();
            var lit = _samples.Where(s => !s.Gpu).ToList();
            double worstLit = lit.Select(s => Enumerable.Range(0, 3).Max(c =>
                Math.Abs(_lit.Rgba[4 * s.Pixel + c] / 255.0 - _albedo[c] * (_ambient + _light[c] * NDotL(s.Pixel))))).DefaultIfEmpty(double.NaN).Max();
            double meanLit = lit.Average(s => Enumerable.Range(0, 3).Average(c => _lit.Rgba[4 * s.Pixel + c] / 255.0));
            double meanShadowed = shadowed.Select(s => Enumerable.Range(0, 3).Average(c => _lit.Rgba[4 * s.Pixel + c] / 255.0)).DefaultIfEmpty(double.NaN).Average();
            TestContext.Out.WriteLine($"{shadowed.Count} of {_samples.Count} sampled sunlit pixels shadowed, mean {meanShadowed:F3}, largest |colour - albedo x ambient| " +
                                      $"{worstShadowed * 255:F2}/255; lit mean {meanLit:F3}, largest |colour - Lambert| {worstLit * 255:F2}/255");
            Assert.That(shadowed.Count, Is.GreaterThan(_samples.Count / 20), "the ridges shadow 5% of the sunlit terrain or more");
            Assert.That(worstShadowed, Is.LessThanOrEqualTo(Quantum), "a shadowed pixel keeps albedo x ambient only");
            Assert.That(worstLit, Is.LessThanOrEqualTo(3.0 / 255), "a pixel the screen-space shadow leaves lit is Lambert's");
            Assert.That(meanShadowed, Is.InRange(0.05, 0.15), "shadowed slopes: albedo x ambient");
            Assert.That(meanLit, Is.InRange(0.20, 0.60), "sunlit slopes (N.L >= 0.25)");
        }

        [Test]
        public void TheRidgesShadow_FallsWhereACpuRayTowardTheSunSays()
        {
            PipelinePassRun.AssertShadowAgreement(_samples, _edge, _texel, "Built-in's screen-space shadow");
        }
    }
}
