// The harness binds the rig's uniform blocks (TerrainParams b0, the camera b1) as storage buffers on
// lavapipe (gt-harness --uniform-blocks, Tools~/harness/README.md): lavapipe inlines uniform values
// that steer branches and loops and compiles the pipeline again for every new set, which made each
// GPU scene of the test command a fresh compile. These tests hold the two halves of that choice:
// the drawn vertices are the same bits either way, and one compile serves scenes whose values differ.
using System.Collections.Generic;
using System.IO;
using System.Linq;
using GregoryTerrain.Tests;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    [TestFixture, Parallelizable(ParallelScope.Self), Order(12)]
    public class UniformBlockBindingTests
    {
        static readonly NoiseSettings Noise = new NoiseSettings(0.004f, 16f, 2f, 2f, 6);
        string _work, _spirv;
        PatchGrid _grid;

        [OneTimeSetUp]
        public void CompileShaders()
        {
            _work = ReadbackRun.PrepareWork("rigtests-uniform-blocks");
            _grid = HardCaseGrids.Fitted();
            _spirv = ReadbackRun.CompileVariants(_work, "readback+noise");
        }

        /// <summary>One readback draw of scene <paramref name="name"/> (tiles x tiles at factor), binding as asked, Mesa's cache in <paramref name="cache"/>.</summary>
        (HarnessRun run, float[] readback) Draw(string name, int tiles, int factor, TerrainRange range, string binding, string cache)
        {
            string dir = Path.Combine(_work, name);
            TerrainParams p = ReadbackRun.UniformParams(_grid, range, RangeOrigin.zero, tiles, factor, Noise);
            var inputs = TerrainInputs.Create(_grid, p);
            ReadbackRun.WriteBuffers(dir, inputs, ReadbackRun.TopDownCamera());
            int floats = 12 * tiles * tiles * (factor + 1) * (factor + 1);
            string readback = Path.Combine(dir, "readback.f32");
            var args = new List<string>(ReadbackRun.Stages(_spirv, "readback+noise"));
            args.AddRange(new[] { "--buffers", dir, "--patches", (tiles * tiles).ToString(), "--width", "64", "--height", "64",
                                  "--device", "llvmpipe", "--readback", readback, "--readback-floats", floats.ToString() });
            if (binding != null) args.AddRange(new[] { "--uniform-blocks", binding });
            HarnessRun run = HarnessRun.Start(HarnessRun.HarnessPath(), HarnessRun.PassStateArgs("tessellated").Concat(args),
                new Dictionary<string, string> { ["MESA_SHADER_CACHE_DIR"] = cache });
            run.AssertSucceeded();
            return (run, ReadbackRun.ReadFloats(readback));
        }

        static int CacheFiles(string cache) => Directory.Exists(cache) ? Directory.GetFiles(cache, "*", SearchOption.AllDirectories).Length : 0;

        string FreshCache(string name)
        {
            string cache = Path.Combine(_work, "mesa-cache-" + name);
            if (Directory.Exists(cache)) Directory.Delete(cache, true);
            return cache;
        }

        [Test]
        public void StorageBindingDrawsTheSameBitsAsUniform()
        {
            var range = new TerrainRange(0.21, 0.33, 0.46, 0.58);
            string cache = FreshCache("bits");
            var (auto, autoBits) = Draw("bits-auto", 3, 7, range, null, cache);
            var (uniform, uniformBits) = Draw("bits-uniform", 3, 7, range, "uniform", cache);
            Assert.That(auto.Value("inputs", "uniform_blocks"), Is.EqualTo(new[] { "storage" }), "lavapipe's default binding");
            Assert.That(uniform.Value("inputs", "uniform_blocks"), Is.EqualTo(new[] { "uniform" }));
            Assert.That(autoBits.Length, Is.EqualTo(12 * 9 * 64));
            Assert.That(autoBits.Count(float.IsNaN), Is.EqualTo(0), "every vertex written");
            int differing = Enumerable.Range(0, autoBits.Length).Count(i => System.BitConverter.SingleToInt32Bits(autoBits[i]) != System.BitConverter.SingleToInt32Bits(uniformBits[i]));
            TestContext.Out.WriteLine($"storage vs uniform binding: {autoBits.Length} floats, {differing} differ in any bit");
            Assert.That(differing, Is.EqualTo(0), "the vertices drawn through storage and uniform bindings differ");
        }

        [TestCase("storage", false)]
        [TestCase("uniform", true)]
        public void ASceneWithOtherValuesCompilesAgainOnlyThroughUniformBlocks(string binding, bool compilesAgain)
        {
            string cache = FreshCache(binding);
            Draw("first-" + binding, 2, 3, new TerrainRange(0.1, 0.1, 0.4, 0.4), binding, cache);
            int afterFirst = CacheFiles(cache);
            Draw("second-" + binding, 3, 6, new TerrainRange(0.5, 0.2, 0.7, 0.4), binding, cache);
            int afterSecond = CacheFiles(cache);
            TestContext.Out.WriteLine($"--uniform-blocks {binding}: Mesa's shader cache {afterFirst} files after the first scene, {afterSecond} after the second (other factor, tiles, range)");
            Assert.That(afterFirst, Is.GreaterThan(0), "Mesa's disk cache is on (MESA_SHADER_CACHE_DIR)");
            if (compilesAgain)
                Assert.That(afterSecond, Is.GreaterThan(afterFirst), "lavapipe inlines uniform values: the reason for the storage binding");
            else
                Assert.That(afterSecond, Is.EqualTo(afterFirst), "a scene with other values compiled its pipeline again");
        }
    }
}
