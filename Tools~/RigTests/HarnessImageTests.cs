// --image / --sampler through the harness on lavapipe: sampling.hlsl's probe kernel reads uploaded
// textures through separate samplers and writes what it read to binding 8, compared here exactly.
using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    public partial class HarnessTests
    {
        // _Values (4x4, R32G32_SFLOAT): texel (x, y) = (x + 4 y, 1000 - x y).
        static float[] ValueTexels() =>
            Enumerable.Range(0, 16).SelectMany(i => new float[] { i % 4 + 4 * (i / 4), 1000 - (i % 4) * (i / 4) }).ToArray();

        /// <summary>Runs the probe kernel with the comparison sampler's OP; returns the 5 probes (float4 each).</summary>
        float[] Probes(string name, string compareOp, params string[] extra)
        {
            string dir = MakeInputs("in_" + name, 4, 8, new[] { 0f, 0, 1, 1 });
            var (pos, idx) = WriteQuadMesh(name);
            string values = Path.Combine(_work, name + "_values.f32"), depth = Path.Combine(_work, name + "_depth.f32");
            string layers = Path.Combine(_work, name + "_layers.u8"), dump = Path.Combine(_work, name + "_probes.bin");
            WriteFloats(values, ValueTexels());
            WriteFloats(depth, new[] { 0.25f, 0.75f, 0.25f, 0.75f });  // 2x2 D32: columns 0.25 | 0.75
            File.WriteAllBytes(layers, new byte[] { 0, 0, 0, 0, 255, 0, 51, 102 });  // 1x1, 2 layers, RGBA8
            var args = new List<string> { "--static-mesh", "--mesh", pos, idx, "--vert", Spv("mesh.vert.spv"),
                "--frag", Spv("mesh.frag.spv"), "--buffers", dir, "--width", Size.ToString(), "--height", Size.ToString(),
                "--device", "llvmpipe", "--storage", "8:80", "--compute", Spv("sampling.comp.spv") + ":1",
                "--dump-storage", "8:" + dump,
                "--image", "10:" + values + ":R32G32_SFLOAT:4:4", "--image", "11:" + depth + ":D32:2:2",
                "--image", "15:" + layers + ":R8G8B8A8_UNORM:1:1:2",
                "--sampler", "12:linear:clamp", "--sampler", "13:point:repeat", "--sampler", "14:point:clamp:" + compareOp };
            args.AddRange(extra);
            HarnessRun r = HarnessRun.Harness(args.ToArray());
            r.AssertSucceeded();
            Assert.That(r.Value("inputs", "image"), Is.EqualTo(new[] { "10", "R32G32_SFLOAT", "4x4", "layers", "1" }), r.Stdout);
            byte[] bytes = File.ReadAllBytes(dump);
            Assert.That(bytes.Length, Is.EqualTo(80));
            return Enumerable.Range(0, 20).Select(i => BitConverter.ToSingle(bytes, 4 * i)).ToArray();
        }

        [Test]
        public void SampledImages_FetchBilinearWrapAndLayersReadExactly()
        {
            float[] p = Probes("images", "compare-gequal");
            Assert.That(p.Take(2).ToArray(), Is.EqualTo(new[] { 7f, 997f }), "Load(3, 1): texel x + 4y, 1000 - xy");
            // uv (0.5, 0.5) is the corner shared by texels (1..2, 1..2): weights 1/4 each.
            Assert.That(p.Skip(4).Take(2).ToArray(), Is.EqualTo(new[] { 7.5f, 997.75f }), "bilinear midpoint, linear clamp sampler");
            Assert.That(p.Skip(8).Take(2).ToArray(), Is.EqualTo(new[] { 9f, 998f }), "uv (-0.625, 0.625), point repeat: texel (1, 2)");
            Assert.That(p.Skip(16).ToArray(), Is.EqualTo(new[] { 1f, 0f, 51 / 255f, 102 / 255f }).Within(1e-6f),
                "Texture2DArray layer 1 of an R8G8B8A8_UNORM image");
        }

        // Unity's reversed depth (near the light 1): a receiver is lit when its depth is at or above the
        // shadow map's, Vulkan's GREATER_OR_EQUAL with the reference on the left. compare-less, the
        // forward-depth direction, inverts every probe.
        [TestCase("compare-gequal", new[] { 1f, 0f, 1f, 1f })]
        [TestCase("compare-greater", new[] { 1f, 0f, 1f, 0f })]
        [TestCase("compare-less", new[] { 0f, 1f, 0f, 0f })]
        public void ComparisonSampler_PassesWhenReferenceOpTexel(string op, float[] expected)
        {
            // x: reference 0.5 over texel 0.25, y: 0.5 over 0.75, z: 0.8 over 0.75, w: 0.25 over 0.25.
            float[] p = Probes("compare_" + op.Substring(8), op);
            float[] got = p.Skip(12).Take(4).ToArray();
            Assert.That(got, Is.EqualTo(expected), op + " probes (x, y, z, w): " + string.Join(", ", got));
        }

        [TestCase("--image", "3:x.f32:R32_SFLOAT:4:4", "binding 3 in '3:x.f32:R32_SFLOAT:4:4' is the rig's")]
        [TestCase("--image", "10:x.f32:R32_FLOAT:4:4", "FORMAT 'R32_FLOAT' in '10:x.f32:R32_FLOAT:4:4'")]
        [TestCase("--image", "10:x.f32:R32_SFLOAT:0:4", "W '0' in '10:x.f32:R32_SFLOAT:0:4'")]
        [TestCase("--image", "10:x.f32:R32_SFLOAT:4:4:0", "LAYERS '0' in")]
        [TestCase("--image", "10:x.f32:R32_SFLOAT:4", "expected BINDING:FILE:FORMAT:W:H[:LAYERS]")]
        [TestCase("--sampler", "12:cubic", "filter 'cubic' in '12:cubic'")]
        [TestCase("--sampler", "12:linear:mirror", "'mirror' in '12:linear:mirror'")]
        [TestCase("--sampler", "12:linear:compare-lesser", "'compare-lesser' in '12:linear:compare-lesser'")]
        [TestCase("--sampler", "8:point", "binding 8 is already given (--storage 8)")]
        [TestCase("--sampler", "10:point", "binding 10 is already given (--image '10:")]
        public void BadImageOrSampler_IsRefusedNamingTheOptionAndValue(string option, string value, string expected)
        {
            string dir = MakeInputs("in_bad_image", 4, 8, new[] { 0f, 0, 1, 1 });
            var (pos, idx) = WriteQuadMesh("bad_image");
            string values = Path.Combine(_work, "bad_image_values.f32");
            WriteFloats(values, new float[16]);
            HarnessRun r = HarnessRun.Harness("--static-mesh", "--mesh", pos, idx, "--vert", Spv("mesh.vert.spv"),
                "--frag", Spv("mesh.frag.spv"), "--buffers", dir, "--device", "llvmpipe", "--storage", "8:16",
                "--image", "10:" + values + ":R32_SFLOAT:4:4", option, value);
            Assert.That(r.ExitCode, Is.EqualTo(1), r.Stdout + r.Stderr);
            Assert.That(r.Stderr, Does.Contain(option).And.Contain(expected));
        }

        [Test]
        public void ImageFileOfTheWrongSizeOrDepthOutsideZeroOne_IsRefused()
        {
            string dir = MakeInputs("in_bad_image_file", 4, 8, new[] { 0f, 0, 1, 1 });
            var (pos, idx) = WriteQuadMesh("bad_image_file");
            string small = Path.Combine(_work, "bad_image_small.f32"), deep = Path.Combine(_work, "bad_image_deep.f32");
            WriteFloats(small, new float[15]);
            WriteFloats(deep, new[] { 0.5f, 1.5f });
            HarnessRun Run(string image) => HarnessRun.Harness("--static-mesh", "--mesh", pos, idx, "--vert", Spv("mesh.vert.spv"),
                "--frag", Spv("mesh.frag.spv"), "--buffers", dir, "--device", "llvmpipe", "--image", image);
            HarnessRun a = Run("10:" + small + ":R32_SFLOAT:4:4");
            Assert.That(a.ExitCode, Is.EqualTo(1), a.Stdout + a.Stderr);
            Assert.That(a.Stderr, Does.Contain("--image").And.Contain("has 60 bytes; expected 64"));
            HarnessRun b = Run("10:" + deep + ":D32:2:1");
            Assert.That(b.ExitCode, Is.EqualTo(1), b.Stdout + b.Stderr);
            Assert.That(b.Stderr, Does.Contain("--image").And.Contain("texel 1").And.Contain("outside a depth image's [0, 1]"));
        }

        [Test]
        public void ShaderTextureWithoutAnImage_NamesTheOptionToAdd()
        {
            string dir = MakeInputs("in_missing_image", 4, 8, new[] { 0f, 0, 1, 1 });
            var (pos, idx) = WriteQuadMesh("missing_image");
            HarnessRun r = HarnessRun.Harness("--static-mesh", "--mesh", pos, idx, "--vert", Spv("mesh.vert.spv"),
                "--frag", Spv("mesh.frag.spv"), "--buffers", dir, "--device", "llvmpipe", "--storage", "8:80",
                "--compute", Spv("sampling.comp.spv") + ":1");
            Assert.That(r.ExitCode, Is.EqualTo(1), r.Stdout + r.Stderr);
            Assert.That(r.Stderr, Does.Contain("which this run does not bind").And.Contain("--image ").And.Contain("--sampler "));
        }
    }
}
