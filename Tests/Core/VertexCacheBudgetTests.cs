using System;
using System.Collections.Generic;
using NUnit.Framework;

namespace GregoryTerrain.Tests
{
    /// <summary>
    /// The vertex cache's buffer sizes (cache spec, "Layout"): the factor limit from <c>_Tess</c>,
    /// the slot count from the slot layout itself (every slot the layout can address, enumerated),
    /// the bytes from hand-worked cases, and the size check the renderer runs before allocating.
    /// </summary>
    [TestFixture]
    public class VertexCacheBudgetTests
    {
        [TestCase(64f, 0f, 64)]     // adaptive: the max factor
        [TestCase(63.2f, 0f, 64)]   // rounded up: the kernel's integer factors reach 64
        [TestCase(17f, 0f, 17)]
        [TestCase(64f, 8f, 8)]      // uniform wins over the max factor
        [TestCase(64f, 7.5f, 8)]
        [TestCase(64f, 0.25f, 1)]   // below 1: clamped up
        [TestCase(1f, 0f, 1)]
        [TestCase(200f, 0f, 64)]    // above the hardware limit: clamped down
        public void FactorLimitFollowsUniformElseMaxFactor(float maxFactor, float uniform, int expected)
        {
            Assert.That(VertexCache.FactorLimit(new Float4(16f, maxFactor, 8f, uniform)), Is.EqualTo(expected));
        }

        [Test]
        public void FactorLimitOfSettingsIsTheOneOfTheirTess()
        {
            var s = new TessellationSettings(16, 40.5f, 4f, 0f);
            Assert.That(VertexCache.FactorLimit(s), Is.EqualTo(VertexCache.FactorLimit(s.ToFloat4())));
            Assert.That(VertexCache.FactorLimit(s), Is.EqualTo(41));
            Assert.Throws<ArgumentException>(() => VertexCache.FactorLimit(new TessellationSettings(16, 0.5f, 4f, 0f)));
        }

        [Test]
        public void FactorLimitRejectsNonFiniteTess()
        {
            var e = Assert.Throws<ArgumentException>(() => VertexCache.FactorLimit(new Float4(16f, float.NaN, 8f, 0f)));
            Assert.That(e.Message, Does.Contain("maxFactor").And.Contain("NaN"));
            e = Assert.Throws<ArgumentException>(() => VertexCache.FactorLimit(new Float4(16f, 64f, 8f, float.PositiveInfinity)));
            Assert.That(e.Message, Does.Contain("uniformFactor"));
            Assert.Throws<ArgumentException>(() => VertexCache.FactorLimit(new Float4(16f, 64f, 8f, -1f)));
        }

        /// <summary>
        /// Every slot the layout addresses for any factors up to L (inside factors Iu, Iv in [2, L]
        /// or the all-ones tile, edge factors in [1, L]) lies below S(L), interior and edge slots never
        /// share an index, and the largest factors reach the last slot: S(L) is exactly enough.
        /// </summary>
        [TestCase(1)]
        [TestCase(2)]
        [TestCase(3)]
        [TestCase(7)]
        [TestCase(64)]
        public void SlotsPerTileHoldsEverySlotTheLayoutAddresses(int limit)
        {
            int s = VertexCache.SlotsPerTile(limit);
            var interior = new HashSet<int>();
            int highest = -1;
            // Interior points (0 < i < Iu, 0 < j < Iv) at slot i + j (Iu + 1), every inside-factor pair.
            for (int iu = 1; iu <= limit; iu++)
                for (int iv = 1; iv <= limit; iv++)
                    for (int j = 1; j < iv; j++)
                        for (int i = 1; i < iu; i++)
                        {
                            int slot = i + j * (iu + 1);
                            interior.Add(slot);
                            highest = Math.Max(highest, slot);
                        }
            // Edge e, point k of F_e + 1 at (L+1)^2 + e (L+1) + k.
            var edges = new HashSet<int>();
            for (int e = 0; e < 4; e++)
                for (int f = 1; f <= limit; f++)
                    for (int k = 0; k <= f; k++)
                    {
                        int slot = (limit + 1) * (limit + 1) + e * (limit + 1) + k;
                        edges.Add(slot);
                        highest = Math.Max(highest, slot);
                    }
            Assert.That(highest, Is.EqualTo(s - 1), "the last slot is used and none lies beyond");
            interior.IntersectWith(edges);
            Assert.That(interior, Is.Empty, "interior and edge slots are disjoint");
            // Edge points are 4 (L+1) distinct slots.
            Assert.That(edges.Count, Is.EqualTo(4 * (limit + 1)));
        }

