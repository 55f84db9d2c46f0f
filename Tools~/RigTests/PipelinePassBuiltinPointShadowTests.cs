// Built-in's ShadowCaster into one face of a point light's cube map (Tools~/rig/pipeline_pass.py, --only builtin_point_cube:
// PointLightFace, a 90-degree face looking down from above the terrain): the SHADOWS_CUBE variant Unity draws for a cube
// map since the pass declares multi_compile_shadowcaster, and the SHADOWS_DEPTH variant, which Unity drew for it before.
// With a depth cube map (SHADOWS_CUBE_IN_DEPTH_TEX, every API the rig's Vulkan stands for) Unity's caster leaves the light's
// depth bias out (UnityApplyLinearShadowBias, UnityCG.cginc:942) because the receiver subtracts it from the distance
// (UnitySampleShadowmap, UnityShadowLibrary.cginc:113): the map must hold the surface itself, so the bias applies once.
// The distance-in-colour variant (no depth cube map: GLES2) cannot be drawn on Vulkan. Fails, never skips.
using System;
using System.IO;
using System.Linq;
using System.Text.Json;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    [TestFixture, Parallelizable(ParallelScope.Self)]
    public class PipelinePassBuiltinPointShadowTests
    {
        string _out;
        JsonElement _face;
        float[] _cube, _depth;
        int _n;
        double _near, _far, _bias;

        [OneTimeSetUp]
        public void Draw()
        {
            (_out, _) = PipelinePassRun.Draw("pipeline_pass.py", "rigtests-pipeline-pass-builtin-point", new[] { "--only", "builtin_point_cube" });
            _face = JsonDocument.Parse(File.ReadAllText(Path.Combine(_out, "point_light.json"))).RootElement;
            _n = _face.GetProperty("resolution").GetInt32();
            (_near, _far, _bias) = (_face.GetProperty("near").GetDouble(), _face.GetProperty("far").GetDouble(), _face.GetProperty("bias").GetDouble());
            _cube = PipelinePassRun.ReadDepth(_out, "builtin_point_cube.f32");
            _depth = PipelinePassRun.ReadDepth(_out, "builtin_point_depth.f32");
            Assert.That(_cube.Length, Is.EqualTo(_n * _n));
            Assert.That(_depth.Length, Is.EqualTo(_n * _n));
            Assert.That(PipelinePassRun.Strings(PipelinePassRun.Manifest(_out, "builtin_point_cube").GetProperty("defaulted_read")), Is.Empty,
                "a member the cube caster reads was left to its default");
        }

        /// <summary>The face's reversed depth d of a point at distance w along the face's axis is near (far - w) / ((far - near) w)
        /// (the perspective _LightProjectionParams describes); back: w = near far / ((far - near) d + near).</summary>
        double AxisDistance(double d) => _near * _far / ((_far - _near) * d + _near);

        /// <summary>UnityApplyLinearShadowBias's change to a depth at axis distance w (UnityCG.cginc:945-946, reversed depth): x / w
        /// added to clip z, clamped to [-1, 0], so x / w^2 after the divide by w.</summary>
        double LinearBias(double w) => Math.Max(-1.0, Math.Min(_bias / w, 0.0)) / w;

        [Test]
        public void TheCubeCaster_LeavesTheLinearBiasOut_TheDepthCasterAddsIt()
        {
            var covered = Enumerable.Range(0, _n * _n).Where(p => _cube[p] > 0).ToList();
            int coverageDiffers = Enumerable.Range(0, _n * _n).Count(p => (_cube[p] > 0) != (_depth[p] > 0));
            double worst = covered.Max(p => Math.Abs(_depth[p] - (_cube[p] + LinearBias(AxisDistance(_cube[p])))));
            double meanShift = covered.Average(p => _cube[p] - _depth[p]);
            // The depth caster's surface, pushed along the axis: what the receiver's own bias comes on top of (twice, before).
            double meanPush = covered.Average(p => AxisDistance(_depth[p]) - AxisDistance(_cube[p]));
            TestContext.Out.WriteLine($"point face {_n}^2: {covered.Count} texels covered (coverage differs at {coverageDiffers}); SHADOWS_DEPTH - SHADOWS_CUBE " +
                                      $"depth: mean {-meanShift:G4}, largest |difference - x / w^2| {worst:G3}; the SHADOWS_DEPTH caster pushes the surface " +
                                      $"{meanPush:G4} world units away on average (x = {_bias})");
            Assert.That(covered.Count, Is.GreaterThan(_n * _n / 10), "the terrain covers a tenth of the face or more");
            Assert.That(coverageDiffers, Is.Zero, "the two casters cover the same texels");
            Assert.That(meanShift, Is.GreaterThan(1e-3), "the SHADOWS_DEPTH caster adds the depth bias, the SHADOWS_CUBE caster does not");
            Assert.That(worst, Is.LessThan(1e-5), "SHADOWS_DEPTH's depth = SHADOWS_CUBE's + UnityApplyLinearShadowBias's, texel by texel");
        }

        [Test]
        public void TheCubeCastersDepth_IsTheSurfaceSeenFromTheLight()
        {
            // Every 4th texel both ways: its world point from the cube caster's depth through the face's inverse view-projection
            // (the harness's rows top first: clip y = +1), its height against TerrainSurfaceQuery's exact surface below it.
            double[,] clipToWorld = PipelinePassRun.Inverse(PipelinePassRun.Matrix(_face.GetProperty("view_proj")));
            double[,] worldToObject = PipelinePassRun.Inverse(PipelinePassRun.Matrix(_face.GetProperty("object_to_world")));
            double worldPerTerrain = 1.0 / Math.Sqrt(Enumerable.Range(0, 3).Sum(r => worldToObject[r, 0] * worldToObject[r, 0]));
            var query = new TerrainSurfaceQuery(PatchGridJson.ReadFile(Path.Combine(_out, "grid.json")), null);
            double HeightError(float[] depth, int p)
            {
                double[] world = PipelinePassRun.Mul(clipToWorld, new[] { (p % _n + 0.5) / _n * 2 - 1, 1 - (p / _n + 0.5) / _n * 2, depth[p], 1.0 });
                double[] o = PipelinePassRun.Mul(worldToObject, world.Select(x => x / world[3]).ToArray());
                return (o[1] - query.SampleHeight(o[0], o[2])) * worldPerTerrain;
            }
            var sampled = Enumerable.Range(0, _n * _n).Where(p => p % _n % 4 == 0 && p / _n % 4 == 0 && _cube[p] > 0)
                .Where(p => !double.IsNaN(HeightError(_cube, p))).ToList();
            var cube = sampled.Select(p => Math.Abs(HeightError(_cube, p))).OrderBy(e => e).ToList();
            double depthMean = sampled.Select(p => HeightError(_depth, p)).Where(e => !double.IsNaN(e)).Average();
            TestContext.Out.WriteLine($"{sampled.Count} texels: |cube caster's point - surface| in height: median {cube[cube.Count / 2]:G3}, " +
                                      $"largest {cube[^1]:G3} world units; the SHADOWS_DEPTH caster's points {depthMean:G3} on average");
            Assert.That(sampled.Count, Is.GreaterThan(500), "texels over the terrain sampled");
            Assert.That(cube[^1], Is.LessThan(HeightTolerance), "the cube map holds the surface (its bias is the receiver's)");
        }

        /// <summary>World units: the tessellated surface against the exact one (the fixture's largest, measured, with margin).</summary>
        const double HeightTolerance = 1e-3;
    }
}
