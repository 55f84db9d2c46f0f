using System;
using NUnit.Framework;

namespace GregoryTerrain.Tests
{
    /// <summary>
    /// The horizon-to-feet level layout (LodLevels): nested power-of-two ranges around the camera,
    /// each level's boundary on the coarser level's cell lines, the last one the whole terrain.
    /// </summary>
    [TestFixture]
    public class LodLevelsTests
    {
        [Test]
        public void ACamera2mAboveA100kmTerrainNeeds13LevelsOfAbout24mAndUp()
        {
            int n = LodLevels.FinestExponent(100000, 16);
            Assert.That(n, Is.EqualTo(12), "2^-12 of 100 km = 24.4 m >= 16 m");
            Assert.That(LodLevels.LevelCount(n), Is.EqualTo(13), "13 float4 a frame");
            Assert.That(LodLevels.LevelCount(LodLevels.FinestExponent(1e6, 16)), Is.EqualTo(16), "1,000 km: 16");
        }

        [TestCase(0.5, 0.5)]
        [TestCase(0.123456789, 0.987654321)]
        [TestCase(0.0, 0.0)]
        [TestCase(1.0, 0.3)]
        [TestCase(0.99999, 1e-7)]
        public void LevelsAreNestedSnappedAndEndWithTheTerrain(double x, double y)
        {
            const int tiles = 16, n = 12;
            var levels = new TerrainRange[LodLevels.LevelCount(n)];
            int count = LodLevels.Layout(new Double2(x, y), n, tiles, levels);
            Assert.That(count, Is.EqualTo(13));
            Assert.That(levels[count - 1], Is.EqualTo(TerrainRange.full));
            for (int k = 0; k < count; k++)
            {
                TerrainRange r = levels[k];
                r.Validate($"levels[{k}]");
                Assert.That(r.Width, Is.EqualTo(Math.Pow(2, k - n)), $"level {k} width");
                Assert.That(r.Height, Is.EqualTo(Math.Pow(2, k - n)));
                // The camera's ground point inside level 0 and every level (in the unit square).
                Assert.That(x, Is.InRange(r.c, r.g), $"level {k} holds the camera");
                Assert.That(y, Is.InRange(r.d, r.h));
                if (k + 1 < count)
                {
                    TerrainRange o = levels[k + 1];
                    Assert.That(r.c >= o.c && r.g <= o.g && r.d >= o.d && r.h <= o.h, Is.True, $"level {k} {r} inside level {k + 1} {o}");
                    // Its boundary on the coarser level's cell lines (cells of W_{k+1} / M).
                    double cell = o.Width / tiles;
                    foreach (double line in new[] { r.c - o.c, r.g - o.c, r.d - o.d, r.h - o.d })
                        Assert.That(line / cell, Is.EqualTo(Math.Round(line / cell)), $"level {k} boundary {line:R} on level {k + 1}'s lattice");
                }
            }
            // Away from the terrain's edge the camera keeps at least a quarter level of margin.
            if (x > 0.01 && x < 0.99 && y > 0.01 && y < 0.99)
                for (int k = 0; k < count - 6; k++)
                {
                    TerrainRange r = levels[k];
                    double margin = Math.Min(Math.Min(x - r.c, r.g - x), Math.Min(y - r.d, r.h - y));
                    Assert.That(margin, Is.GreaterThanOrEqualTo(0.5 * r.Width - 2 * r.Width / tiles), $"level {k} margin");
                }
        }

        [Test]
        public void BadInputNamesTheField()
        {
            var levels = new TerrainRange[13];
            StringAssert.Contains("tiles (4)", Assert.Throws<ArgumentException>(() => LodLevels.Layout(new Double2(0.5, 0.5), 12, 4, levels)).Message);
            StringAssert.Contains("levels.Length (13)", Assert.Throws<ArgumentException>(() => LodLevels.Layout(new Double2(0.5, 0.5), 13, 16, levels)).Message);
            StringAssert.Contains("finestExponent (-1)", Assert.Throws<ArgumentException>(() => LodLevels.LevelCount(-1)).Message);
            StringAssert.Contains("terrainMeters (0)", Assert.Throws<ArgumentException>(() => LodLevels.FinestExponent(0, 1)).Message);
        }

        /// <summary>A camera's frame of the levels as the renderer runs it (layout, origin, PushLevels) allocates nothing.</summary>
        [Test]
        public void AFrameOfTheLevelsAllocatesNothing()
        {
            const int tiles = 16, n = 16;   // 1,000 km: 16 levels
            var ranges = new TerrainRange[LodTiles.MaxLevels];
            var vectors = new Float4[LodTiles.MaxLevels];
            var origin = new RangeOriginTracker();
            void Frame(double y)
            {
                int count = LodLevels.Layout(new Double2(0.37, y), n, tiles, ranges);
                origin.Update(ranges[0]);
                for (int k = 0; k < count; k++)
                {
                    RangeMapping.EncodeRange(ranges[k], origin.Origin, out Float4 r, out _);
                    vectors[k] = r;
                }
            }
            Frame(0.52);   // warm up (JIT)
            // The fewest of three frames: the runtime's one-off work (tiered JIT) shows in one.
            long allocated = long.MaxValue;
            for (int i = 1; i <= 3; i++)
            {
                long before = GC.GetAllocatedBytesForCurrentThread();
                Frame(0.52 + i * 1e-6);
                allocated = Math.Min(allocated, GC.GetAllocatedBytesForCurrentThread() - before);
            }
            Assert.That(allocated, Is.EqualTo(0), "bytes allocated by one frame of 16 levels");
            Assert.That(vectors[15], Is.Not.EqualTo(default(Float4)));
        }
    }
}
