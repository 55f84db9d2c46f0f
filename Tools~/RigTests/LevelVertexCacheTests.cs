using System;
using System.Collections.Generic;
using GregoryTerrain.Tests;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>
    /// (Core's tests, kept under Tools~: the package's 2 MB leaves no room for them in Tests/Core.)
    /// The Horizon levels' compact cache layout (<see cref="LevelVertexCache"/>): each drawn tile's
    /// records lie in its own block, the block holds every record the draw reads for a vertex of the
    /// tile and the kernel writes them, culled tiles take none, and bad input changes nothing.
    /// </summary>
    [TestFixture]
    public class LevelVertexCacheTests
    {
        static TileFactorSet Set(float e0, float e1, float e2, float e3, float i0, float i1) => VertexCacheTests.Set(e0, e1, e2, e3, i0, i1);

        /// <summary>Integer factors as the factor kernels leave them: a quarter culled, the rest in [1, 64], inside drawn >= 2 unless all are 1.</summary>
        static TileFactorSet[] Frame(int patches, int seed)
        {
            var random = new Random(seed);
            var f = new TileFactorSet[patches];
            for (int p = 0; p < patches; p++)
            {
                if (random.Next(4) == 0) { f[p] = TileFactors.CulledTileFactors(); continue; }
                float F() => random.Next(3) == 0 ? 1f + random.Next(64) : 1f + random.Next(12);
                f[p] = VertexCache.IntegerFactors(Set(F(), F(), F(), F(), F(), F()));
            }
            f[1] = VertexCache.IntegerFactors(Set(1, 1, 1, 1, 1, 1));
            f[2] = VertexCache.IntegerFactors(Set(64, 64, 64, 64, 64, 64));
            return f;
        }

        [Test]
        public void EveryVertexTheDrawReadsLiesInItsTilesBlockAndTheKernelWritesIt()
        {
            TileFactorSet[] f = Frame(3 * 64, 7);
            var first = new long[f.Length];
            long total = LevelVertexCache.TileFirstRecords(f, first);
            var owner = new int[total];
            Array.Fill(owner, -1);
            for (int p = 0; p < f.Length; p++)
            {
                long end = first[p] + LevelVertexCache.TileSlots(f[p]);
                var written = new HashSet<long>();
                foreach (var (_, slot) in VertexCache.TilePoints(f[p], LevelVertexCache.TileFactorLimit(f[p])))
                {
                    long r = first[p] + slot;
                    Assert.That(r, Is.GreaterThanOrEqualTo(first[p]).And.LessThan(end), $"patch {p} ({f[p]}): slot {slot} outside its block");
                    Assert.That(owner[r], Is.EqualTo(-1).Or.EqualTo(p), $"record {r} written by patches {owner[r]} and {p}");
                    owner[r] = p;
                    written.Add(r);
                }
                foreach (var (tess, _) in VertexCache.TilePoints(f[p], LevelVertexCache.TileFactorLimit(f[p])))
                    Assert.That(written, Does.Contain(LevelVertexCache.Record(first[p], tess, f[p])), $"patch {p} ({f[p]}): the draw reads tess {tess} from a record its kernel never wrote");
            }
        }

        /// <summary>A tile without records evaluates at the kernel's points, from the tessellator's coordinate off by 1.2e-4 (lavapipe).</summary>
        [Test]
        public void TheDomainStagesPointIsTheKernelsPoint()
        {
            TileFactorSet[] f = Frame(64, 5);
            int points = 0;
            foreach (TileFactorSet set in f)
                foreach (var (tess, _) in VertexCache.TilePoints(set, LevelVertexCache.TileFactorLimit(set)))
                    foreach (float d in new[] { 0f, 1.2e-4f, -1.2e-4f })
                    {
                        // The tessellator keeps an edge vertex's 0 or 1 exact; it errs along the edge.
                        float Off(float x) => x == 0f || x == 1f ? x : x + d;
                        var drawn = new Float2(Off(tess.x), Off(tess.y));
                        Assert.That(LevelVertexCache.PointTess(drawn, set), Is.EqualTo(tess), $"{set}: tess {tess} drawn at {drawn}");
                        points++;
                    }
            Assert.That(points, Is.GreaterThan(10000));
        }

        [Test]
        public void CulledTilesTakeNoRecordsAndTheTotalIsTheBlocksSum()
        {
            TileFactorSet[] f = Frame(100, 11);
            var first = new long[f.Length];
            long total = LevelVertexCache.TileFirstRecords(f, first);
            long sum = 0;
            for (int p = 0; p < f.Length; p++)
            {
                Assert.That(first[p], Is.EqualTo(sum), $"patch {p} starts after the blocks before it");
                int slots = LevelVertexCache.TileSlots(f[p]);
                if (f[p].IsCulled) Assert.That(slots, Is.EqualTo(0), $"patch {p} is culled");
                else Assert.That(slots, Is.EqualTo(VertexCache.SlotsPerTile(LevelVertexCache.TileFactorLimit(f[p]))));
                sum += slots;
            }
            Assert.That(total, Is.EqualTo(sum));
            Assert.That(LevelVertexCache.TileSlots(f[1]), Is.EqualTo(VertexCache.SlotsPerTile(1)), "all six factors 1: L = 1");
            Assert.That(LevelVertexCache.TileSlots(f[2]), Is.EqualTo(VertexCache.SlotsPerTile(64)), "all 64: the single range's S(64)");
        }

        /// <summary>The records buffer: a 16th of the fixed layout first, kept while a frame fits, a quarter above one that did not, never past 2^24.</summary>
        [Test]
        public void TheBufferStartsSmallGrowsPastWhatAFrameNeededAndStaysExactInFloat()
        {
            Assert.That(LevelVertexCache.FirstRecords(3840, 64), Is.EqualTo(3840 * VertexCache.SlotsPerTile(64) / 16));
            Assert.That(LevelVertexCache.FirstRecords(0, 64), Is.EqualTo(1), "a buffer is never empty");
            Assert.That(LevelVertexCache.GrownRecords(1000, 1000), Is.EqualTo(1000), "a frame that fits keeps the buffer");
            Assert.That(LevelVertexCache.GrownRecords(400, 1000), Is.EqualTo(1000), "never shrinks");
            Assert.That(LevelVertexCache.GrownRecords(1001, 1000), Is.EqualTo(1251));
            Assert.That(LevelVertexCache.GrownRecords(1L << 30, 1000), Is.EqualTo(LevelVertexCache.MaxRecords));
            Assert.That(LevelVertexCache.FirstRecords(1 << 20, 64), Is.EqualTo(LevelVertexCache.MaxRecords));
            Assert.That((float)LevelVertexCache.MaxRecords - 1f, Is.Not.EqualTo((float)LevelVertexCache.MaxRecords), "every count below the bound is exact in float");
            // Vulkan's guaranteed bound range (2^27 bytes): 16-byte records stop at 2^23, 32-byte (snow) at 2^22,
            // whatever the device allocates; a device allocating less stops them sooner.
            Assert.That(LevelVertexCache.RecordLimit(16, 1L << 31), Is.EqualTo(1 << 23));
            Assert.That(LevelVertexCache.RecordLimit(32, 0), Is.EqualTo(1 << 22), "unknown device limit: the bound range");
            Assert.That(LevelVertexCache.RecordLimit(16, 1L << 24), Is.EqualTo(1 << 20), "the device's largest buffer");
            Assert.That(LevelVertexCache.RecordLimit(4, 1L << 40), Is.EqualTo(LevelVertexCache.MaxRecords), "small records: the float bound first");
            var e = Assert.Throws<ArgumentOutOfRangeException>(() => LevelVertexCache.FirstRecords(-1, 64));
            Assert.That(e.ParamName, Is.EqualTo("drawnTiles"));
        }

        [Test]
        public void ATilesLimitIsItsLargestFactor()
        {
            Assert.That(LevelVertexCache.TileFactorLimit(Set(3, 9, 2, 5, 4, 7)), Is.EqualTo(9));
            Assert.That(LevelVertexCache.TileFactorLimit(Set(3, 1, 2, 5, 4, 17)), Is.EqualTo(17), "an inside factor");
            Assert.That(LevelVertexCache.TileFactorLimit(TileFactors.CulledTileFactors()), Is.EqualTo(0));
        }

        [Test]
        public void BadInputNamesTheFieldAndWritesNothing()
        {
            TileFactorSet[] f = Frame(8, 3);
            var first = new long[7];
            Array.Fill(first, -5L);
            var e = Assert.Throws<ArgumentException>(() => LevelVertexCache.TileFirstRecords(f, first));
            Assert.That(e.ParamName, Is.EqualTo("firstRecords"));
            Assert.That(e.Message, Does.Contain("7").And.Contain("8"));
            Assert.That(first, Is.All.EqualTo(-5L), "nothing written");
            e = Assert.Throws<ArgumentException>(() => LevelVertexCache.TileSlots(Set(2.5f, 3, 3, 3, 3, 3)));
            Assert.That(e.ParamName, Is.EqualTo("integerFactors"));
            Assert.That(e.Message, Does.Contain("2.5"));
            Assert.Throws<ArgumentException>(() => LevelVertexCache.TileSlots(Set(65, 3, 3, 3, 3, 3)));
            Assert.Throws<ArgumentException>(() => LevelVertexCache.TileSlots(Set(float.NaN, 3, 3, 3, 3, 3)));
        }
    }
}
