using System;
using System.Collections.Generic;
using System.Linq;
using System.Runtime.InteropServices;
using NUnit.Framework;

namespace GregoryTerrain.Tests
{
    /// <summary>The vertex cache's layout (VertexCache.cs, mirrored by Shaders/Cache/VertexCache.hlsl).</summary>
    [TestFixture]
    public class VertexCacheTests
    {
        internal static TileFactorSet Set(float e0, float e1, float e2, float e3, float i0, float i1) =>
            new TileFactorSet(new Float4(e0, e1, e2, e3), new Float2(i0, i1));

        [Test]
        public void IntegerFactorsRoundUpAndClamp()
        {
            var f = VertexCache.IntegerFactors(Set(1.01f, 2f, 63.5f, 100f, 0.2f, 7.9f));
            Assert.That(f, Is.EqualTo(Set(2f, 2f, 64f, 64f, 2f, 8f)));
        }

        [Test]
        public void InsideFactorOfOneBecomesTwoUnlessEverythingIsOne()
        {
            Assert.That(VertexCache.IntegerFactors(Set(1, 1, 1, 1, 1, 1)), Is.EqualTo(Set(1, 1, 1, 1, 1, 1)));
            Assert.That(VertexCache.IntegerFactors(Set(1, 3, 1, 1, 1, 1)), Is.EqualTo(Set(1, 3, 1, 1, 2, 2)));
            Assert.That(VertexCache.IntegerFactors(Set(1, 1, 1, 1, 1, 5)), Is.EqualTo(Set(1, 1, 1, 1, 2, 5)));
        }

        [Test]
        public void CulledTilesStayCulled()
        {
            var culled = VertexCache.IntegerFactors(Set(0, 0, 0, 0, 0, 0));
            Assert.That(culled.IsCulled, Is.True);
            Assert.That(VertexCache.TilePoints(culled, 8).Count(), Is.EqualTo(0));
        }

        [Test]
        public void FactorLimitIsTheUniformFactorElseTheMaximum()
        {
            Assert.That(VertexCache.FactorLimit(TessellationSettings.Uniform(8, 6.5f)), Is.EqualTo(7));
            Assert.That(VertexCache.FactorLimit(new TessellationSettings(8, 33f, 1f, 0f)), Is.EqualTo(33));
            Assert.That(VertexCache.FactorLimit(new TessellationSettings(8, 64f, 1f, 0f)), Is.EqualTo(64));
        }

        [Test]
        public void SizesFollowTheFormula()
        {
            Assert.That(VertexCache.SlotsPerTile(64), Is.EqualTo(65 * 65 + 4 * 65));
            Assert.That(VertexCacheBudget.VertexCacheBytes(32, 64, false), Is.EqualTo(32L * 32 * 4485 * 1 * 16));
            Assert.That(VertexCacheBudget.VertexCacheBytes(32, 64, true), Is.EqualTo(32L * 32 * 4485 * 2 * 16));
            Assert.That(VertexCacheBudget.TileFactorsBytes(16), Is.EqualTo(16L * 16 * 4 * 16));
            Assert.That(VertexCacheBudget.TileCellsBytes(16), Is.EqualTo(16L * 16 * (2 + 5 + 51) * 16));
            Assert.That(() => VertexCache.SlotsPerTile(0), Throws.InstanceOf<ArgumentException>());
            Assert.That(() => VertexCache.SlotsPerTile(65), Throws.InstanceOf<ArgumentException>());
        }

        /// <summary>Each record's Stride, the GraphicsBuffer stride the renderer gives, is the struct's size.</summary>
        [Test]
        public void RecordStridesAreTheStructSizes()
        {
            Assert.That(TileFactorRecord.Stride, Is.EqualTo(Marshal.SizeOf<TileFactorRecord>()).And.EqualTo(64));
            Assert.That(TileCellRecord.Stride, Is.EqualTo(Marshal.SizeOf<TileCellRecord>()).And.EqualTo(928));
            Assert.That(LodFactorRecord.Stride, Is.EqualTo(Marshal.SizeOf<LodFactorRecord>()).And.EqualTo(64));
        }

