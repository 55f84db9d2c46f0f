using System;
using System.Collections.Generic;
using NUnit.Framework;

namespace GregoryTerrain.Tests
{
    /// <summary>
    /// Anchored tiles drawn from whole cells (<see cref="ClippedCell"/>): a clipped tile's factors and
    /// the cell records each of its vertices reads. Watertight: neighbours read the same records at the
    /// same fractions for every vertex of their shared edge. Covering: a tile's vertices lie in its part
    /// of the cell, in order.
    /// </summary>
    [TestFixture]
    public class ClippedCellTests
    {
        const int M = 8, Limit = 64;
        static readonly Float4 Lattice = new Float4(0.25f, 0.30f, 0.65f, 0.70f);

        static TerrainParams Params(float dx, float dy) => new TerrainParams
        {
            range = new Float4(Lattice.x + dx, Lattice.y + dy, Lattice.z + dx, Lattice.w + dy),
            tess = new Float4(M, Limit, 1f, 0f),
            tileLattice = Lattice,
        };

        static readonly (float dx, float dy)[] Pans = { (0f, 0f), (1e-4f, 3e-4f), (0.013f, -0.0071f), (0.0499f, 0.05f), (-0.031f, 0.17f) };

        [Test]
        public void KeptSegmentsCountTheSegmentsThatMeetThePart()
        {
            Assert.That(ClippedCell.KeptSegments(8f, 0f, 1f), Is.EqualTo(8f), "the whole line");
            Assert.That(ClippedCell.KeptSegments(8f, 0.3f, 1f), Is.EqualTo(6f), "from inside segment 2");
            Assert.That(ClippedCell.KeptSegments(8f, 0f, 0.3f), Is.EqualTo(3f), "up to inside segment 2");
            Assert.That(ClippedCell.KeptSegments(8f, 0.25f, 1f), Is.EqualTo(6f), "from point 2 itself");
            Assert.That(ClippedCell.KeptSegments(8f, 0.3f, 0.31f), Is.EqualTo(1f), "a sliver");
        }

        [Test]
        public void ClippedFactorsAreTheCellsWhereWholeAndNoSegmentIsLonger()
        {
            var cell = new TileFactorSet(new Float4(8f, 6f, 5f, 3f), new Float2(7f, 9f));
            Assert.That(ClippedCell.ClippedTileFactors(cell, new Float4(0f, 1f, 0f, 1f)), Is.EqualTo(cell), "whole: bit for bit");
            Assert.That(ClippedCell.ClippedTileFactors(default, new Float4(0.5f, 1f, 0f, 1f)).IsCulled, Is.True, "culled stays culled");
            Assert.That(ClippedCell.ClippedTileFactors(cell, new Float4(0.4f, 0.4f, 0f, 1f)).IsCulled, Is.True, "no area: culled");
            // u kept from 0.5: lines along u (v = 0, 1: y, w) keep their second half; the edge at u = 0
            // lies on the range's edge and takes the tile's inside count across (9 along v).
            Assert.That(ClippedCell.ClippedTileFactors(cell, new Float4(0.5f, 1f, 0f, 1f)),
                        Is.EqualTo(new TileFactorSet(new Float4(9f, 3f, 5f, 2f), new Float2(4f, 9f))));
            // A sliver keeps one segment across, drawn as 2 inside (the tessellator's rule).
            Assert.That(ClippedCell.ClippedTileFactors(cell, new Float4(0f, 1f, 0.99f, 1f)),
                        Is.EqualTo(new TileFactorSet(new Float4(1f, 7f, 1f, 3f), new Float2(7f, 2f))));
            var rng = new Random(5);
            for (int n = 0; n < 2000; n++)
            {
                var c = new TileFactorSet(new Float4(rng.Next(1, 65), rng.Next(1, 65), rng.Next(1, 65), rng.Next(1, 65)),
                                          new Float2(rng.Next(2, 65), rng.Next(2, 65)));
                float s0 = (float)rng.NextDouble() * 0.9f, s1 = s0 + (1f - s0) * (float)(0.01 + 0.99 * rng.NextDouble());
                var kept = new Float4(s0, s1, 0f, 1f);
                TileFactorSet f = ClippedCell.ClippedTileFactors(c, kept);
                string at = $"{c}, kept {kept}";
                // Segments along u: the inside count and the lines along u (edges v = 0, 1).
                Assert.That((s1 - s0) / f.inside.x, Is.LessThanOrEqualTo(1f / c.inside.x * (1f + 1e-6f)), at + ": inside");
                Assert.That((s1 - s0) / f.edge.y, Is.LessThanOrEqualTo(1f / c.edge.y * (1f + 1e-6f)), at + ": v = 0");
                Assert.That((s1 - s0) / f.edge.w, Is.LessThanOrEqualTo(1f / c.edge.w * (1f + 1e-6f)), at + ": v = 1");
                Assert.That(f.inside.y, Is.EqualTo(c.inside.y), at + ": v is whole");
            }
        }

