using System;
using System.Collections.Generic;
using System.Linq;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>
    /// Which view chooses the tessellation in the passes no harness draws (Unity's shadow maps, HDRP):
    /// compiled against Unity's real libraries as each pass would be (Tools~/rig/shaderreads.py), the
    /// globals the code reads. Every pass of a pipeline must tessellate from the camera whose frame it
    /// is part of, so a shadow caster is the surface the camera draws (a caster tessellated in the
    /// light's clip space with the camera's pixel count is another surface: acne and leaks); the
    /// culling stays in the pass's own view, or terrain off screen would cast no shadow into it.
    /// What a Unity editor would show (the shadow itself) is not drawn here.
    /// </summary>
    [TestFixture, Parallelizable(ParallelScope.Self)]
    public class TessellationViewTests
    {
        /// <summary>What the camera's view is read from, per pipeline. URP and Built-in: the renderer's
        /// per-camera constants (their own view is the light's in a shadow pass); HDRP: its camera
        /// constants, which its shadow passes keep (camera-relative: the object matrix and the camera
        /// position make the object point relative first).</summary>
        static readonly Dictionary<string, string[]> CameraView = new Dictionary<string, string[]>
        {
            ["URP"] = new[] { "_GtTessObjectToClip", "_GtTessScreenSize" },
            ["Builtin"] = new[] { "_GtTessObjectToClip", "_GtTessScreenSize" },
            ["HDRP"] = new[] { "_CameraViewProjMatrix", "_ScreenSize", "_GtObjectToWorld", "_WorldSpaceCameraPos_Internal" },
        };

        /// <summary>The view a pass draws from: the light's in a shadow pass.</summary>
        static readonly Dictionary<string, string> PassView = new Dictionary<string, string>
        {
            ["URP"] = "unity_MatrixVP", ["Builtin"] = "unity_MatrixVP", ["HDRP"] = "_ViewProjMatrix",
        };

        /// <summary>The terrain's own data (TerrainParams and the grid's buffers): not a view.</summary>
        static readonly HashSet<string> TerrainData = new HashSet<string>(
            TerrainParams.PropertyNames.Concat(new[] { "_ControlPoints", "_Regions", "_GridLines", "_NoiseCells" }));

        static string Probe => PackageRoot.Combine("Tools~", "RigTests", "TessellationViewProbe.hlsl");

        /// <summary>The probe's two functions (the factors' pixel scale, a vertex's octave count) with
        /// one pipeline's adapter as one pass defines it: what they read besides the terrain's data.</summary>
        [TestCase("URP", "FORWARD", null)]
        [TestCase("URP", "DEPTH", null)]
        [TestCase("URP", "DEPTH_NORMALS", null)]
        [TestCase("URP", "SHADOWCASTER", null)]
        [TestCase("URP", "SHADOWCASTER", "_CASTING_PUNCTUAL_LIGHT_SHADOW")]
        [TestCase("URP", "SCENE_SELECTION", null)]
        [TestCase("URP", "SCENE_PICKING", null)]
        [TestCase("HDRP", "FORWARD", null)]
        [TestCase("HDRP", "DEPTH_NORMALS", null)]
        [TestCase("HDRP", "SHADOWCASTER", null)]
        [TestCase("HDRP", "SCENE_SELECTION", null)]
        [TestCase("HDRP", "SCENE_PICKING", null)]
        [TestCase("Builtin", "FORWARD", null)]
        [TestCase("Builtin", "SHADOWCASTER", null)]
        public void EveryPassTessellatesFromTheCamerasView(string pipeline, string pass, string keyword)
        {
            var args = new List<string> { "--probe", Probe, "--stage", "vert", "--entry", "TessellationViewProbe",
                "--define", "PROBE_" + pipeline.ToUpperInvariant(), "--define", "GT_PASS_" + pass,
                "--define", "GT_NOISE", "--define", "GT_RANGE_ORIGIN" };
            if (keyword != null) args.AddRange(new[] { "--define", keyword });
            var view = Reads(args.ToArray()).Where(n => !TerrainData.Contains(n)).ToList();
            TestContext.Out.WriteLine($"{pipeline} {pass} {keyword}: reads {string.Join(" ", view)}");
            Assert.That(view, Is.EquivalentTo(CameraView[pipeline]),
                $"{pipeline} GT_PASS_{pass} {keyword}: the factors and octave counts must read the camera's view, and only it");
        }

        /// <summary>The real hull stage of each tessellated ShadowCaster: factors from the camera's view,
        /// culling in the light's (the pass's own view matrix is still read).</summary>
        [TestCase("URP", "sub0 ShadowCaster")]
        [TestCase("HDRP", "sub2 ShadowCaster")]
        [TestCase("Builtin", "sub4 ShadowCaster")]
        public void ShadowCasterHullCullsInTheLightsViewAndTessellatesInTheCamerasView(string pipeline, string pass)
        {
            var reads = Reads("--pass", pass, "--stage", "tesc", "--entry", "hull_shader");
            TestContext.Out.WriteLine($"{pipeline} {pass} hull: reads {string.Join(" ", reads)}");
            Assert.That(reads, Is.SupersetOf(CameraView[pipeline]), pass + ": the factors from the camera's view");
            Assert.That(reads, Does.Contain(PassView[pipeline]), pass + ": the culling in the pass's (the light's) view");
        }

        /// <summary>The globals Tools~/rig/shaderreads.py reports.</summary>
        internal static List<string> Reads(params string[] args) =>
            Run(args).First(l => l.StartsWith("reads:")).Substring("reads:".Length).Split(' ', StringSplitOptions.RemoveEmptyEntries).ToList();

        /// <summary>Tools~/rig/shaderreads.py's output lines; a program that does not compile fails the test.</summary>
        internal static string[] Run(params string[] args) =>
            ReadbackRun.Exec("python3", new[] { PackageRoot.Combine("Tools~", "rig", "shaderreads.py") }.Concat(args).ToArray(), null)
                .Split('\n').Select(l => l.TrimEnd('\r')).ToArray();
    }
}
