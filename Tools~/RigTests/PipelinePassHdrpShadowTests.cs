// HDRP's directional shadow from the package's own ShadowCaster (Tools~/rig/pipeline_pass_hdrp.py, --only hdrp_lit_shadows):
// the HDRP ShadowCaster pass drawn from the sun into a 2048^2 cascade atlas with HDRP 14's matrices, _ZClip 0 (depth
// clamp) and depth bias (1, 2.5), then ForwardOnly's SHADOW_LOW variant over the prepass's depth sampling it through
// HDRP's own cascade code (split sphere, normal bias, PCF tent 5x5). The shadow's place is checked against Core as
// PipelinePassShadowTests checks URP's (PipelinePassRun.ShadowSamples / AssertShadowAgreement). Fails, never skips.
using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.Json;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    [TestFixture, Parallelizable(ParallelScope.Self)]
    public class PipelinePassHdrpShadowTests
    {
        /// <summary>The shadowed frame: gt pipeline_pass's shadow sun (12 degrees up, from +x), written out.</summary>
        static readonly string[] Scene = { "--only", "hdrp_lit_shadows", "--shadow-sun-elevation", "12", "--shadow-sun-azimuth", "90",
                                           "--light-color", "1,0.96,0.9" };
        const double Lux = 100000, Ev100 = 15, SkyShare = 0.2, MinNDotL = 0.25, Quantum = 2.0 / 255.0;

        string _out;
        RigPng _lit, _normalBuffer;
        JsonElement _shadow;
        double[] _albedo, _sun, _light;
        double _scale, _texel, _edge;
        List<int> _covered;
        List<PipelinePassRun.ShadowSample> _samples;

        [OneTimeSetUp]
        public void Draw()
        {
            (_out, _) = PipelinePassRun.Draw("pipeline_pass_hdrp.py", "rigtests-pipeline-pass-hdrp-shadow", Scene);
            _lit = RigPng.Read(Path.Combine(_out, "hdrp_lit_shadows.png"));
            _normalBuffer = RigPng.Read(Path.Combine(_out, "hdrp_depth.png"));
            _shadow = JsonDocument.Parse(File.ReadAllText(Path.Combine(_out, "hdrp_shadow.json"))).RootElement;
            JsonElement m = PipelinePassRun.Manifest(_out, "hdrp_lit_shadows");
            _sun = PipelinePassRun.Doubles(m.GetProperty("sun"));
            _light = PipelinePassRun.Doubles(m.GetProperty("light_color"));
            _albedo = PipelinePassRun.Shading().Albedo;
            _scale = Lux / Math.PI / (1.2 * Math.Pow(2, Ev100));
            _covered = PipelinePassRun.Covered(_lit);
            _texel = _shadow.GetProperty("texel").GetDouble();
            // How far HDRP's map may move an edge on the receiver, across the light: point sampling (half a texel either
            // way, 1) and the normal bias (0.75 x sqrt(2) texels, 1.06); the slope-scaled depth bias moves the casters'
            // depth, not their outline in the light's view, and the 5x5 tent's penumbra is split at its middle: 3 texels
            // as for URP, stretched by 1 / N.L up to 1 / MinNDotL = 4. Rays start 3 texels out, past HDRP's bias.
            _edge = 3 * _texel / MinNDotL;
            int w = _lit.Width;
            var chosen = _covered.Where(p => p % w % 3 == 0 && p / w % 3 == 0 && NDotL(p) >= MinNDotL);
            // GPU verdict: the light's share left at the pixel is under half of Lambert's (the tent's penumbra splits at 0.5).
            _samples = PipelinePassRun.ShadowSamples(_out, "hdrp_lit_shadows_depth.f32", _shadow, _sun, _lit.Width, _lit.Height, chosen,
                3 * _texel, _edge, p => DirectShare(p) < 0.5 * NDotL(p));
        }


        double NDotL(int p) => PipelinePassRun.OctahedralNormal(_normalBuffer, p).Select((n, c) => n * _sun[c]).Sum();

        /// <summary>The light's share at the pixel over albedo x light, after HDRP's exposure: N.L unshadowed, 0 in shadow.</summary>
        double DirectShare(int p) =>
            Enumerable.Range(0, 3).Average(c => (_lit.Rgba[4 * p + c] / 255.0 / _scale - _albedo[c] * SkyShare) / (_albedo[c] * _light[c]));

        [Test]
        public void TheCascadeAtlas_IsTheShadowCastersDepthFromTheSun_WithHdrpsBiasAndZClip()
        {
            int n = _shadow.GetProperty("resolution").GetInt32();
            PipelinePassRun.AssertShadowMapWritten(_out, "hdrp_shadow_map.f32", n, _texel, "cascade atlas");
            string caster = string.Join(" ", PipelinePassRun.Strings(PipelinePassRun.Manifest(_out, "hdrp_shadow_map").GetProperty("state")));
            Assert.That(caster, Does.Contain("--zclip off").And.Contain("--color-mask 0"), "ShadowCaster's ZClip [_ZClip] with HDRP's _ZClip 0, ColorMask 0");
            string log = File.ReadAllText(Path.Combine(_out, "hdrp_shadow_map", "harness.log"));
            Assert.That(log, Does.Contain("depth_bias 1.000000 2.500000"), "HDRP's SetGlobalDepthBias(1, slopeBias 5 x 0.5)");
            JsonElement lit = PipelinePassRun.Manifest(_out, "hdrp_lit_shadows");
            Assert.That(PipelinePassRun.Strings(lit.GetProperty("filled")), Has.Some.StartWith($"_ShadowmapCascadeAtlas=D32 {n}x{n}"));
            Assert.That(PipelinePassRun.Strings(lit.GetProperty("defaulted_read")), Is.Empty, "a member ForwardOnly reads was left to its default");
            Assert.That(PipelinePassRun.Strings(PipelinePassRun.Manifest(_out, "hdrp_shadow_map").GetProperty("defaulted_read")), Is.Empty,
                "a member ShadowCaster reads was left to its default");
        }

        [Test]
        public void NoPixelIsNaNOrInf_AndAShadowedPixelKeepsTheSkyOnly()
        {
            double[] lo = Enumerable.Range(0, 3).Select(c => _scale * _albedo[c] * SkyShare - Quantum).ToArray();
            double[] hi = Enumerable.Range(0, 3).Select(c => _scale * _albedo[c] * (SkyShare + _light[c]) + Quantum).ToArray();
            PipelinePassRun.AssertWithinBounds(_lit, _covered, lo, hi, PipelinePassRun.IsSky, "scale x albedo x (sky .. sky + light)");
            // Away from edges a shadowed pixel is the sky probe's colour alone (the tent's 25 taps all in shadow).
            int shadowed = _samples.Count(s => s.Gpu);
            var away = _samples.Where(s => s.Gpu && s.Cpu && !s.NearEdge).ToList();
            double worst = away.Select(s => Enumerable.Range(0, 3).Max(c => Math.Abs(_lit.Rgba[4 * s.Pixel + c] / 255.0 - _scale * _albedo[c] * SkyShare)))
                .DefaultIfEmpty(double.NaN).Max();
            TestContext.Out.WriteLine($"{shadowed} of {_samples.Count} sampled sunlit pixels shadowed; {away.Count} away from edges: " +
                                      $"largest |colour - scale x albedo x sky| {worst * 255:F2}/255");
            Assert.That(shadowed, Is.GreaterThan(_samples.Count / 20), "the ridges shadow 5% of the sunlit terrain or more");
            Assert.That(away, Is.Not.Empty, "shadowed samples away from edges");
            Assert.That(worst, Is.LessThanOrEqualTo(Quantum), "a shadowed pixel away from edges keeps the sky probe only");
        }

        [Test]
        public void TheRidgesShadow_FallsWhereACpuRayTowardTheSunSays()
        {
            PipelinePassRun.AssertShadowAgreement(_samples, _edge, _texel, "HDRP's shadow");
        }
    }
}