        /// <summary>
        /// Integer cell factors of a lattice whose shared edges agree (as the kernel's do): a line's
        /// factor depends only on the line, a cell's inside factors on the cell.
        /// </summary>
        static TileFactorSet CellFactors(int cx, int cy)
        {
            static float Hash(int a, int b, int c) => 1f + (uint)(a * 73856093 ^ b * 19349663 ^ c * 83492791) % 40u;
            return new TileFactorSet(new Float4(Hash(cx, cy, 1), Hash(cx, cy, 2), Hash(cx + 1, cy, 1), Hash(cx, cy + 1, 2)),
                                     new Float2(1f + Hash(cx, cy, 3), 1f + Hash(cx, cy, 4)));
        }

        sealed class Tile
        {
            public int slot;
            public TileFactorSet cell, drawn;
            public Float4 kept;
        }

        static Tile TileAt(TerrainParams p, int i, int j)
        {
            int slot = TileLatticeTests.SlotOf(p, i, j);
            Float4 c = TileLattice.CellSpan(p, slot);
            int cx = (int)MathF.Round((c.x - Lattice.x) / (Lattice.z - Lattice.x) * M);
            int cy = (int)MathF.Round((c.y - Lattice.y) / (Lattice.w - Lattice.y) * M);
            TileFactorSet cell = CellFactors(cx, cy);
            Float4 kept = TileLattice.TileKeptCellSpan(p, slot);
            return new Tile { slot = slot, cell = cell, kept = kept, drawn = ClippedCell.ClippedTileFactors(cell, kept) };
        }

        // Where the kernel evaluates slot `s` of a tile's cell, as a terrain point (equal bits: equal records).
        static Float2 SlotPoint(TerrainParams p, Tile t, int s)
        {
            Float2 tess = ClippedCell.CellSlotTess(s, t.cell, Limit);
            return TileLattice.CellToTerrainPoint(p, t.slot, tess.x, tess.y).local;
        }

        // The records a vertex reads, as terrain points and fractions: what makes its bits.
        static string Resolve(TerrainParams p, Tile t, CellPointBlend b)
        {
            string P(int s) { Float2 q = SlotPoint(p, t, s); return FormattableString.Invariant($"({q.x:R}, {q.y:R})"); }
            string u = b.t.x > 0f ? $"{P(b.a)}-{P(b.b)}@{b.t.x:R}" : P(b.a);
            if (b.t.y == 0f) return u;
            string w = b.t.x > 0f ? $"{P(b.c)}-{P(b.d)}@{b.t.x:R}" : P(b.c);
            return $"[{u}]-[{w}]@{b.t.y:R}";
        }

        // Where the vertex lands, blending the terrain points as the domain stage blends records.
        static Float2 Place(TerrainParams p, Tile t, CellPointBlend b)
        {
            Float2 L(Float2 x, Float2 y, float f) => new Float2(x.x + f * (y.x - x.x), x.y + f * (y.y - x.y));
            Float2 ab = b.t.x > 0f ? L(SlotPoint(p, t, b.a), SlotPoint(p, t, b.b), b.t.x) : SlotPoint(p, t, b.a);
            if (b.t.y == 0f) return ab;
            Float2 cd = b.t.x > 0f ? L(SlotPoint(p, t, b.c), SlotPoint(p, t, b.d), b.t.x) : SlotPoint(p, t, b.c);
            return L(ab, cd, b.t.y);
        }

