// URP's ForwardLit and Built-in's ForwardBase fog variants (multi_compile_fog: FOG_LINEAR, FOG_EXP, FOG_EXP2) drawn
// by the harness with unity_FogParams and unity_FogColor as Unity sets them from RenderSettings (Tools~/rig/
// pipeline_pass.py's fog_values), each pixel held to the pipeline's fog formula at the pixel's depth, applied to the
// pipeline's unfogged picture.
using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.Json;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    [TestFixture, Parallelizable(ParallelScope.Self)]
    public class PipelinePassFogTests
    {
        static readonly string[] Scene = { "--only", "lit", "--only", "lit_fog_linear", "--only", "lit_fog_exp", "--only", "lit_fog_exp2",
            "--only", "builtin_lit", "--only", "builtin_fog_linear", "--only", "builtin_fog_exp", "--only", "builtin_fog_exp2" };

        string _out;
        RigPng _lit, _builtinLit;

        [OneTimeSetUp]
        public void Draw()
        {
            (_out, _) = PipelinePassRun.Draw("pipeline_pass.py", "rigtests-pipeline-pass-fog", Scene);
            _lit = RigPng.Read(Path.Combine(_out, "lit.png"));
            _builtinLit = RigPng.Read(Path.Combine(_out, "builtin_lit.png"));
        }

        /// <summary>URP 14's fog intensity (1: no fog) at nearToFarZ (ShaderVariablesFunctions.hlsl: InitializeInputDataFog
        /// takes the view depth minus the near plane, ComputeFogFactorZ0ToFar, ComputeFogIntensity; MixFogColor lerps
        /// from the fog colour to the colour by it). EXP and EXP2 both scale by params.x (density / sqrt(ln 2)).</summary>
        static double Intensity(string mode, double[] p, double z)
        {
            double Saturate(double x) => Math.Clamp(x, 0, 1);
            switch (mode)
            {
                case "lit_fog_linear": return Saturate(z * p[2] + p[3]);
                case "lit_fog_exp": return Saturate(Math.Pow(2, -(p[0] * z)));
                case "lit_fog_exp2": return Saturate(Math.Pow(2, -(p[0] * z) * (p[0] * z)));
                // Built-in (UnityCG.cginc UNITY_CALC_FOG_FACTOR_RAW): EXP scales by params.y (density / ln 2).
                case "builtin_fog_linear": return Saturate(z * p[2] + p[3]);
                case "builtin_fog_exp": return Saturate(Math.Pow(2, -(p[1] * z)));
                case "builtin_fog_exp2": return Saturate(Math.Pow(2, -(p[0] * z) * (p[0] * z)));
                default: throw new ArgumentException(mode);
            }
        }

        [TestCase("lit_fog_linear", "FOG_LINEAR")]
        [TestCase("lit_fog_exp", "FOG_EXP")]
        [TestCase("lit_fog_exp2", "FOG_EXP2")]
        [TestCase("builtin_fog_linear", "FOG_LINEAR")]
        [TestCase("builtin_fog_exp", "FOG_EXP")]
        [TestCase("builtin_fog_exp2", "FOG_EXP2")]
        public void TheFoggedPicture_IsTheLitPictureFoggedByThePipelinesFormula_AtEachPixelsDepth(string picture, string keyword)
        {
            bool builtin = picture.StartsWith("builtin_");
            RigPng lit = builtin ? _builtinLit : _lit;
            JsonElement m = PipelinePassRun.Manifest(_out, picture);
            Assert.That(m.GetProperty("variant").GetString(), Is.EqualTo(keyword));
            Assert.That(PipelinePassRun.Strings(m.GetProperty("defaulted_read")), Is.Empty, "a member some stage reads was left to its default");
            Assert.That(PipelinePassRun.Strings(m.GetProperty("reads").GetProperty("frag")), Is.SupersetOf(new[] { "$Global.unity_FogParams", "$Global.unity_FogColor" }));

            JsonElement view = JsonDocument.Parse(File.ReadAllText(Path.Combine(_out, picture + "_view.json"))).RootElement;
            double[] fogParams = PipelinePassRun.Doubles(view.GetProperty("fog").GetProperty("unity_FogParams"));
            double[] fogColor = PipelinePassRun.Doubles(view.GetProperty("fog").GetProperty("unity_FogColor"));
            double[,] clipToWorld = PipelinePassRun.Inverse(PipelinePassRun.Matrix(view.GetProperty("camera_view_proj")));
            double[,] worldToView = PipelinePassRun.Matrix(view.GetProperty("camera_view"));
            double near = view.GetProperty("near").GetDouble(), far = view.GetProperty("far").GetDouble();
            byte[] depth = File.ReadAllBytes(Path.Combine(_out, picture + "_depth.f32"));
            RigPng fogged = RigPng.Read(Path.Combine(_out, picture + ".png"));
            int w = fogged.Width, h = fogged.Height;
            Assert.That(depth.Length, Is.EqualTo(4 * w * h));

            var errors = new List<double>();
            double least = 1, most = 0;
            for (int p = 0; p < w * h; p++)
            {
                float d = BitConverter.ToSingle(depth, 4 * p);
                if (!(d > 0)) continue;
                double[] world = PipelinePassRun.Mul(clipToWorld, new[] { (p % w + 0.5) / w * 2 - 1, 1 - (p / w + 0.5) / h * 2, d, 1.0 });
                world = world.Select(x => x / world[3]).ToArray();
                double viewZ = -PipelinePassRun.Mul(worldToView, world)[2];
                // URP: view depth past the near plane. Built-in (UnityCG.cginc UNITY_Z_0_FAR_FROM_CLIPSPACE, reversed z):
                // clip z (= depth * clip w, w = view depth) remapped to [0, far] by _ProjectionParams' near and far.
                double z = builtin ? Math.Max((1 - d * viewZ / near) * far, 0) : Math.Max(viewZ - near, 0);
                double intensity = Intensity(picture, fogParams, z);
                least = Math.Min(least, intensity);
                most = Math.Max(most, intensity);
                for (int c = 0; c < 3; c++)
                {
                    double unfogged = lit.Rgba[4 * p + c] / 255.0;
                    errors.Add(Math.Abs(fogged.Rgba[4 * p + c] / 255.0 - (fogColor[c] + (unfogged - fogColor[c]) * intensity)));
                }
            }
            TestContext.Out.WriteLine($"{picture}: {errors.Count / 3} covered pixels, fog intensity {least:F3} .. {most:F3}");
            Assert.That(errors.Count / 3, Is.GreaterThan(w * h / 5), "the terrain covers a fifth of the picture or more");
            Assert.That(most - least, Is.GreaterThan(0.2), "the scene's fog varies across the terrain (a test of the distance, not a constant)");
            // Expected from the 8-bit unfogged picture: its rounding (0.5/255, scaled by the intensity) plus the fogged
            // picture's own (0.5/255); the view depth from float32 reversed depth is exact to ~1e-6 units.
            PipelinePassRun.AssertWithinEightBitSteps(errors, picture + " vs lerp(unity_FogColor, unfogged, the pipeline's intensity)");
        }
    }
}