        [Test]
        public void SlotsPerTileRejectsLimitsOutsideTheHardwareRange()
        {
            var e = Assert.Throws<ArgumentException>(() => VertexCache.SlotsPerTile(0));
            Assert.That(e.Message, Does.Contain("factorLimit").And.Contain("0"));
            Assert.Throws<ArgumentException>(() => VertexCache.SlotsPerTile(65));
        }

        [Test]
        public void BytesOfHandWorkedCases()
        {
            // M = 1, L = 1: a 2 x 2 inside grid (4 slots) + 4 edges of 2 points (8) = 12 slots;
            // one uint4 each, 16 bytes: 192 bytes; with snow 2 uint4: 384.
            Assert.That(VertexCacheBudget.VertexCacheBytes(1, 1, false), Is.EqualTo(192));
            Assert.That(VertexCacheBudget.VertexCacheBytes(1, 1, true), Is.EqualTo(384));
            // M = 16, L = 64: 65^2 + 4 * 65 = 4485 slots per tile, 256 tiles, one uint4: 1,148,160 uint4.
            Assert.That(VertexCacheBudget.VertexCacheUint4s(16, 64, false), Is.EqualTo(256L * 4485));
            Assert.That(VertexCacheBudget.VertexCacheBytes(16, 64, false), Is.EqualTo(18_370_560L));
            // A tile's records: 64 bytes of factors and keys, 928 of its cell (2 + 5 + 51 float4): 992 in all.
            Assert.That(VertexCacheBudget.TileFactorsBytes(16), Is.EqualTo(256 * 64));
            Assert.That(VertexCacheBudget.TileCellsBytes(16), Is.EqualTo(256 * 928));
            Assert.That(VertexCacheBudget.TotalBytes(16, 64, false), Is.EqualTo(18_370_560L + 253_952));
            TestContext.Out.WriteLine($"M = 16, L = 64: {VertexCacheBudget.TotalBytes(16, 64, false)} bytes, with snow {VertexCacheBudget.TotalBytes(16, 64, true)}; M = 64, L = 64, snow: {VertexCacheBudget.TotalBytes(64, 64, true)}");
        }

        [Test]
        public void LargestSettingsDoNotOverflow()
        {
            // M = 1024 (TessellationSettings' limit), L = 64, snow: about 2.3e11 bytes, far above int.
            long bytes = VertexCacheBudget.VertexCacheBytes(1024, 64, true);
            double expect = 1024.0 * 1024.0 * 4485.0 * 2.0 * 16.0;
            Assert.That((double)bytes, Is.EqualTo(expect));
            Assert.That(bytes, Is.GreaterThan((long)int.MaxValue));
        }

        [Test]
        public void CheckFitsAcceptsTheExactLimitAndNamesTheBytesAbove()
        {
            long need = VertexCacheBudget.VertexCacheBytes(32, 64, true);
            Assert.DoesNotThrow(() => VertexCacheBudget.CheckFits(32, 64, true, need));
            var e = Assert.Throws<ArgumentException>(() => VertexCacheBudget.CheckFits(32, 64, true, need - 1));
            Assert.That(e.Message, Does.Contain("tiles = 32").And.Contain(need.ToString(System.Globalization.CultureInfo.InvariantCulture))
                .And.Contain((need - 1).ToString(System.Globalization.CultureInfo.InvariantCulture)));
            Assert.That(e.ParamName, Is.EqualTo("tiles"));
        }

        [Test]
        public void CheckFitsCapsAtTwoGibibytesWhateverTheDeviceSays()
        {
            // M = 64, L = 64, snow: 64^2 * 4485 * 2 * 16 = 587,857,920 bytes: fits 2 GiB.
            Assert.DoesNotThrow(() => VertexCacheBudget.CheckFits(64, 64, true, long.MaxValue));
            // M = 128: four times that (2,351,431,680), above 2 GiB even on a device reporting more.
            var e = Assert.Throws<ArgumentException>(() => VertexCacheBudget.CheckFits(128, 64, true, long.MaxValue));
            Assert.That(e.Message, Does.Contain((1L << 31).ToString(System.Globalization.CultureInfo.InvariantCulture)));
        }

        [Test]
        public void BadArgumentsNameTheField()
        {
            Assert.That(Assert.Throws<ArgumentException>(() => VertexCacheBudget.TileFactorsBytes(0)).Message, Does.Contain("tiles (0)"));
            Assert.That(Assert.Throws<ArgumentException>(() => VertexCacheBudget.CheckFits(4, 8, false, 0)).Message, Does.Contain("maxBufferBytes (0)"));
        }
    }
}