        static float Distance(Float2 a, Float2 b) => MathF.Sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y));

        static float Edge(TileFactorSet f, int e) => e == 0 ? f.edge.x : e == 1 ? f.edge.y : e == 2 ? f.edge.z : f.edge.w;

        // Every drawn (not culled) tile (i, j) of every pan.
        static IEnumerable<(TerrainParams p, int i, int j, Tile t, string at)> DrawnTiles()
        {
            foreach (var (dx, dy) in Pans)
            {
                TerrainParams p = Params(dx, dy);
                for (int j = 0; j <= M; j++)
                    for (int i = 0; i <= M; i++)
                    {
                        Tile t = TileAt(p, i, j);
                        if (!t.drawn.IsCulled) yield return (p, i, j, t, $"pan ({dx}, {dy}), tile ({i}, {j})");
                    }
            }
        }

        static CellPointBlend EdgeVertex(Tile t, int e, int k) =>
            ClippedCell.CellPoint(VertexCache.EdgeTess(e, k, Edge(t.drawn, e)), t.drawn, t.cell, t.kept, Limit);

        [Test]
        public void NeighboursReadTheSameRecordsForEveryVertexOfTheirSharedEdge()
        {
            int clipped = 0;
            foreach (var (p, i, j, a, atA) in DrawnTiles())
            {
                if (!ClippedCell.CellKeptWhole(a.kept)) clipped++;
                foreach (var (ni, nj, ea, eb) in new[] { (i + 1, j, 2, 0), (i, j + 1, 3, 1) })
                {
                    if (ni > M || nj > M) continue;
                    Tile b = TileAt(p, ni, nj);
                    if (b.drawn.IsCulled) continue;
                    string at = $"{atA} and ({ni}, {nj})";
                    Assert.That(Edge(b.drawn, eb), Is.EqualTo(Edge(a.drawn, ea)), at + ": one factor");
                    for (int k = 0; k <= (int)Edge(a.drawn, ea); k++)
                        Assert.That(Resolve(p, b, EdgeVertex(b, eb, k)), Is.EqualTo(Resolve(p, a, EdgeVertex(a, ea, k))), $"{at}, vertex {k}");
                }
            }
            Assert.That(clipped, Is.GreaterThan(4 * M), "the pans clip tiles");
        }

        [Test]
        public void AClippedTilesVerticesLieInItsPartInOrder()
        {
            foreach (var (p, _, _, t, at) in DrawnTiles())
            {
                Float4 span = TileLattice.TileSpan(p, t.slot);
                for (int e = 0; e < 4; e++)
                {
                    int n = (int)Edge(t.drawn, e);
                    Float2 prev = default;
                    for (int k = 0; k <= n; k++)
                    {
                        Float2 q = Place(p, t, EdgeVertex(t, e, k));
                        Assert.That(q.x, Is.InRange(span.x - 1e-6f, span.z + 1e-6f), $"{at}, edge {e} vertex {k}: x");
                        Assert.That(q.y, Is.InRange(span.y - 1e-6f, span.w + 1e-6f), $"{at}, edge {e} vertex {k}: y");
                        float along = e == 0 || e == 2 ? q.y : q.x;
                        if (k > 0) Assert.That(along, Is.GreaterThan(e == 0 || e == 2 ? prev.y : prev.x), $"{at}, edge {e} vertex {k}: in order");
                        prev = q;
                    }
                }
                // The corners are the span's own (the range's edge, or the cell's lines).
                Float2 c00 = Place(p, t, EdgeVertex(t, 1, 0)), c11 = Place(p, t, EdgeVertex(t, 3, (int)t.drawn.edge.w));
                Assert.That(c00.x, Is.EqualTo(span.x).Within(1e-6f), at + ": corner (0, 0)");
                Assert.That(c00.y, Is.EqualTo(span.y).Within(1e-6f), at + ": corner (0, 0)");
                Assert.That(c11.x, Is.EqualTo(span.z).Within(1e-6f), at + ": corner (1, 1)");
                Assert.That(c11.y, Is.EqualTo(span.w).Within(1e-6f), at + ": corner (1, 1)");
                for (int gj = 1; gj < (int)t.drawn.inside.y; gj++)
                    for (int gi = 1; gi < (int)t.drawn.inside.x; gi++)
                    {
                        var tess = new Float2(gi / t.drawn.inside.x, gj / t.drawn.inside.y);
                        Float2 q = Place(p, t, ClippedCell.CellPoint(tess, t.drawn, t.cell, t.kept, Limit));
                        Assert.That(q.x > span.x && q.x < span.z && q.y > span.y && q.y < span.w, Is.True, $"{at}, inside ({gi}, {gj}): {q} in {span}");
                    }
            }
        }

        [Test]
        public void CellSlotTessIsThePointTheKernelWroteEverySlotAt()
        {
            int checkedSlots = 0;
            foreach (var f in new[] { new TileFactorSet(new Float4(5f, 6f, 7f, 8f), new Float2(9f, 10f)), CellFactors(3, 5), CellFactors(-2, 7),
                                      new TileFactorSet(new Float4(1f, 64f, 13f, 2f), new Float2(64f, 2f)) })
                foreach (var (tess, slot) in VertexCache.TilePoints(f, Limit, anchored: true))
                {
                    Assert.That(ClippedCell.CellSlotTess(slot, f, Limit), Is.EqualTo(tess), $"factors {f}, slot {slot}");
                    checkedSlots++;
                }
            Assert.That(checkedSlots, Is.GreaterThan(4 * 4 * 10), "grid and edge slots");
        }

        /// <summary>
        /// CellPointTess is where a vertex lies (its records' points blended as their values are), so
        /// the Patch Id view over the cache finds the patch there: exactly a record's own point where
        /// the vertex reads one record, else within a float step of the blended point. On a clipped
        /// tile that is not the tile's evenly spread point (what the domain stage would evaluate).
        /// </summary>
        [Test]
        public void CellPointTessIsWhereAClippedTilesVertexLies()
        {
            int vertices = 0, offTilePoint = 0;
            foreach (var (p, _, _, t, at) in DrawnTiles())
            {
                // The kernel's own points (VertexCache.TilePoints, whole grid), not CellSlotTess's.
                var written = new Dictionary<int, Float2>();
                foreach (var (tess, slot) in VertexCache.TilePoints(t.cell, Limit, anchored: true)) written[slot] = tess;
                void Check(Float2 tess, string which)
                {
                    CellPointBlend b = ClippedCell.CellPoint(tess, t.drawn, t.cell, t.kept, Limit);
                    Float2 cellTess = ClippedCell.CellPointTess(b, t.cell, Limit);
                    Float2 q = TileLattice.CellToTerrainPoint(p, t.slot, cellTess.x, cellTess.y).local, placed = Place(p, t, b);
                    bool oneRecord = b.t.x == 0f && b.t.y == 0f;
                    if (oneRecord) Assert.That(cellTess, Is.EqualTo(written[b.a]), $"{at}, {which}: the point the kernel wrote the record at");
                    Assert.That(Distance(q, placed), Is.LessThan(1e-6f), $"{at}, {which}: {q} against {placed}");
                    if (Distance(q, TileLattice.TileToTerrainPoint(p, t.slot, tess.x, tess.y).local) > 1e-5f) offTilePoint++;
                    vertices++;
                }
                for (int e = 0; e < 4; e++)
                    for (int k = 0; k <= (int)Edge(t.drawn, e); k++)
                        Check(VertexCache.EdgeTess(e, k, Edge(t.drawn, e)), $"edge {e} vertex {k}");
                for (int gj = 1; gj < (int)t.drawn.inside.y; gj++)
                    for (int gi = 1; gi < (int)t.drawn.inside.x; gi++)
                        Check(new Float2(gi / t.drawn.inside.x, gj / t.drawn.inside.y), $"inside ({gi}, {gj})");
            }
            TestContext.Out.WriteLine($"{vertices} vertices, {offTilePoint} of them away from the tile's evenly spread point");
            Assert.That(offTilePoint, Is.GreaterThan(0), "clipped tiles' vertices sit on their cells' points");
        }

        [Test]
        public void AWholeTileReadsItsSlotsAsBefore()
        {
            // One record, one the kernel wrote for that point (a corner is written by both its edges).
            var f = new TileFactorSet(new Float4(5f, 6f, 7f, 8f), new Float2(9f, 10f));
            var written = new Dictionary<Float2, List<int>>();
            foreach (var (tess, slot) in VertexCache.TilePoints(f, Limit))
                (written.TryGetValue(tess, out var list) ? list : written[tess] = new List<int>()).Add(slot);
            foreach (var (tess, slots) in written)
            {
                CellPointBlend b = ClippedCell.CellPoint(tess, f, f, new Float4(0f, 1f, 0f, 1f), Limit);
                Assert.That(b, Is.EqualTo(ClippedCell.CellSlotBlend(b.a)), $"{tess}: one record");
                Assert.That(slots, Does.Contain(b.a), $"{tess}");
            }
        }
    }
}
