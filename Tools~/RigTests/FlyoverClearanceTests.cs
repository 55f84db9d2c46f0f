using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using GregoryTerrain.Samples.TerrainFlyover;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>
    /// The Terrain Fly-over sample's camera stays above the surface it flies over: its loop is walked
    /// frame by frame (every 0.1 degree) through <see cref="FlyoverPath"/>, the arithmetic
    /// FlyoverCamera runs, with the scene's own settings (the camera's clearance, loop, look-ahead and
    /// smoothing; the renderer's Transform, Terrain Size, Height Scale and noise; the material's noise
    /// keywords; the sample's grid asset), over the surface that GregoryTerrainRenderer.SampleHeight
    /// answers (Core's TerrainSurfaceQuery, every noise octave). Its height over the surface must never
    /// be below the stated clearance.
    /// </summary>
    [TestFixture]
    public class FlyoverClearanceTests
    {
        static string Sample(params string[] parts) => PackageRoot.Combine(new[] { "Samples~", "TerrainFlyover" }.Concat(parts).ToArray());

        /// <summary>The scene's objects by anchor (file ID): the text from its "--- !u!" line to the next.</summary>
        internal static Dictionary<string, string> SceneObjects(string text)
        {
            text = text.Replace("\r\n", "\n");
            var heads = Regex.Matches(text, @"^--- !u!\d+ &(-?\d+)\n", RegexOptions.Multiline).ToList();
            return heads.Select((m, k) => (m.Groups[1].Value, text.Substring(m.Index, (k + 1 < heads.Count ? heads[k + 1].Index : text.Length) - m.Index)))
                        .ToDictionary(x => x.Item1, x => x.Item2);
        }

        /// <summary>A field's value; "noise.amplitude" is the field of a struct written as a block under its name.</summary>
        static string Field(string obj, string name)
        {
            int dot = name.IndexOf('.');
            var m = dot < 0 ? Regex.Match(obj, "^  " + name + @": (.*)$", RegexOptions.Multiline)
                : Regex.Match(obj, "^  " + name.Substring(0, dot) + @":\n(?:    [^\n]*\n)*?    " + name.Substring(dot + 1) + @": (.*)$", RegexOptions.Multiline);
            Assert.That(m.Success, name + " not in the object:\n" + obj.Substring(0, Math.Min(obj.Length, 300)));
            return m.Groups[1].Value.Trim();
        }

        static double Number(string obj, string name) => double.Parse(Field(obj, name), NumberStyles.Float, CultureInfo.InvariantCulture);

        /// <summary>Components of an inline map "{x: 1, y: 2}" by key.</summary>
        static double Component(string obj, string name, string key)
        {
            var m = Regex.Match(Field(obj, name), @"\b" + key + @": (-?[\d.eE+-]+)");
            Assert.That(m.Success, $"{name}.{key}");
            return double.Parse(m.Groups[1].Value, NumberStyles.Float, CultureInfo.InvariantCulture);
        }

        static string Guid(string metaPath) =>
            Regex.Match(File.ReadAllText(metaPath), @"^guid: ([0-9a-f]{32})", RegexOptions.Multiline).Groups[1].Value;

        /// <summary>What the sample's scene says the flight and the terrain are.</summary>
        internal sealed class Flight
        {
            public double Clearance, LoopSeconds, LookAheadSeconds, SmoothSeconds;
            public double BaseY, ScaleY, HeightScale;
            public TerrainSurfaceQuery Surface;

            /// <summary>World y of the surface over unit-square point (x, y): base + Transform y scale * Height Scale * height.</summary>
            public double SurfaceY(double x, double y) => BaseY + ScaleY * HeightScale * Surface.SampleHeight(x, y);
        }

        internal static Flight ReadFlight()
        {
            var scene = SceneObjects(File.ReadAllText(Sample("Sample.unity")));
            string cameraGuid = Guid(Sample("FlyoverCamera.cs.meta")), rendererGuid = Guid(PackageRoot.Combine("Runtime", "GregoryTerrainRenderer.cs.meta"));
            string camera = scene.Values.Single(o => o.Contains("m_Script: {fileID: 11500000, guid: " + cameraGuid));
            string terrainId = Regex.Match(Field(camera, "terrain"), @"fileID: (\d+)").Groups[1].Value;
            string renderer = scene[terrainId];
            Assert.That(renderer, Does.Contain("guid: " + rendererGuid), "the camera's terrain is a GregoryTerrainRenderer");
            string gameObject = Regex.Match(Field(renderer, "m_GameObject"), @"fileID: (\d+)").Groups[1].Value;
            string transform = scene.Values.Single(o => o.StartsWith("--- !u!4 ", StringComparison.Ordinal) && o.Contains("m_GameObject: {fileID: " + gameObject + "}"));
            Assert.That(Field(transform, "m_LocalRotation"), Is.EqualTo("{x: 0, y: 0, z: 0, w: 1}"), "the terrain is not rotated (its y is the world's)");
            Assert.That(Field(transform, "m_Father"), Is.EqualTo("{fileID: 0}"), "the terrain is a root object");

            string material = File.ReadAllText(Sample("Gregory Terrain.mat"));
            Assert.That(Field(renderer, "material"), Does.Contain(Guid(Sample("Gregory Terrain.mat.meta"))), "the renderer draws the sample's material");
            Assert.That(Field(renderer, "grid"), Does.Contain(Guid(Sample("PatchGrid.asset.meta"))), "the renderer draws the sample's grid");
            bool noise = Regex.IsMatch(material, @"^  - GT_NOISE$", RegexOptions.Multiline);
            TerrainKeywords tiled = Regex.IsMatch(material, @"^  - GT_NOISE_TABLE$", RegexOptions.Multiline) ? TerrainKeywords.NoiseTable : TerrainKeywords.None;
            NoiseSettings? settings = noise
                ? new NoiseSettings((float)Number(renderer, "noise.amplitude"), (float)Number(renderer, "noise.frequency"),
                                    (float)Number(renderer, "noise.alpha"), (float)Number(renderer, "noise.beta"), (int)Number(renderer, "noise.octaves"))
                : (NoiseSettings?)null;
            PatchGrid grid = SampleGridAssetTests.ReadAsset(File.ReadAllText(Sample("PatchGrid.asset")));
            return new Flight
            {
                Clearance = Number(camera, "clearance"),
                LoopSeconds = Number(camera, "loopSeconds"),
                LookAheadSeconds = Number(camera, "lookAheadSeconds"),
                SmoothSeconds = Number(camera, "smoothSeconds"),
                BaseY = Component(transform, "m_LocalPosition", "y"),
                ScaleY = Component(transform, "m_LocalScale", "y"),
                HeightScale = Number(renderer, "heightScale"),
                Surface = new TerrainSurfaceQuery(grid, settings, tiled),
            };
        }

        /// <summary>Frames per loop: one every 0.1 degree.</summary>
        const int FramesPerLoop = 3600;

        [Test]
        public void TheCameraKeepsItsClearanceOverTheSurfaceAlongTheWholeLoop()
        {
            Flight f = ReadFlight();
            double dt = f.LoopSeconds / FramesPerLoop, perSecond = 2.0 * Math.PI / f.LoopSeconds;
            double height = double.NaN, lowest = double.PositiveInfinity, highest = double.NegativeInfinity, lowestAt = 0.0;
            double surfaceLow = double.PositiveInfinity, surfaceHigh = double.NegativeInfinity;
            int below = 0, sampled = 0;
            double fastestClimb = 0.0;
            int held = 0;   // frames at exactly the clearance: the floor, not the easing, set the height
            // Two loops: the first frames start the easing from nothing; the second loop is the steady flight.
            for (int frame = 0; frame < 2 * FramesPerLoop; frame++)
            {
                double phase = frame * 2.0 * Math.PI / FramesPerLoop;
                FlyoverPath.Point(phase, out double x, out double y);
                double under = f.SurfaceY(x, y);
                double ahead = FlyoverPath.GroundAhead(phase, f.LookAheadSeconds * perSecond, f.SurfaceY);
                double before = height;
                height = FlyoverPath.NextHeight(height, under, ahead, f.Clearance, dt, f.SmoothSeconds);
                if (frame < FramesPerLoop) continue;
                fastestClimb = Math.Max(fastestClimb, Math.Abs(height - before) / dt);
                double clearance = height - under;
                sampled++;
                if (clearance < f.Clearance - 1e-6) below++;
                if (Math.Abs(clearance - f.Clearance) < 1e-9) held++;
                if (clearance < lowest) { lowest = clearance; lowestAt = (frame - FramesPerLoop) * 360.0 / FramesPerLoop; }
                highest = Math.Max(highest, clearance);
                surfaceLow = Math.Min(surfaceLow, under);
                surfaceHigh = Math.Max(surfaceHigh, under);
            }
            TestContext.Out.WriteLine(FormattableString.Invariant(
                $"fly-over: surface on the loop {surfaceLow:F1} to {surfaceHigh:F1} m; camera clearance {lowest:F2} m (at {lowestAt:F1} deg) to {highest:F2} m over {sampled} frames; stated {f.Clearance} m; below it: {below}; held at it: {held}; fastest climb or descent {fastestClimb:F1} m/s"));
            Assert.That(surfaceHigh - surfaceLow, Is.GreaterThan(f.Clearance), "the loop crosses relief higher than the clearance (else the check proves little)");
            Assert.That(below, Is.EqualTo(0), FormattableString.Invariant($"frames below the stated clearance {f.Clearance} m (lowest {lowest:F2} m at {lowestAt:F1} deg)"));
            Assert.That(highest, Is.LessThan(f.Clearance + (surfaceHigh - surfaceLow)), "the camera follows the ground rather than flying above all of it");
        }

        [Test]
        public void TheHeightRuleNeverGoesBelowTheClearanceOverAStep()
        {
            // A cliff 100 m high the look-ahead does not see (nothing ahead is higher): the camera is
            // lifted at once rather than eased through the rock.
            double h = FlyoverPath.NextHeight(double.NaN, 0.0, 0.0, 25.0, 0.016, 1.0);
            Assert.That(h, Is.EqualTo(25.0));
            h = FlyoverPath.NextHeight(h, 100.0, 100.0, 25.0, 0.016, 1.0);
            Assert.That(h, Is.EqualTo(125.0));
            // Down again: it sinks, eased, not jumping to the new target.
            double next = FlyoverPath.NextHeight(h, 0.0, 0.0, 25.0, 0.016, 1.0);
            Assert.That(next, Is.LessThan(125.0).And.GreaterThan(120.0));
            Assert.That(FlyoverPath.NextHeight(h, double.NaN, 0.0, 25.0, 0.016, 1.0), Is.NaN, "no ground under the camera: no height");
        }
    }
}
