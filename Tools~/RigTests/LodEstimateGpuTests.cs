// The triangle estimate with Horizon levels (Core TerrainTriangleEstimate.InLevels) against the GPU,
// on gt lod-bench's scene: a 100 km terrain (the demo grid), the camera 2 m above it, 13 levels of
// 16 x 16 tiles, adaptive factors at 1 px, 1920 x 1080 (Tools~/dotnet/Gt/LodScene.cs).
using System;
using System.Collections.Generic;
using System.IO;
using static GregoryTerrain.Tests.TriangleEstimateTests;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>Core's level estimate without the GPU.</summary>
    [TestFixture]
    public class LodEstimateTests
    {
        /// <summary>
        /// Horizon levels: one level is the single range drawn with integer partitioning; L levels at a
        /// uniform even factor F draw 2 F^2 per tile not inside the finer level, less F / 2 per fine
        /// seam edge (g = F / 2 segments there; the coarse side keeps 2g = F).
        /// </summary>
        [Test]
        public void LevelsCountEveryLevelAndTheSeamRule()
        {
            TerrainInputs adaptive = Inputs(new TessellationSettings(8, 32f, 2f, 0f));
            var whole = TerrainTriangleEstimate.InLevels(adaptive, new[] { TerrainRange.full }, RangeOrigin.zero, Low, Screen, TerrainKeywords.Noise, int.MaxValue);
            Assert.That(whole.triangles, Is.EqualTo(TerrainTriangleEstimate.InView(adaptive, Low, Screen, TerrainKeywords.Noise, TessellationPartitioning.Integer, int.MaxValue).triangles));
            Assert.That(whole.tilesSampledDrawn, Is.GreaterThan(0).And.LessThan(64), "the view culls some tiles");

            const int m = 8, f = 8;
            var levels = new TerrainRange[LodLevels.LevelCount(4)];
            int count = LodLevels.Layout(new Double2(0.4, 0.55), 4, m, levels);
            long expected = 0;
            for (int k = 0; k < count; k++)
                for (int tj = 0; tj < m; tj++)
                    for (int ti = 0; ti < m; ti++)
                    {
                        if (k > 0 && LodTiles.TileInsideFiner(ti, tj, Offset(levels[k], levels[k - 1]).a, Offset(levels[k], levels[k - 1]).b, m)) continue;
                        int fine = k + 1 < count ? LodTiles.FineSeamEdges(ti, tj, Offset(levels[k + 1], levels[k]).a, Offset(levels[k + 1], levels[k]).b, m) : 0;
                        expected += 2 * f * f - f / 2 * System.Numerics.BitOperations.PopCount((uint)fine);
                    }
            var e = TerrainTriangleEstimate.InLevels(Inputs(TessellationSettings.Uniform(m, f)), levels, RangeOrigin.For(levels[0]), Low, Screen, TerrainKeywords.Noise, int.MaxValue);
            TestContext.Out.WriteLine("{0} levels: {1}", count, e);
            Assert.That(e.tileCount, Is.EqualTo(LodLevels.DrawnTileCount(count, m)));
            Assert.That(e.tilesSampledDrawn, Is.EqualTo(e.tileCount), "a uniform factor culls nothing in view");
            Assert.That(e.triangles, Is.EqualTo(expected));
            Assert.That(expected, Is.LessThan(2L * f * f * e.tileCount), "some fine seam edges");

            var sample = TerrainTriangleEstimate.InLevels(Inputs(TessellationSettings.Uniform(m, f)), levels, RangeOrigin.For(levels[0]), Low, Screen, TerrainKeywords.Noise, 5 * 16);
            Assert.That(sample.tilesSampled, Is.LessThanOrEqualTo(5 * 16), "4 x 4 per level, less the tiles inside the finer level");
            Assert.That(sample.triangles, Is.EqualTo(e.triangles).Within(10).Percent);
            var ex = Assert.Throws<ArgumentException>(() => TerrainTriangleEstimate.InLevels(adaptive, Array.Empty<TerrainRange>(), RangeOrigin.zero, Low, Screen, TerrainKeywords.None));
            StringAssert.Contains("levels.Length (0)", ex.Message);
            ex = Assert.Throws<ArgumentException>(() => TerrainTriangleEstimate.InLevels(Inputs(TessellationSettings.Uniform(7, 4)), levels, RangeOrigin.zero, Low, Screen, TerrainKeywords.None));
            StringAssert.Contains("tiles (7)", ex.Message);
        }

        /// <summary>gt lod-bench's view (13 levels, 600 of 3,328 tiles drawn): the inspector's sample against every tile, and its cost (printed).</summary>
        [Test]
        public void TheInspectorsSampleOfTheLevelsStaysNearTheWhole()
        {
            LodScene s = new LodScene().Build(HeightmapFitter.Fit(DemoHeightmap.Heights(129), 129, 129, 5, 5).Grid);
            double Run(int maxTiles, out double ms)
            {
                var watch = System.Diagnostics.Stopwatch.StartNew();
                double t = TerrainTriangleEstimate.InLevels(s.Inputs, s.Levels, s.Origin.Value, s.Camera.ObjectToClipFloat(), new Float2(s.Width, s.Height), TerrainKeywords.Noise, maxTiles).triangles;
                ms = watch.Elapsed.TotalMilliseconds;
                return t;
            }
            Run(64, out _);   // JIT
            double all = Run(int.MaxValue, out double allMs);
            foreach (int maxTiles in new[] { 256, 1024, 2048 })
                TestContext.Out.WriteLine("maxTiles {0}: {1:+0.0%;-0.0%} of every tile ({2:N0}, {3:F1} ms; {4:F1} ms for every tile)",
                    maxTiles, Run(maxTiles, out double ms) / all - 1, all, ms, allMs);
            Assert.That(all, Is.EqualTo(613673), "gt lod-bench's GPU count (LodEstimateGpuTests)");
            Assert.That(Run(256, out _), Is.EqualTo(all).Within(15).Percent, "the inspector's 256 tiles: 4 x 4 a level");
        }

        // The finer level's corner in the coarser one's cells (the layout snaps it to them).
        static (int a, int b) Offset(TerrainRange coarse, TerrainRange finer) =>
            ((int)Math.Round((finer.Min.x - coarse.Min.x) / (coarse.Max.x - coarse.Min.x) * 8), (int)Math.Round((finer.Min.y - coarse.Min.y) / (coarse.Max.y - coarse.Min.y) * 8));

    }

    [TestFixture, Parallelizable(ParallelScope.Self), Order(4)]
    public class LodEstimateGpuTests
    {
        /// <summary>
        /// Core's mirror of the levels' factors (seam rule included) against hull_const's readback tile by
        /// tile, and its count against the GPU's clipping invocations; the inspector's 256-tile sample
        /// against the count over every tile.
        /// </summary>
        [Test]
        public void TheLevelsEstimateIsWhatTheGpuDraws()
        {
            string work = ReadbackRun.PrepareWork("rigtests-lod-estimate");
            string spirv = ReadbackRun.CompileVariants(work, "lod+noise", "factor_readback+lod+noise");
            PatchGrid grid = HeightmapFitter.Fit(DemoHeightmap.Heights(129), 129, 129, 5, 5).Grid;
            LodScene s = new LodScene().Build(grid);
            string dir = Path.Combine(work, "scene");
            s.Write(dir);
            HarnessRun Draw(string variant, params string[] extra)
            {
                var args = new List<string>(ReadbackRun.Stages(spirv, variant));
                args.AddRange(s.HarnessArgs(dir));
                args.AddRange(new[] { "--width", s.Width.ToString(), "--height", s.Height.ToString(), "--device", "llvmpipe", "--stats" });
                args.AddRange(extra);
                HarnessRun h = HarnessRun.Harness(args.ToArray());
                h.AssertSucceeded();
                return h;
            }
            long gpu = Draw("lod+noise").Long("stat", "clipping_invocations");
            string rb = Path.Combine(dir, "factors.f32");
            Draw("factor_readback+lod+noise", "--readback", rb, "--readback-floats", (8L * s.Patches).ToString());
            float[] h = ReadbackRun.ReadFloats(rb);

            Float4x4 m = s.Camera.ObjectToClipFloat();
            var screen = new Float2(s.Width, s.Height);
            TerrainInputs[] levels = TerrainTriangleEstimate.LevelInputs(s.Inputs, s.Levels, s.Origin.Value);
            int tiles = s.Tiles, culledDiffer = 0, segmentsDiffer = 0, drawn = 0;
            long model = 0;
            for (int p = 0; p < s.Patches; p++)
            {
                int level = LodTiles.LevelOfPatch(p, tiles), slot = LodTiles.SlotOfPatch(p, tiles);
                var g = new TileFactorSet(new Float4(h[8 * p], h[8 * p + 1], h[8 * p + 2], h[8 * p + 3]), new Float2(h[8 * p + 4], h[8 * p + 5]));
                bool gpuCulled = h[8 * p + 6] != 0f;
                TileFactorSet c = TerrainTriangleEstimate.LodTileFactors(levels, level, slot % tiles, slot / tiles, m, screen, TerrainKeywords.Noise);
                if (c.IsCulled != gpuCulled) culledDiffer++;
                if (gpuCulled) continue;
                drawn++;
                model += TerrainTriangleEstimate.PatchTriangles(g, TessellationPartitioning.Integer);
                if (!c.IsCulled && TerrainTriangleEstimate.PatchTriangles(c, TessellationPartitioning.Integer) != TerrainTriangleEstimate.PatchTriangles(g, TessellationPartitioning.Integer))
                    segmentsDiffer++;
            }
            TriangleEstimate all = TerrainTriangleEstimate.InLevels(s.Inputs, s.Levels, s.Origin.Value, m, screen, TerrainKeywords.Noise, int.MaxValue);
            TriangleEstimate sample = TerrainTriangleEstimate.InLevels(s.Inputs, s.Levels, s.Origin.Value, m, screen, TerrainKeywords.Noise);
            double off = (all.triangles - gpu) / gpu, sampleOff = (sample.triangles - all.triangles) / all.triangles;
            TestContext.Out.WriteLine("{0} levels, {1} patches, {2} drawn on the GPU; culled differently {3}, triangles differently {4}", s.LevelCount, s.Patches, drawn, culledDiffer, segmentsDiffer);
            TestContext.Out.WriteLine("GPU {0:N0} triangles, model of its factors {1:N0}, Core over every tile {2:N0} ({3:+0.00%;-0.00%}), 256-tile sample {4:N0} ({5:+0.0%;-0.0%} of every tile; {6})",
                gpu, model, all.triangles, off, sample.triangles, sampleOff, sample);
            Assert.That(s.LevelCount, Is.EqualTo(13));
            Assert.That(all.tileCount, Is.EqualTo(LodLevels.DrawnTileCount(13, tiles)));
            Assert.That(model, Is.EqualTo(gpu), "integer partitioning: the model counts what the tessellator made");
            Assert.That(culledDiffer, Is.EqualTo(0), "culled on the GPU and in Core alike");
            Assert.That(Math.Abs(off), Is.LessThan(0.005), "Core's count against the GPU's");
            Assert.That(Math.Abs(sampleOff), Is.LessThan(0.25), "the inspector's sample against every tile");
        }
    }
}
