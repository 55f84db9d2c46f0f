// URP's DepthNormalsOnly pass of GregoryTerrain.shader (tessellated SubShader, _GBUFFER_NORMALS_OCT) drawn by
// the harness with every binding filled by name (Tools~/rig/pipeline_pass.py --only depth_normals), the
// renderer's Transform turned 30 degrees about y so a normal left in object space, or turned the wrong way,
// is not the world normal. Its output is decoded as URP decodes _CameraNormalsTexture and compared with
// Core's normal (TerrainSurfaceQuery) at the world position the pass's own depth gives. The base variant, which a
// default (Forward) asset draws, goes into the R8G8B8A8_SNorm target URP gives it and is read back as URP reads it.
// The _WRITE_RENDERING_LAYERS variants of DepthNormalsOnly and ForwardLit write the draw's rendering layers into
// the second target URP binds with decal layers on, and their first target as the plain variants do.
using System;
using System.Globalization;
using System.Text.RegularExpressions;
using System.IO;
using System.Linq;
using System.Text.Json;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    [TestFixture, Parallelizable(ParallelScope.Self)]
    public class PipelinePassDepthNormalsTests
    {
        static readonly string[] Scene = { "--only", "depth_normals", "--only", "depth_normals_snorm", "--only", "depth_normals_layers",
                                           "--only", "lit", "--only", "lit_layers", "--object-yaw", "30" };

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
        // The base variant's signed bytes: each component within half a step (0.5/127) of the shader's, so the stored
        // vector's length within sqrt(3) x 0.5/127 = 0.0068 of the shader's unit length and its direction within about
        // 0.39 degrees of it (the mean near half that); the shader's own approximation adds as above.
        public const double SignedMeanDegrees = 0.4, SignedP99Degrees = 1.2, SignedLength = 0.01;
        const int Step = 2;      // every 2nd covered pixel in x and y

        string _out;
        RigPng _normals, _signed;

        [OneTimeSetUp]
        public void Draw()
        {
            (_out, _) = PipelinePassRun.Draw("pipeline_pass.py", "rigtests-pipeline-pass-normals", Scene);
            _normals = RigPng.Read(Path.Combine(_out, "depth_normals.png"));
            _signed = RigPng.Read(Path.Combine(_out, "depth_normals_snorm.png"));
        }

        /// <summary>What URP's LoadSceneNormals returns for the base variant (DeclareNormalsTexture.hlsl:21-23: the
        /// texel's xyz, no decode, no normalize) from an R8G8B8A8_SNorm texel: Vulkan's SNORM conversion, max(b / 127, -1)
        /// of the signed byte (the harness's --png keeps the stored bytes).</summary>
        static double[] StoredSignedNormal(RigPng png, int p) =>
            Enumerable.Range(0, 3).Select(c => Math.Max((sbyte)png.Rgba[4 * p + c] / 127.0, -1.0)).ToArray();

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

        [Test]
        public void TheBaseVariant_DrawsIntoUrpsSignedTarget_WithEveryReadMemberFilled()
        {
            JsonElement m = PipelinePassRun.Manifest(_out, "depth_normals_snorm");
            Assert.That(m.GetProperty("variant").GetString(), Is.EqualTo("base"));
            Assert.That(PipelinePassRun.Strings(m.GetProperty("defaulted_read")), Is.Empty, "a member some stage reads was left to its default");
            string command = File.ReadLines(Path.Combine(_out, "depth_normals_snorm", "harness.log")).First();
            Assert.That(command, Does.Contain("--color-format R8G8B8A8_SNORM"), "DepthNormalOnlyPass.GetGraphicsFormat's target");
            Assert.That(PipelinePassRun.Strings(m.GetProperty("state")), Is.EqualTo(new[]
                { "--cull", "back", "--ztest", "lequal", "--zwrite", "on", "--zclip", "on", "--color-mask", "rgba" }));
        }

        [Test]
        public void TheBaseVariantsStoredNormals_AreUnitLength_AndCoresNormals_AtThePixelsDepth()
        {
            // URP's consumers (SSAO, decals) use LoadSceneNormals' value as it is: it must be unit length as stored.
            int covered = 0, offLength = 0;
            double worstLength = 0;
            byte[] depth = File.ReadAllBytes(Path.Combine(_out, "depth_normals_snorm_depth.f32"));
            for (int p = 0; p < _signed.Width * _signed.Height; p++)
            {
                if (!(BitConverter.ToSingle(depth, 4 * p) > 0)) continue;
                covered++;
                double length = Math.Sqrt(StoredSignedNormal(_signed, p).Sum(x => x * x)), off = Math.Abs(length - 1);
                offLength += off > SignedLength ? 1 : 0;
                worstLength = Math.Max(worstLength, off);
            }
            TestContext.Out.WriteLine($"base variant: {covered} covered pixels, |length - 1| largest {worstLength:F4}, over {SignedLength}: {offLength}");
            Assert.That(covered, Is.GreaterThan(_signed.Width * _signed.Height / 5), "the terrain covers a fifth of the picture or more");
            Assert.That(offLength, Is.Zero, "stored normals whose length is not 1 within the SNORM step");

            var (angles, outside, worst) = PipelinePassRun.NormalAngles(_out, "depth_normals_snorm_depth.f32", "depth_normals_snorm_view.json", _signed,
                p => { double[] n = StoredSignedNormal(_signed, p); double l = Math.Sqrt(n.Sum(x => x * x)); return n.Select(x => x / l).ToArray(); }, Step);
            var (mean, p99, max) = PipelinePassRun.AngleFigures(angles, "URP DepthNormalsOnly (base, R8G8B8A8_SNorm) vs Core");
            TestContext.Out.WriteLine($"sampled pixels off the terrain: {outside}; {worst}");
            Assert.That(outside, Is.LessThan(angles.Count / 100), "sampled pixels whose depth puts them off the terrain");
            Assert.That(mean, Is.LessThan(SignedMeanDegrees), "mean angle (degrees)");
            Assert.That(p99, Is.LessThan(SignedP99Degrees), "99th percentile angle (degrees)");
            Assert.That(max, Is.LessThan(MaxDegrees), "largest angle (degrees)");
        }

        /// <summary>The byte URP's R8_UNorm rendering-layers target holds for the scene's mask: EncodeMeshRenderingLayer
        /// (ShaderVariablesFunctions.hlsl: mask AND _RenderingLayerMaxInt, times its reciprocal) stored as UNORM8, from
        /// pipeline_pass.py's RENDERING_LAYER_MASK and RENDERING_LAYER_BITS.</summary>
        static int ExpectedLayersByte()
        {
            string script = File.ReadAllText(Path.Combine(HarnessRun.PackageRoot(), "Tools~", "rig", "pipeline_pass.py"));
            uint mask = uint.Parse(Regex.Match(script, @"^RENDERING_LAYER_MASK = 0x([0-9A-Fa-f]+)", RegexOptions.Multiline).Groups[1].Value, NumberStyles.HexNumber);
            int bits = int.Parse(Regex.Match(script, @"^RENDERING_LAYER_BITS = (\d+)", RegexOptions.Multiline).Groups[1].Value);
            uint max = (1u << bits) - 1;
            Assert.That(bits, Is.EqualTo(8), "the scene's R8_UNorm target holds 8 layers");
            return (int)Math.Round((mask & max) / (double)max * 255);
        }

        [TestCase("depth_normals_layers", "depth_normals_snorm")]
        [TestCase("lit_layers", "lit")]
        public void TheRenderingLayersVariant_WritesTheDrawsLayersInTheSecondTarget_AndTheFirstAsThePlainVariant(string picture, string plain)
        {
            JsonElement m = PipelinePassRun.Manifest(_out, picture);
            Assert.That(m.GetProperty("variant").GetString(), Is.EqualTo("_WRITE_RENDERING_LAYERS"));
            Assert.That(PipelinePassRun.Strings(m.GetProperty("defaulted_read")), Is.Empty, "a member some stage reads was left to its default");
            Assert.That(PipelinePassRun.Strings(m.GetProperty("reads").GetProperty("frag")),
                Is.SupersetOf(new[] { "UnityPerDraw.unity_RenderingLayer", "$Global._RenderingLayerMaxInt", "$Global._RenderingLayerRcpMaxInt" }),
                "EncodeMeshRenderingLayer(GetMeshRenderingLayer()) reads the draw's mask and the target's range");
            Assert.That(File.ReadLines(Path.Combine(_out, picture, "harness.log")).First(), Does.Contain("--target1 R8_UNORM:"),
                        "RenderingLayerUtils.GetFormat(Bits8)'s target");

            byte[] layers = File.ReadAllBytes(Path.Combine(_out, picture + "_target1.bin"));
            byte[] depth = File.ReadAllBytes(Path.Combine(_out, "depth_normals_snorm_depth.f32"));   // the same view and geometry
            Assert.That(layers.Length, Is.EqualTo(depth.Length / 4), "one byte per pixel");
            int expected = ExpectedLayersByte(), covered = 0, wrongInside = 0, writtenOutside = 0, first = -1;
            for (int p = 0; p < layers.Length; p++)
            {
                bool inside = BitConverter.ToSingle(depth, 4 * p) > 0;
                covered += inside ? 1 : 0;
                bool bad = inside ? layers[p] != expected : layers[p] != 0;
                wrongInside += inside && bad ? 1 : 0;
                writtenOutside += !inside && bad ? 1 : 0;
                if (bad && first < 0) first = p;
            }
            string where = first < 0 ? "" : $"; first at ({first % _signed.Width}, {first / _signed.Width}) = {layers[first]}";
            TestContext.Out.WriteLine($"{picture}: second target {expected} expected at {covered} covered pixels: {wrongInside} differ, {writtenOutside} written outside{where}");
            Assert.That(covered, Is.GreaterThan(layers.Length / 5), "the terrain covers a fifth of the picture or more");
            Assert.That(wrongInside, Is.Zero, $"covered pixels whose rendering layers are not {expected}{where}");
            Assert.That(writtenOutside, Is.Zero, "pixels written outside the terrain (the target is cleared to 0)");

            RigPng withLayers = RigPng.Read(Path.Combine(_out, picture + ".png")), without = RigPng.Read(Path.Combine(_out, plain + ".png"));
            Assert.That(withLayers.Rgba, Is.EqualTo(without.Rgba), $"{picture}'s first target equals {plain}'s");
        }
    }
}