        /// <summary>
        /// CacheTileVertices' groups per tile: at every limit they cover the largest tile (the one at
        /// the limit everywhere, whose point count MaxTilePoints is), one group fewer would not, and
        /// no group makes more than PassesPerGroup passes.
        /// </summary>
        [Test]
        public void GroupsPerTileCoverTheLargestTileInAFewPasses()
        {
            const int perGroup = VertexCache.VertexThreadsPerGroup * VertexCache.PassesPerGroup;
            for (int limit = 1; limit <= 64; limit++)
            {
                var full = VertexCache.IntegerFactors(Set(limit, limit, limit, limit, limit, limit));
                int points = VertexCache.TilePoints(full, limit, anchored: true).Count();
                Assert.That(VertexCache.TilePoints(full, limit).Count(), Is.EqualTo(points - 4 * limit), $"limit {limit}: the grid's border");
                Assert.That(VertexCache.MaxTilePoints(limit), Is.EqualTo(points), $"limit {limit}");
                int groups = VertexCache.GroupsPerTile(limit);
                Assert.That(groups * perGroup, Is.GreaterThanOrEqualTo(points), $"limit {limit}");
                Assert.That((groups - 1) * perGroup, Is.LessThan(points), $"limit {limit}");
            }
            Assert.That(VertexCache.GroupsPerTile(17), Is.EqualTo(1));
            // CacheTileFactors: a group a tile, a sample a lane.
            Assert.That(VertexCache.FactorSamplesPerTile, Is.EqualTo(51).And.LessThanOrEqualTo(VertexCache.FactorThreadsPerGroup));
            Assert.That(VertexCache.GroupsPerTile(64), Is.EqualTo(9));
            Assert.That(() => VertexCache.GroupsPerTile(0), Throws.InstanceOf<ArgumentException>());
        }

        /// <summary>
        /// For many factor sets: the kernel's points have distinct slots inside the tile's stride, the
        /// tessellator's vertices (every tess coordinate integer partitioning makes) all find a written
        /// slot, and the slot the domain stage computes is the one the kernel wrote that point to.
        /// </summary>
        [Test]
        public void EveryTessellatorVertexFindsTheSlotTheKernelWrote()
        {
            var random = new Random(5);
            for (int trial = 0; trial < 400; trial++)
            {
                int limit = trial < 200 ? 1 + random.Next(8) : 1 + random.Next(64);
                float F() => 1f + (float)(random.NextDouble() * (limit - 1));
                var f = VertexCache.IntegerFactors(Set(F(), F(), F(), F(), F(), F()));
                var points = VertexCache.TilePoints(f, limit).ToList();
                var written = new Dictionary<int, Float2>();
                foreach (var (tess, slot) in points)
                {
                    Assert.That(slot, Is.InRange(0, VertexCache.SlotsPerTile(limit) - 1), $"{f}, limit {limit}");
                    Assert.That(written.ContainsKey(slot), Is.False, $"{f}: slot {slot} written twice");
                    written[slot] = tess;
                }
                // The domain stage's slot for each point holds that point (a corner is written by both
                // its edges; the domain reads one of the two).
                foreach (var (tess, _) in points)
                    Assert.That(written[VertexCache.Slot(tess, f, limit)], Is.EqualTo(tess), $"{f}: tess {tess}");
                // Integer partitioning's vertices: the inside grid's interior and each edge's k / F.
                for (int j = 1; j < f.inside.y; j++)
                    for (int i = 1; i < f.inside.x; i++)
                        Assert.That(written.ContainsKey(VertexCache.Slot(new Float2(i / f.inside.x, j / f.inside.y), f, limit)), Is.True, $"{f}: inside ({i}, {j})");
                Assert.That(points.Count, Is.EqualTo((int)((f.inside.x - 1) * (f.inside.y - 1) + f.edge.x + f.edge.y + f.edge.z + f.edge.w + 4)));
            }
        }

        /// <summary>A fixed-point tessellator's coordinates (lavapipe: 1.2e-4 off) still find their slot.</summary>
        [Test]
        public void SlotToleratesTessellatorRounding()
        {
            var f = Set(63, 64, 17, 5, 64, 63);
            Assert.That(VertexCache.Slot(new Float2(26f / 64f + 1.2e-4f, 32f / 63f - 1.2e-4f), f, 64), Is.EqualTo(VertexCache.InteriorSlot(26, 32, 64)));
            Assert.That(VertexCache.Slot(new Float2(1f, 3f / 17f + 1.2e-4f), f, 64), Is.EqualTo(VertexCache.EdgeSlot(2, 3, 64)));
        }

        [Test]
        public void RecordHoldsThePositionBitsAndThePackedShading()
        {
            var v = new TerrainVertexOutput
            {
                position = new Float3(1f, 2f, -3.5f), normal = new Float3(0f, 0.6f, 0.8f),
                absoluteHeight = 2.5f, colorNoise = -0.25f, snowDepth = 0.125f,
            };
            uint[] r = VertexCache.Record(v, 0.75f, snow: true);
            Assert.That(r.Length, Is.EqualTo(8));
            // (x, z, y): Unity is Y-up; the float bits as they are.
            Assert.That(new[] { r[0], r[1], r[2] }, Is.EqualTo(new[] { Bits(1f), Bits(-3.5f), Bits(2f) }));
            Float2 e = NormalEncoding.LambertEncodeNormal(new Float3(0f, 0.8f, 0.6f));
            Assert.That(r[3], Is.EqualTo(VertexCache.PackCachedVaryings(new Float3(e.x, e.y, 0.75f))));
            Assert.That(new[] { r[4], r[5], r[6], r[7] }, Is.EqualTo(new[] { Bits(0.125f), 0u, 0u, 0u }));
            Assert.That(VertexCache.Record(v, 0.75f, snow: false).Length, Is.EqualTo(4));
            Assert.That(VertexCache.Uint4sPerRecord(false), Is.EqualTo(1));
            Assert.That(VertexCache.Uint4sPerRecord(true), Is.EqualTo(2));
        }

