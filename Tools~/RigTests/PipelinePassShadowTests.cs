// URP's main-light shadow in the rig's frame (pipeline_pass.py: ShadowCaster drawn from the sun into a
// 2048^2 map, ForwardLit's _MAIN_LIGHT_SHADOWS variant sampling it with the LightShadows block URP
// fills). The shadow's place is checked against Core: each covered pixel's world position, recovered
// from the forward pass's own depth, casts a ray toward the sun on TerrainSurfaceQuery's exact surface.
using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.Json;
using System.Threading.Tasks;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    public partial class PipelinePassGpuTests
    {
        RigPng _litShadows;
        JsonElement _shadow;
        double[] _shadowSun;     // the shadowed frame's sun (Scene: 12 degrees up, from +x)
        const double MinNDotL = 0.25;   // the sunlit pixels graded: N.L at least this
        List<PipelinePassRun.ShadowSample> _samples;
        double _edgeTolerance;   // world units

        /// <summary>The picture's colour above the ambient term, averaged over the channels: the light's share.</summary>
        double DirectShare(RigPng png, int p) => Enumerable.Range(0, 3).Average(c => Channel(png, p, c) - _albedo[c] * _ambient);

        /// <summary>N.L of the shadowed frame's sun, N from the normals view (the same surface).</summary>
        double ShadowNDotL(int p) => PipelinePassRun.NormalsViewDot(_normals, p, _shadowSun);

        /// <summary>Lambert's colour channel without a shadow (TheLitPicture_IsLambertOfThePassesOwnNormals holds it within 3/255).</summary>
        double Unshadowed(int p, int c) => _albedo[c] * (_ambient + _light[c] * Math.Max(0, ShadowNDotL(p)));

        /// <summary>Draws nothing: reads what the fixture's run drew and classifies the sampled pixels (PipelinePassRun.ShadowSamples).</summary>
        void LoadShadowSamples()
        {
            if (_samples != null) return;
            _litShadows = RigPng.Read(Path.Combine(_out, "lit_shadows.png"));
            _shadow = JsonDocument.Parse(File.ReadAllText(Path.Combine(_out, "shadow.json"))).RootElement;
            _shadowSun = PipelinePassRun.Doubles(Manifest("lit_shadows").GetProperty("sun"));
            double texel = _shadow.GetProperty("texel").GetDouble();
            // How far the map may move an edge on the receiver (world units): point sampling (half a texel
            // either way, 1) and URP's depth and normal bias (1 texel each along the light and the
            // normal, 2), across the light; on a receiver lit at N.L that stretches by 1 / N.L, at most
            // 1 / MinNDotL = 4: (1 + 2) * 4 = 12 texels. Pixels whose CPU verdict changes within that
            // distance are edge pixels, left out of the agreement. Rays start 2 texels out, past URP's bias.
            _edgeTolerance = 3 * texel / MinNDotL;
            // Every third covered pixel in x and y (about 9,000), those the sun lights without the map (N.L >= MinNDotL).
            int w = _lit.Width;
            var chosen = _covered.Where(p => p % w % 3 == 0 && p / w % 3 == 0 && ShadowNDotL(p) >= MinNDotL);
            _samples = PipelinePassRun.ShadowSamples(_out, "lit_shadows_depth.f32", _shadow, _shadowSun, _lit.Width, _lit.Height, chosen,
                2 * texel, _edgeTolerance,
                p => DirectShare(_litShadows, p) < 0.5 * Enumerable.Range(0, 3).Average(c => Unshadowed(p, c) - _albedo[c] * _ambient));
        }

        [Test]
        public void TheShadowMap_IsTheShadowCastersDepthFromTheSun_BoundByName()
        {
            LoadShadowSamples();
            // The culling sphere holds the camera's frustum to the shadow distance (3 world units), the terrain is 1
            // across and seen from 12 degrees: about 1% of the map.
            PipelinePassRun.AssertShadowMapWritten(_out, "shadow_map.f32", _shadow.GetProperty("resolution").GetInt32(),
                _shadow.GetProperty("texel").GetDouble(), "shadow map");
            JsonElement m = Manifest("lit_shadows");
            JsonElement image = m.GetProperty("bindings").EnumerateArray().Single(b => b.GetProperty("name").GetString() == "_MainLightShadowmapTexture");
            Assert.That(image.GetProperty("file").GetString(), Does.EndWith("shadow_map_texels.f32"), "the map the ShadowCaster drew, rows in texture order");
            Assert.That(Strings(m.GetProperty("filled")), Does.Contain("_MainLightShadowmapTexture")
                .And.Contain("LightShadows._MainLightWorldToShadow").And.Contain("LightShadows._MainLightShadowParams"));
            // URP's sampler_LinearClampCompare: a comparison under reversed depth (lit when the receiver's
            // depth is at or above the map's), point-filtered (lavapipe lists no linear filtering of D32).
            Assert.That(Strings(m.GetProperty("defaults")), Does.Contain("sampler_LinearClampCompare=point:clamp:compare-gequal"));
            Assert.That(Strings(Manifest("shadow_map").GetProperty("state")), Does.Contain("--color-mask").And.Contain("0"),
                "ShadowCaster's ColorMask 0, read from the ShaderLab pass");
        }

        [Test]
        public void NoShadowedPixelIsNaNOrInf_AndShadowRemovesTheLightsShareOnly()
        {
            LoadShadowSamples();
            // Lambert's bounds on every covered pixel (a NaN reads 0, an Inf 1), nothing drawn outside.
            var covered = new HashSet<int>(_covered);
            int outOfBounds = 0, drawnOutside = 0;
            for (int p = 0; p < _litShadows.Width * _litShadows.Height; p++)
            {
                if (!covered.Contains(p)) { drawnOutside += Enumerable.Range(0, 3).All(c => IsSky(_litShadows, p, c)) ? 0 : 1; continue; }
                for (int c = 0; c < 3; c++)
                {
                    double v = Channel(_litShadows, p, c);
                    if (v < _albedo[c] * _ambient - Quantum || v > _albedo[c] * (_ambient + _light[c]) + Quantum) outOfBounds++;
                }
            }
            // Where the GPU shadows a pixel, what is left is the ambient term (hard shadow, strength 1):
            // Lambert's colour minus the light's share albedo * light * N.L.
            var shadowed = _samples.Where(s => s.Gpu).ToList();
            double worstAmbient = shadowed.Select(s => Enumerable.Range(0, 3).Max(c => Math.Abs(Channel(_litShadows, s.Pixel, c) - _albedo[c] * _ambient)))
                .DefaultIfEmpty(double.NaN).Max();
            // and elsewhere the picture is Lambert's (3/255: the normals view's and the colour's 8 bits).
            int litChanged = _samples.Where(s => !s.Gpu).Count(s => Enumerable.Range(0, 3).Any(c => Math.Abs(Channel(_litShadows, s.Pixel, c) - Unshadowed(s.Pixel, c)) > 3.0 / 255));
            TestContext.Out.WriteLine($"lit_shadows: channels outside Lambert's bounds {outOfBounds}, drawn outside {drawnOutside}; " +
                                      $"{shadowed.Count} of {_samples.Count} sampled sunlit pixels shadowed, largest |shadowed - albedo * ambient| {worstAmbient * 255:F2}/255; " +
                                      $"unshadowed pixels off Lambert by more than 3/255: {litChanged}");
            Assert.That(outOfBounds, Is.Zero, "channels outside albedo * ambient .. albedo * (ambient + light)");
            Assert.That(drawnOutside, Is.Zero);
            Assert.That(shadowed.Count, Is.GreaterThan(_samples.Count / 20), "the ridges shadow 5% of the sunlit terrain or more");
            Assert.That(worstAmbient, Is.LessThanOrEqualTo(Quantum), "a shadowed pixel keeps the ambient term only");
            Assert.That(litChanged, Is.Zero, "a pixel the map does not shadow is Lambert's, unshadowed");
        }

        [Test]
        public void TheRidgesShadow_FallsWhereACpuRayTowardTheSunSays()
        {
            LoadShadowSamples();
            PipelinePassRun.AssertShadowAgreement(_samples, _edgeTolerance, _shadow.GetProperty("texel").GetDouble(), "URP's shadow");
        }
    }
}
