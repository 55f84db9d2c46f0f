using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Linq;
using System.Text.Json;
using NUnit.Framework;
using static GregoryTerrain.Rig.Tests.ComputeRunner;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>
    /// Shaders/Snow/SnowSimulation.compute against the Core reference (SnowSimulation): compiled with
    /// glslang's HLSL front end, validated, cross-compiled, then run by gt-compute on lavapipe.
    /// Missing tools, runner or lavapipe make these tests fail (run <c>Tools~/gt setup</c>).
    /// </summary>
    [TestFixture, Parallelizable(ParallelScope.Self)]
    public class SnowComputeTests
    {
        const string Lavapipe = "llvmpipe";
        static readonly string[] Kernels = { "SnowExposureKernel", "SnowAccumulateKernel" };

        // Exposure is smoothstep(occlusion / softness): a float rounding difference d in the occlusion
        // moves L by at most 1.5 d / softness (softness 0.1 here); the march sums nothing, so d is a few
        // ulp of values of order 1. Depth after K steps: K roundings of additions of order cap.
        const float ExposureTolerance = 2e-4f;
        const float DepthRelativeTolerance = 1e-4f;

        string _dir;

        [OneTimeSetUp]
        public void Compile()
        {
            _dir = Path.Combine(Path.GetTempPath(), "gt-snow-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(_dir);
            string src = PackageRoot.Combine("Shaders", "Snow", "SnowSimulation.compute");
            foreach (string k in Kernels)
            {
                string spv = Spv(k);
                // The command of Tools~/rig/README.md ("Snow kernels"): no register shifts; glslang ignores #pragma kernel.
                Run("glslangValidator", "-D", "-V", "-S", "comp", "-e", k, "-o", spv, src);
                Run("spirv-val", spv);
            }
        }

        [OneTimeTearDown]
        public void Clean()
        {
            if (_dir != null && Directory.Exists(_dir)) Directory.Delete(_dir, true);
        }

        string Spv(string kernel) => Path.Combine(_dir, kernel + ".spv");

        [Test]
        public void KernelsCrossCompileToGlsl450AndMsl()
        {
            foreach (string k in Kernels)
            {
                string glsl = Path.Combine(_dir, k + ".comp"), msl = Path.Combine(_dir, k + ".metal");
                Run("spirv-cross", Spv(k), "--entry", k, "--no-es", "--version", "450", "--output", glsl);
                Run("glslangValidator", "-S", "comp", glsl);
                Run("spirv-cross", Spv(k), "--entry", k, "--msl", "--output", msl);
                Assert.That(new FileInfo(msl).Length, Is.GreaterThan(0));
            }
        }

        [Test]
        public void BindingsAreTheContractsSnowMap()
        {
            var expected = new Dictionary<string, int> { ["SnowParams"] = 0, ["_SnowField"] = 1, ["_SnowExposure"] = 2, ["_SnowDepth"] = 3 };
            foreach (string k in Kernels)
            {
                using var doc = JsonDocument.Parse(Run("spirv-cross", Spv(k), "--reflect"));
                var found = new Dictionary<string, int>();
                foreach (string kind in new[] { "ubos", "ssbos" })
                    if (doc.RootElement.TryGetProperty(kind, out var list))
                        foreach (var r in list.EnumerateArray())
                        {
                            found[r.GetProperty("name").GetString()] = r.GetProperty("binding").GetInt32();
                            if (kind == "ubos") Assert.That(r.GetProperty("block_size").GetInt32(), Is.EqualTo(16 * SnowParams.Float4Count));
                        }
                foreach (var kv in found)
                    Assert.That(kv.Value, Is.EqualTo(expected[kv.Key]), k + " " + kv.Key);
                Assert.That(found.ContainsKey("_SnowDepth"), Is.EqualTo(k == "SnowAccumulateKernel"), k + ": only the step touches the depth");
            }
        }

        /// <summary>
        /// The per-step kernel must not carry the exposure march: it has no loop, and it is
        /// smaller than the exposure kernel. (The terrain stages' GT_SNOW variant comparison is added
        /// when those stages get the keyword.)
        /// </summary>
        [Test]
        public void StepKernelHasNoMarchLoop()
        {
            var counts = Kernels.ToDictionary(k => k, k => Disassemble(Spv(k)));
            foreach (var kv in counts) TestContext.Out.WriteLine($"{kv.Key}: {kv.Value.instructions} SPIR-V instructions, {kv.Value.loops} loops");
            Assert.That(counts["SnowAccumulateKernel"].loops, Is.EqualTo(0));
            Assert.That(counts["SnowExposureKernel"].loops, Is.EqualTo(1));
            Assert.That(counts["SnowAccumulateKernel"].instructions, Is.LessThan(counts["SnowExposureKernel"].instructions));
        }

        [Test]
        public void LavapipeMatchesTheCoreReference()
        {
            const int r = 128, steps = 25;
            const float dt = 0.5f;
            var s = SnowSettings.Default;
            s.resolution = r; s.wind = new Float2(1.6f, 0.7f); s.fallSpeed = 1f; s.scale = 0.002f;
            s.depthCap = 0.02f; s.meltRate = 0.0002f; s.rayLength = 0.3f; s.raySteps = 24;
            SnowField field = TestTerrain(r);
            var cpu = new SnowSimulation(s);
            for (int n = 0; n < steps; n++) cpu.Step(field, dt);

            string fieldFile = Path.Combine(_dir, "field.bin"), paramsFile = Path.Combine(_dir, "params.bin");
            string exposureFile = Path.Combine(_dir, "exposure.bin"), depthFile = Path.Combine(_dir, "depth.bin");
            ReadbackRun.WriteFloats(fieldFile, field.Data);
            ReadbackRun.WriteFloats(paramsFile, s.Params(dt).Pack());
            int groups = r / 8, bytes = 4 * r * r;
            string runner = Runner();
            string o1 = Run(runner, "--spv", Spv("SnowExposureKernel"), "--entry", "SnowExposureKernel", "--device", Lavapipe,
                "--groups", $"{groups},{groups}", "--uniform", "0=" + paramsFile, "--buffer", "1=" + fieldFile,
                "--zeros", $"2={bytes}", "--out", "2=" + exposureFile);
            Assert.That(o1, Does.Contain("device llvmpipe"));
            Run(runner, "--spv", Spv("SnowAccumulateKernel"), "--entry", "SnowAccumulateKernel", "--device", Lavapipe,
                "--groups", $"{groups},{groups}", "--repeat", steps.ToString(), "--uniform", "0=" + paramsFile,
                "--buffer", "1=" + fieldFile, "--buffer", "2=" + exposureFile, "--zeros", $"3={bytes}", "--out", "3=" + depthFile);
            float[] gpuExposure = ReadbackRun.ReadFloats(exposureFile), gpuDepth = ReadbackRun.ReadFloats(depthFile);
            Assert.That(gpuExposure.Length, Is.EqualTo(r * r));
            Assert.That(gpuDepth.Length, Is.EqualTo(r * r));

            float maxExposureDiff = 0f, maxDepthDiff = 0f, maxDepth = 0f;
            int shielded = 0;
            for (int k = 0; k < r * r; k++)
            {
                maxExposureDiff = Math.Max(maxExposureDiff, Math.Abs(gpuExposure[k] - cpu.Exposure[k]));
                maxDepthDiff = Math.Max(maxDepthDiff, Math.Abs(gpuDepth[k] - cpu.Depth[k]));
                maxDepth = Math.Max(maxDepth, cpu.Depth[k]);
                if (cpu.Exposure[k] < 0.5f) shielded++;
            }
            TestContext.Out.WriteLine($"R {r}, {steps} steps: max |exposure diff| {maxExposureDiff:E2}, max |depth diff| {maxDepthDiff:E2} (max depth {maxDepth:E3}), shielded cells {shielded}");
            // The field must exercise the interesting cases, or the comparison proves little.
            Assert.That(shielded, Is.GreaterThan(r * r / 50), "some cells lie in a lee");
            Assert.That(maxDepth, Is.GreaterThan(0.5f * s.depthCap));
            Assert.That(maxExposureDiff, Is.LessThanOrEqualTo(ExposureTolerance));
            Assert.That(maxDepthDiff, Is.LessThanOrEqualTo(DepthRelativeTolerance * s.depthCap));
            // A few named cells: level ground upwind, the lee foot of the ridge, its windward face.
            foreach (var (i, j) in new[] { (2, 2), (80, 64), (52, 64), (127, 127) })
            {
                int k = j * r + i;
                Assert.That(gpuDepth[k], Is.EqualTo(cpu.Depth[k]).Within(DepthRelativeTolerance * s.depthCap), $"depth ({i}, {j})");
                Assert.That(gpuExposure[k], Is.EqualTo(cpu.Exposure[k]).Within(ExposureTolerance), $"exposure ({i}, {j})");
            }
        }

        /// <summary>A diagonal ridge with ripples on level ground; exact normals of that height function.</summary>
        static SnowField TestTerrain(int r)
        {
            var f = new SnowField(r);
            for (int j = 0; j < r; j++)
                for (int i = 0; i < r; i++)
                {
                    double x = (i + 0.5) / r, y = (j + 0.5) / r;
                    double d = (x - 0.5) + 0.3 * (y - 0.5);           // across the ridge
                    double g = Math.Exp(-d * d / (2 * 0.05 * 0.05));   // gaussian ridge, 0.12 high
                    double h = 0.12 * g + 0.004 * Math.Sin(40 * x) * Math.Cos(37 * y);
                    double dd = -d / (0.05 * 0.05) * 0.12 * g;          // dh/dd
                    double hx = dd + 0.004 * 40 * Math.Cos(40 * x) * Math.Cos(37 * y);
                    double hy = 0.3 * dd - 0.004 * 37 * Math.Sin(40 * x) * Math.Sin(37 * y);
                    double len = Math.Sqrt(hx * hx + hy * hy + 1);
                    f.Set(i, j, new Float3((float)(-hx / len), (float)(-hy / len), (float)(1 / len)), (float)h);
                }
            return f;
        }

        static (int instructions, int loops) Disassemble(string spv)
        {
            string text = Run("spirv-dis", "--no-header", spv);
            var lines = text.Split('\n').Select(l => l.Trim()).Where(l => l.Length > 0 && !l.StartsWith(";")).ToArray();
            return (lines.Length, lines.Count(l => l.Contains("OpLoopMerge")));
        }
    }
}
