using System;
using System.Collections.Generic;
using NUnit.Framework;

namespace GregoryTerrain.Tests
{
    /// <summary>
    /// Drawing the levels (LodTiles): the drawn tiles of all levels cover the terrain exactly once
    /// (tiles inside the finer level culled), and the seam rule forms every seam vertex from the
    /// coarse edge on both sides, bit for bit, at the right place.
    /// </summary>
    [TestFixture]
    public class LodTilesTests
    {
        static Float4[] Levels(double x, double y, int n, int tiles)
        {
            var ranges = new TerrainRange[LodLevels.LevelCount(n)];
            int count = LodLevels.Layout(new Double2(x, y), n, tiles, ranges);
            var f = new Float4[count];
            for (int k = 0; k < count; k++)   // dyadic: exact in float
                f[k] = new Float4((float)ranges[k].c, (float)ranges[k].d, (float)ranges[k].g, (float)ranges[k].h);
            return f;
        }

        // The tessellator's tess coordinate k / F as lavapipe forms it (16.16 fixed point).
        static float Fixed16(int k, float f) => (float)(Math.Round(k / (double)f * 65536) / 65536);

        static IEnumerable<TestCaseData> Cases()
        {
            foreach (int tiles in new[] { 8, 16, 12 })
                foreach (var p in new[] { (0.5, 0.5), (0.123456789, 0.987654321), (0.0, 0.0), (1.0, 0.3), (0.3, 0.99999) })
                    yield return new TestCaseData(tiles, p.Item1, p.Item2);
        }

        [TestCaseSource(nameof(Cases))]
        public void DrawnTilesCoverTheTerrainOnce(int tiles, double x, double y)
        {
            Float4[] levels = Levels(x, y, 6, tiles);
            var rng = new Random(7);
            for (int s = 0; s < 3000; s++)
            {
                // Points near the camera as well as far away.
                double px = s % 2 == 0 ? rng.NextDouble() : GMath.clamp(x + (rng.NextDouble() - 0.5) * 0.05, 0.0, 1.0);
                double py = s % 2 == 0 ? rng.NextDouble() : GMath.clamp(y + (rng.NextDouble() - 0.5) * 0.05, 0.0, 1.0);
                int covering = 0;
                for (int k = 0; k < levels.Length; k++)
                {
                    Float4 r = levels[k];
                    int a = 0, b = 0;
                    if (k > 0) LodTiles.FinerOffsetCells(r, levels[k - 1], tiles, out a, out b);
                    double cell = (r.z - r.x) / tiles;
                    int ti = (int)Math.Floor((px - r.x) / cell), tj = (int)Math.Floor((py - r.y) / cell);
                    if (px == r.z) ti = tiles - 1;
                    if (py == r.w) tj = tiles - 1;
                    if (ti < 0 || tj < 0 || ti >= tiles || tj >= tiles) continue;
                    if (k > 0 && LodTiles.TileInsideFiner(ti, tj, a, b, tiles)) continue;
                    covering++;
                }
                // Points on a level's boundary may sit in two tiles; away from lines exactly one.
                Assert.That(covering, Is.InRange(1, 2), $"({px:R}, {py:R})");
                if (covering == 2) continue;
                Assert.That(covering, Is.EqualTo(1), $"({px:R}, {py:R}) drawn once");
            }
        }

