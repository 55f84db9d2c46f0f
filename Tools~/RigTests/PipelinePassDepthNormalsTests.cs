// URP's DepthNormalsOnly pass of GregoryTerrain.shader (tessellated SubShader, _GBUFFER_NORMALS_OCT) drawn by
// the harness with every binding filled by name (Tools~/rig/pipeline_pass.py --only depth_normals), the
// renderer's Transform turned 30 degrees about y so a normal left in object space, or turned the wrong way,
// is not the world normal. Its output is decoded as URP decodes _CameraNormalsTexture and compared with
// Core's normal (TerrainSurfaceQuery) at the world position the pass's own depth gives.
using System.IO;
using System.Linq;
using System.Text.Json;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    [TestFixture]
    public class PipelinePassDepthNormalsTests
    {
        static readonly string[] Scene = { "--only", "depth_normals", "--object-yaw", "30" };

        // The bounds, in degrees. Encoding: two 12-bit octahedral coordinates, a step of 2/4095 in [-1, 1]: at most
        // ~0.06 degrees where the octahedron stretches most, ~0.03 on average. Position from depth: float32 reversed
        // depth 0.5-2 units from the eye moves a pixel's point by ~1e-7 units, and Core's normal there by far less
        // than 0.001 degrees. What remains is the shader's own approximation: the normal is evaluated per tessellated
        // vertex and interpolated across each triangle (TerrainVertex.hlsl: one normal interpolant), so it lags the
        // exact surface by up to curvature x half an edge inside a patch, and more where a tile's triangle spans a
        // patch corner (the grid's patches meet every 0.2, its 16 x 16 tiles every 0.0625) or the grid's border.
        // Measured on this scene (factor-15 tiles): mean 0.052, 99th percentile 0.39 (HDRP's 0.43), max 3.6 degrees,
        // the largest 0.002 from the patch corner (0.6, 0.4) (HDRP's: 0.003 from the border). A normal in the wrong
        // space or turned by the 30-degree Transform misses by tens of degrees on average.
        public const double MeanDegrees = 0.15, P99Degrees = 1.0, MaxDegrees = 5.0;
        const int Step = 2;      // every 2nd covered pixel in x and y

        string _out;
        RigPng _normals;

        [OneTimeSetUp]
        public void Draw()
        {
            (_out, _) = PipelinePassRun.Draw("pipeline_pass.py", "rigtests-pipeline-pass-normals", Scene);
            _normals = RigPng.Read(Path.Combine(_out, "depth_normals.png"));
        }

        [Test]
        public void EveryMemberTheStagesRead_IsFilledByTheScene_AndTheTargetIsUrpsOctahedralOne()
        {
            JsonElement m = PipelinePassRun.Manifest(_out, "depth_normals");
            string[] filled = PipelinePassRun.Strings(m.GetProperty("filled"));
            string[] read = m.GetProperty("reads").EnumerateObject().SelectMany(s => PipelinePassRun.Strings(s.Value)).Distinct().ToArray();
            TestContext.Out.WriteLine($"depth_normals: {filled.Length} filled, read by the stages: {string.Join(", ", read)}");
            Assert.That(PipelinePassRun.Strings(m.GetProperty("defaulted_read")), Is.Empty, "a member some stage reads was left to its default");
            Assert.That(read.Where(r => !filled.Contains(r)), Is.Empty, "read but not filled by the scene");
            Assert.That(read, Does.Contain("$Global._GtWorldToObject"), "the normal is taken to world space with the renderer's matrix");
            Assert.That(m.GetProperty("variant").GetString(), Is.EqualTo("_GBUFFER_NORMALS_OCT"));
            // DepthNormalsOnly names no render state: ShaderLab's defaults, all four channels written.
            Assert.That(PipelinePassRun.Strings(m.GetProperty("state")), Is.EqualTo(new[]
                { "--cull", "back", "--ztest", "lequal", "--zwrite", "on", "--zclip", "on", "--color-mask", "rgba" }));
        }

        [Test]
        public void TheDecodedNormals_AreCoresNormals_AtThePixelsDepth()
        {
            var (angles, outside, worst) = PipelinePassRun.NormalAngles(_out, "depth_normals_depth.f32", "depth_normals_view.json", _normals,
                                                                 p => PipelinePassRun.OctahedralNormal(_normals, p), Step);
            var (mean, p99, max) = PipelinePassRun.AngleFigures(angles, "URP DepthNormalsOnly (_GBUFFER_NORMALS_OCT) vs Core");
            TestContext.Out.WriteLine($"sampled pixels off the terrain: {outside}; {worst}");
            Assert.That(angles.Count, Is.GreaterThan(_normals.Width * _normals.Height / (5 * Step * Step)), "the terrain covers a fifth of the picture or more");
            Assert.That(outside, Is.LessThan(angles.Count / 100), "sampled pixels whose depth puts them off the terrain");
            Assert.That(mean, Is.LessThan(MeanDegrees), "mean angle (degrees)");
            Assert.That(p99, Is.LessThan(P99Degrees), "99th percentile angle (degrees)");
            Assert.That(max, Is.LessThan(MaxDegrees), "largest angle (degrees)");
        }
    }
}
