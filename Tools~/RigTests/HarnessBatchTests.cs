// gt-harness --batch (Tools~/harness/src/batch.hpp) against separate harness processes: the same
// readback bits, each distinct pipeline created once, and a broken line failing alone with its
// line and option named while the runs around it still draw.
using System;
using System.IO;
using System.Linq;
using GregoryTerrain.Tests;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    [TestFixture, Parallelizable(ParallelScope.Self)]
    public class HarnessBatchTests
    {
        static readonly NoiseSettings Noise = new NoiseSettings(0.004f, 16f, 2f, 2f, 6);
        string _work, _spirv;

        [OneTimeSetUp]
        public void CompileShaders()
        {
            _work = ReadbackRun.PrepareWork("rigtests-harness-batch");
            _spirv = ReadbackRun.CompileVariants(_work, "readback", "readback+noise");
        }

        /// <summary>Four scenes over two variants (readback, readback+noise), two grids, ranges and factors.</summary>
        string[][] Scenes(string name, out ReadbackRun[] runs)
        {
            PatchGrid fitted = HardCaseGrids.Fitted();
            PatchGrid small = HeightmapFitter.Fit(HardCaseGrids.Heightmap(17, 5), 17, 17, 3, 2).Grid;
            var scenes = new (PatchGrid grid, TerrainRange range, int tiles, int factor, bool noise)[]
            {
                (fitted, new TerrainRange(0.1, 0.2, 0.6, 0.7), 2, 5, false),
                (small, new TerrainRange(0.3, 0.3, 0.30001, 0.30001), 3, 4, true),
                (small, new TerrainRange(0, 0, 1, 1), 2, 7, false),
                (fitted, new TerrainRange(0.25, 0.5, 0.75, 1), 4, 3, true),
            };
            runs = new ReadbackRun[scenes.Length];
            var args = new string[scenes.Length][];
            for (int i = 0; i < scenes.Length; i++)
            {
                var s = scenes[i];
                var p = ReadbackRun.UniformParams(s.grid, s.range, RangeOrigin.For(s.range), s.tiles, s.factor, Noise);
                runs[i] = ReadbackRun.Prepare(Path.Combine(_work, name + i), _spirv, s.grid, p, s.noise ? Noise : (NoiseSettings?)null,
                                              false, new string[0], out args[i]);
            }
            return args;
        }

        static byte[] Bits(ReadbackRun r) => r.Readback.SelectMany(BitConverter.GetBytes).ToArray();

        [Test]
        public void ABatchReadsBackTheBitsOfSeparateProcesses()
        {
            string[][] args = Scenes("separate", out ReadbackRun[] separate);
            for (int i = 0; i < args.Length; i++) separate[i].Finish(HarnessRun.Harness(args[i]));
            string[][] batchArgs = Scenes("batched", out ReadbackRun[] batched);
            HarnessRun[] runs = HarnessBatch.Run(_work, batchArgs, 1);
            for (int i = 0; i < runs.Length; i++) batched[i].Finish(runs[i]);

            for (int i = 0; i < args.Length; i++)
            {
                Assert.That(batched[i].Readback.Length, Is.GreaterThan(0));
                Assert.That(batched[i].NonFinite(), Is.EqualTo(0), $"scene {i}: NaN in the batch's readback");
                Assert.That(Bits(batched[i]), Is.EqualTo(Bits(separate[i])), $"scene {i}: the batch's readback differs from a separate process's");
                Assert.That(runs[i].Value("stat", "tessellation_evaluation_shader_invocations"),
                            Is.EqualTo(separate[i].Harness.Value("stat", "tessellation_evaluation_shader_invocations")), $"scene {i}: statistics");
            }
            string summary = File.ReadAllText(Path.Combine(_work, "batch0.txt"));
            Assert.That(summary.Split('\n', StringSplitOptions.RemoveEmptyEntries).Length, Is.EqualTo(args.Length), "one line per run");
        }

        [Test]
        public void EachDistinctPipelineIsCreatedOnce()
        {
            string[][] args = Scenes("count", out _);
            string file = Path.Combine(_work, "count.txt");
            File.WriteAllLines(file, args.Concat(args).Select(a => string.Join("\t", HarnessRun.PassStateArgs("tessellated").Concat(a))));
            HarnessRun whole = HarnessRun.Start(HarnessRun.HarnessPath(), new[] { "--batch", file });
            whole.AssertSucceeded();
            // 8 runs over three variants (the deep range's draws GT_RANGE_ORIGIN): a pipeline per variant, every later run reuses one
            int variants = args.Select(a => a[Array.IndexOf(a, "--vert") + 1]).Distinct().Count();
            Assert.That(variants, Is.EqualTo(3));
            Assert.That(whole.Value("batch", "runs"), Is.EqualTo(new[] { "8", "failed", "0", "pipelines_created", "3", "reused", "5" }), whole.Stdout);
        }

        [Test]
        public void ABrokenLineFailsAloneAndIsNamed()
        {
            string[][] args = Scenes("broken", out ReadbackRun[] runs);
            string missing = Path.Combine(_work, "no-such-folder");
            args[1] = args[1].Select(a => a == Path.Combine(_work, "broken1") ? missing : a).ToArray();
            string file = Path.Combine(_work, "broken.txt");
            File.WriteAllLines(file, args.Select(a => string.Join("\t", HarnessRun.PassStateArgs("tessellated").Concat(a))));
            HarnessRun whole = HarnessRun.Start(HarnessRun.HarnessPath(), new[] { "--batch", file });
            Assert.That(whole.ExitCode, Is.EqualTo(1), "a failed run fails the batch");
            Assert.That(whole.Stderr, Does.Contain("--batch '" + file + "' line 2: error:").And.Contain(missing), whole.Stderr);
            HarnessRun[] parts = HarnessBatch.Split(whole, args.Length);
            Assert.That(parts[1].ExitCode, Is.Not.EqualTo(0));
            Assert.That(parts[1].Stderr, Does.Contain(missing));
            foreach (int i in new[] { 0, 2, 3 })
            {
                runs[i].Finish(parts[i]);
                Assert.That(runs[i].NonFinite(), Is.EqualTo(0), $"run {i} after the broken one");
            }
            Assert.That(HarnessBatch.Split(whole, args.Length + 1)[args.Length].Stderr, Does.Contain("has no output of its own"));
        }

        [Test]
        public void AnEmptyOrMissingBatchFileIsRefused()
        {
            string empty = Path.Combine(_work, "empty.txt");
            File.WriteAllText(empty, "# nothing\n\n");
            HarnessRun e = HarnessRun.Start(HarnessRun.HarnessPath(), new[] { "--batch", empty });
            Assert.That(e.ExitCode, Is.EqualTo(1));
            Assert.That(e.Stderr, Does.Contain("--batch '" + empty + "' holds no run"));
            HarnessRun m = HarnessRun.Start(HarnessRun.HarnessPath(), new[] { "--batch", Path.Combine(_work, "absent.txt") });
            Assert.That(m.ExitCode, Is.EqualTo(1));
            Assert.That(m.Stderr, Does.Contain("absent.txt': cannot read the file"));
        }
    }
}