        [TestCaseSource(nameof(Cases))]
        public void SeamVerticesAreBitIdenticalOnBothSides(int tiles, double x, double y)
        {
            Float4[] levels = Levels(x, y, 6, tiles);
            var origin = new Float4(0f, 0f, 0f, 0f);
            int fineEdges = 0, vertices = 0;
            for (int k = 0; k + 1 < levels.Length; k++)
            {
                Float4 range = levels[k], coarser = levels[k + 1];
                LodTiles.FinerOffsetCells(coarser, range, tiles, out int a, out int b);
                var covered = new Dictionary<(int, int, int), int>();
                for (int tj = 0; tj < tiles; tj++)
                    for (int ti = 0; ti < tiles; ti++)
                    {
                        int mask = LodTiles.FineSeamEdges(ti, tj, a, b, tiles);
                        foreach (int edge in new[] { LodTiles.EdgeU0, LodTiles.EdgeV0, LodTiles.EdgeU1, LodTiles.EdgeV1 })
                        {
                            if ((mask & edge) == 0) continue;
                            fineEdges++;
                            LodTiles.FineSeamCoarseTile(edge, ti, tj, a, b, out int cti, out int ctj, out int coarseEdge, out int upperHalf);
                            Assert.That(LodTiles.CoarseSeamEdges(cti, ctj, a, b, tiles) & coarseEdge, Is.Not.Zero,
                                        $"level {k} tile ({ti}, {tj}) edge {edge}: coarse tile ({cti}, {ctj}) has the edge on its seam");
                            Assert.That(LodTiles.TileInsideFiner(cti, ctj, a, b, tiles), Is.False, "the coarse tile across is drawn");
                            covered.TryGetValue((cti, ctj, coarseEdge), out int c);
                            covered[(cti, ctj, coarseEdge)] = c + 1;
                            foreach (float g in new[] { 1f, 2f, 3f, 5f, 8f, 13f, 32f })
                                for (int j = 0; j <= (int)g; j++)
                                {
                                    float along = Fixed16(j, g);
                                    var tess = (edge & (LodTiles.EdgeU0 | LodTiles.EdgeU1)) != 0
                                        ? new Float2(edge == LodTiles.EdgeU0 ? 0f : 1f, along) : new Float2(along, edge == LodTiles.EdgeV0 ? 0f : 1f);
                                    TerrainPoint qf = LodTiles.SeamCoarsePoint(true, edge, tess, g, ti, tj, range, coarser, a, b, origin, tiles);
                                    int n = j + upperHalf * (int)g;
                                    float coarseAlong = Fixed16(n, 2f * g);
                                    var ctess = (coarseEdge & (LodTiles.EdgeU0 | LodTiles.EdgeU1)) != 0
                                        ? new Float2(coarseEdge == LodTiles.EdgeU0 ? 0f : 1f, coarseAlong) : new Float2(coarseAlong, coarseEdge == LodTiles.EdgeV0 ? 0f : 1f);
                                    TerrainPoint qc = LodTiles.SeamCoarsePoint(false, coarseEdge, ctess, g, cti, ctj, coarser, coarser, 0, 0, origin, tiles);
                                    Assert.That(qf.local, Is.EqualTo(qc.local), $"level {k} tile ({ti}, {tj}) edge {edge} g {g} j {j}: both sides form the same q");
                                    // ... and it is the fine edge's own point j / g (to float accuracy).
                                    TerrainPoint own = RangeMapping.ToTerrainPoint(range, origin, tiles, ti, tj, tess.x, tess.y);
                                    double tol = 4e-7 * (coarser.z - coarser.x) + 1e-7;
                                    Assert.That(Math.Abs(qf.local.x - own.local.x), Is.LessThanOrEqualTo(tol), "x on the fine edge");
                                    Assert.That(Math.Abs(qf.local.y - own.local.y), Is.LessThanOrEqualTo(tol), "y on the fine edge");
                                    vertices++;
                                }
                        }
                    }
                foreach (var kv in covered)
                    Assert.That(kv.Value, Is.EqualTo(2), $"coarse edge {kv.Key} of level {k + 1} meets two fine edges");
            }
            Assert.That(fineEdges, Is.GreaterThan(0), "some seams were checked");
            TestContext.Out.WriteLine($"M {tiles} at ({x}, {y}): {fineEdges} fine seam edges, {vertices} seam vertices bit-identical");
        }

        [Test]
        public void SeamFactorsNestAndDrawPatchesNameTheirLevel()
        {
            Assert.That(LodTiles.SeamHalfFactor(7.2f, 64f), Is.EqualTo(4f), "coarse 8 = fine 4 + 4");
            Assert.That(LodTiles.SeamHalfFactor(0.3f, 64f), Is.EqualTo(1f));
            Assert.That(LodTiles.SeamHalfFactor(64f, 64f), Is.EqualTo(32f), "2g stays within the limit");
            Assert.That(LodTiles.SeamHalfFactor(63.5f, 63f), Is.EqualTo(31f));
            Assert.That(LodTiles.LevelOfPatch(3 * 256 + 17, 16), Is.EqualTo(3));
            Assert.That(LodTiles.SlotOfPatch(3 * 256 + 17, 16), Is.EqualTo(17));
            Assert.That(Assert.Throws<ArgumentException>(() => LodTiles.SeamCoarseTess(3, 0, 1f)).Message, Does.Contain("edge (3)"));
        }
    }
}