        static uint Bits(float f) => (uint)BitConverter.SingleToInt32Bits(f);

        [Test]
        public void PackedVaryingsLayOutElevenElevenTenBits()
        {
            // e = 0 is code 1023 exactly: a flat terrain's normal comes back straight up.
            Assert.That(VertexCache.PackCachedVaryings(new Float3(0f, 0f, 0f)), Is.EqualTo(1023u | (1023u << 11)));
            Assert.That(VertexCache.UnpackCachedVaryings(1023u | (1023u << 11)), Is.EqualTo(new Float3(0f, 0f, 0f)));
            // The ends: e = -2 -> 0, e = 2 -> 2046, s = 1 -> 1023.
            Assert.That(VertexCache.PackCachedVaryings(new Float3(-2f, 2f, 1f)), Is.EqualTo(0u | (2046u << 11) | (1023u << 22)));
            Assert.That(VertexCache.UnpackCachedVaryings(0u | (2046u << 11) | (1023u << 22)), Is.EqualTo(new Float3(-2f, 2f, 1f)));
            // Out of range clamps (never spills into the next field); NaN would not reach here (the
            // kernel's normal is unit, the weight saturated).
            Assert.That(VertexCache.PackCachedVaryings(new Float3(-7f, 9f, 3f)), Is.EqualTo(VertexCache.PackCachedVaryings(new Float3(-2f, 2f, 1f))));
            Assert.That(VertexCache.PackCachedVaryings(new Float3(0f, 0f, -0.5f)) >> 22, Is.EqualTo(0u));
        }

        /// <summary>
        /// Every upper-hemisphere normal and every weight comes back within half a step of its code
        /// (1 / 1023 on e, 1 / 2046 on s), and the decoded normal within 0.12 degrees: less than half
        /// an 8-bit step of a Lambert term (0.5 / 255 = 0.0020 rad, as a change of n . l).
        /// </summary>
        [Test]
        public void PackedVaryingsStayWithinHalfAStep()
        {
            double worstE = 0, worstS = 0, worstAngle = 0;
            for (int i = 0; i <= 400; i++)
            {
                double polar = Math.PI / 2 * i / 400;   // 0: straight up, pi / 2: a vertical wall
                for (int j = 0; j < 360; j++)
                {
                    double azimuth = 2 * Math.PI * (j + 0.37) / 360;
                    var n = new Float3((float)(Math.Sin(polar) * Math.Cos(azimuth)), (float)Math.Cos(polar), (float)(Math.Sin(polar) * Math.Sin(azimuth)));
                    Float2 e = NormalEncoding.LambertEncodeNormal(n);
                    float s = (i * 360 + j) / (401f * 360f);
                    Float3 back = VertexCache.UnpackCachedVaryings(VertexCache.PackCachedVaryings(new Float3(e.x, e.y, s)));
                    worstE = Math.Max(worstE, Math.Max(Math.Abs(back.x - e.x), Math.Abs(back.y - e.y)));
                    worstS = Math.Max(worstS, Math.Abs(back.z - s));
                    Float3 m = NormalEncoding.LambertDecodeNormal(new Float2(back.x, back.y));
                    double cos = GMath.dot(m, n) / (GMath.length(m) * GMath.length(n));
                    worstAngle = Math.Max(worstAngle, Math.Acos(Math.Min(1.0, cos)));
                }
            }
            TestContext.Out.WriteLine("packed varyings, upper hemisphere: e within {0:G4} (half step {1:G4}), s within {2:G4} (half step {3:G4}), normal within {4:G4} degrees",
                worstE, 1.0 / 1023, worstS, 0.5 / 1023, worstAngle * 180 / Math.PI);
            Assert.That(worstE, Is.LessThanOrEqualTo(1.0 / 1023 + 1e-6));
            Assert.That(worstS, Is.LessThanOrEqualTo(0.5 / 1023 + 1e-6));
            Assert.That(worstAngle * 180 / Math.PI, Is.LessThan(0.12));
            Assert.That(worstAngle, Is.LessThan(0.5 / 255));
        }
    }
}
