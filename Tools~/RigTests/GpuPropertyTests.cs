// Random scenes on the GPU (lavapipe, readback variant), fixed seeds: watertightness under random
// integer factors and ranges, and a property test (random ranges and fitted grids: no NaN, GPU
// equals Core's float mirror within tolerance). The scenes go through two batch harness processes.
using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Linq;
using GregoryTerrain.Tests;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    [TestFixture, Parallelizable(ParallelScope.Self)]
    public class GpuPropertyTests
    {
        /// <summary>The property test's random fitted grids and random ranges per grid (one readback draw each).</summary>
        public const int Grids = 4, RangesPerGrid = 50;
        static readonly NoiseSettings Noise = new NoiseSettings(0.004f, 16f, 2f, 2f, 6);
        string _work, _spirv;

        [OneTimeSetUp]
        public void CompileShaders()
        {
            _work = ReadbackRun.PrepareWork("rigtests-gpuproperty");
            _spirv = ReadbackRun.CompileVariants(_work, "readback", "readback+noise");
        }

        /// <summary>A random range: width 10^(-6 .. 0), anywhere in the unit square.</summary>
        static TerrainRange RandomRange(Random rng)
        {
            double w = Math.Pow(10, -6 * rng.NextDouble());
            double c = rng.NextDouble() * (1 - w), d = rng.NextDouble() * (1 - w);
            return new TerrainRange(c, d, Math.Min(c + w, 1), Math.Min(d + w, 1));
        }

        sealed class Scene
        {
            public PatchGrid Grid;
            public TerrainRange Range;
            public int Tiles, Factor;
            public bool Noise;
            public ReadbackRun Run;
        }

        /// <summary>Draws every scene: two batch harness processes (HarnessBatch), one pipeline compile per variant each.</summary>
        void DrawAll(IList<Scene> scenes, string name)
        {
            var args = new string[scenes.Count][];
            for (int i = 0; i < scenes.Count; i++)
            {
                Scene s = scenes[i];
                var p = ReadbackRun.UniformParams(s.Grid, s.Range, RangeOrigin.For(s.Range), s.Tiles, s.Factor, Noise);
                s.Run = ReadbackRun.Prepare(Path.Combine(_work, name + i.ToString("D3")), _spirv, s.Grid, p,
                                            s.Noise ? Noise : (NoiseSettings?)null, false, new string[0], out args[i]);
            }
            HarnessRun[] runs = HarnessBatch.Run(_work, args);
            for (int i = 0; i < scenes.Count; i++) scenes[i].Run.Finish(runs[i]);
        }

        [Test]
        public void WatertightUnderRandomFactorsAndRanges()
        {
            var rng = new Random(7321);
            PatchGrid grid = HardCaseGrids.Fitted();
            var scenes = new List<Scene>();
            for (int k = 0; k < 16; k++)
            {
                int factor = k == 0 ? 1 : k == 1 ? 64 : rng.Next(1, 65);
                // up to ~20,000 vertices per run (the split above 65,536 is covered by HardCaseGpuTests.Factor64)
                int maxTiles = Math.Max(2, Math.Min(8, (int)Math.Sqrt(20000.0 / ((factor + 1) * (factor + 1)))));
                scenes.Add(new Scene { Grid = grid, Range = RandomRange(rng), Tiles = rng.Next(2, maxTiles + 1), Factor = factor, Noise = rng.Next(2) == 0 });
            }
            var clock = Stopwatch.StartNew();
            DrawAll(scenes, "watertight");
            int pairs = 0, differing = 0, nonFinite = 0;
            foreach (Scene s in scenes)
            {
                var (p, d) = s.Run.SharedEdges();
                pairs += p;
                differing += d;
                nonFinite += s.Run.NonFinite();
                Assert.That(p, Is.EqualTo(2 * s.Tiles * (s.Tiles - 1) * (s.Factor + 1)));
            }
            TestContext.Out.WriteLine($"watertight under change: {scenes.Count} runs (factors {string.Join(",", scenes.Select(s => s.Factor))}), " +
                                      $"{pairs} shared-edge vertex pairs checked, {differing} differ in any bit; non-finite floats {nonFinite}; {clock.Elapsed.TotalSeconds:F1} s");
            Assert.That(nonFinite, Is.EqualTo(0));
            Assert.That(differing, Is.EqualTo(0), "shared tile edge vertices differ");
        }

        [Test]
        public void RandomRangesAndGridsMatchCore()
        {
            var rng = new Random(424242);
            var scenes = new List<Scene>();
            for (int gi = 0; gi < Grids; gi++)
            {
                int cols = rng.Next(1, 6), rows = rng.Next(1, 6), samples = 9 + 4 * rng.Next(1, 4);
                PatchGrid g = HeightmapFitter.Fit(HardCaseGrids.Heightmap(samples, rng.Next()), samples, samples, cols, rows).Grid;
                for (int ri = 0; ri < RangesPerGrid; ri++)
                    scenes.Add(new Scene { Grid = g, Range = RandomRange(rng), Tiles = 2, Factor = rng.Next(1, 6), Noise = rng.Next(2) == 0 });
            }
            var clock = Stopwatch.StartNew();
            DrawAll(scenes, "property");
            int vertices = 0, nonFinite = 0, unmatched = 0;
            double worstAbs = 0, worstRel = 0;
            foreach (Scene s in scenes)
            {
                nonFinite += s.Run.NonFinite();
                ReadbackComparison c = s.Run.Compare();
                vertices += c.Vertices;
                unmatched += c.Unmatched;
                // absolute output: terrain units; relative output (deep zoom): in range widths
                if (RelativeSurface.IsActive(s.Run.Inputs.Params.rangeOrigin)) worstRel = Math.Max(worstRel, c.MaxPosition / s.Range.Width);
                else worstAbs = Math.Max(worstAbs, c.MaxPosition);
            }
            TestContext.Out.WriteLine($"GPU property iterations (random range x grid): {scenes.Count} over {Grids} fitted grids, {vertices} vertices, " +
                                      $"{clock.Elapsed.TotalSeconds:F1} s; max |gpu - core float| {worstAbs:G3} (absolute output), {worstRel:G3} range widths (relative output); " +
                                      $"non-finite floats {nonFinite}, tess coordinates not recovered {unmatched}");
            Assert.That(nonFinite, Is.EqualTo(0));
            Assert.That(unmatched, Is.EqualTo(0));
            Assert.That(worstAbs, Is.LessThan(1e-6), "GPU vs Core float, absolute output");
            Assert.That(worstRel, Is.LessThan(1e-5), "GPU vs Core float, relative output, in range widths");
            Assert.That(scenes.Count, Is.EqualTo(Grids * RangesPerGrid));
        }
    }
}
