using System;
using NUnit.Framework;

namespace GregoryTerrain.Tests
{
    /// <summary>Anchored tiles (TileLattice): coverage, watertightness, and what a pan leaves alone.</summary>
    [TestFixture]
    public class TileLatticeTests
    {
        const int M = 8;
        static readonly Float4 Lattice = new Float4(0.25f, 0.30f, 0.65f, 0.70f);

        static TerrainParams Params(Float4 range, Float4 lattice, int tiles = M) => new TerrainParams
        {
            range = range, tess = new Float4(tiles, 64f, 1f, 0f), tileLattice = lattice,
        };

        // The lattice shifted by (dx, dy), as a pan moves the range.
        static Float4 Panned(float dx, float dy) => new Float4(Lattice.x + dx, Lattice.y + dy, Lattice.z + dx, Lattice.w + dy);

        static readonly float[] Pans = { 0f, 1e-4f, 0.013f, 0.05f, 0.0499f, -0.031f, 0.17f, -0.4f };
        static readonly float[] Tess = { 0f, 0.125f, 1f / 3f, 0.5f, 0.7f, 1f };

        internal static int SlotOf(TerrainParams p, int i, int j)
        {
            int across = TileLattice.TilesAcross(p);
            int k0x = TileLattice.FirstCell(p.range.x, p.tileLattice.x, p.tileLattice.z, p.tess.x);
            int k0y = TileLattice.FirstCell(p.range.y, p.tileLattice.y, p.tileLattice.w, p.tess.x);
            int sx = ((k0x + i) % across + across) % across, sy = ((k0y + j) % across + across) % across;
            return sy * across + sx;
        }

        static Float2 At(TerrainParams p, int slot, float s, float t)
        {
            TerrainPoint q = TileLattice.TileToTerrainPoint(p, slot, s, t);
            return q.local;   // origin 0: local is q
        }

        [Test]
        public void TheKernelsSeeOnlyThePansThatChangeTheFirstCells()
        {
            TerrainParams p = Params(Panned(0.0123f, -0.0456f), Lattice);
            Float4 k = TileLattice.KernelRange(p);
            Assert.That(TileLattice.KernelRange(Params(Panned(0.0125f, -0.0451f), Lattice)), Is.EqualTo(k), "a pan inside the cells");
            Assert.That(TileLattice.KernelRange(Params(Panned(0.0123f + 0.05f, -0.0456f), Lattice)), Is.Not.EqualTo(k), "a pan across a lattice line");
            Assert.That(TileLattice.KernelRange(Params(Panned(0.0123f, -0.0456f - 0.05f), Lattice)), Is.Not.EqualTo(k), "across a row");
            var range = new Float4(0.1f, 0.2f, 0.7f, 0.9f);
            Assert.That(TileLattice.KernelRange(Params(range, new Float4(0f, 0f, 0f, 0f))), Is.EqualTo(range), "laid over the range: the range");
        }

        [Test]
        public void ZeroLatticeLeavesTheTilesOnTheRangeBitForBit()
        {
            var range = new Float4(0.1f, 0.2f, 0.7f, 0.9f);
            TerrainParams p = Params(range, new Float4(0f, 0f, 0f, 0f));
            Assert.That(TileLattice.TilesAcross(p), Is.EqualTo(M));
            for (int slot = 0; slot < M * M; slot++)
                foreach (float s in Tess)
                    foreach (float t in Tess)
                    {
                        Float2 a = At(p, slot, s, t);
                        Float2 b = RangeMapping.ToTerrainPoint(range, p.rangeOrigin, M, slot % M, slot / M, s, t).local;
                        Assert.That(a.x == b.x && a.y == b.y, Is.True, $"slot {slot} ({s}, {t}): {a} vs {b}");
                    }
            Assert.That(TileLattice.LayoutWidth(p), Is.EqualTo(range.z - range.x));
        }

        [Test]
        public void AnchoredTilesCoverTheRangeEdgeToEdge()
        {
            foreach (float dx in Pans)
                foreach (float shrink in new[] { 0f, 0.02f })
                {
                    Float4 r = Panned(dx, -dx);
                    r = new Float4(r.x, r.y, r.z - shrink, r.w - shrink);   // also a range a little narrower than the lattice
                    TerrainParams p = Params(r, Lattice);
                    Assert.That(TileLattice.TilesAcross(p), Is.EqualTo(M + 1));
                    for (int axis = 0; axis < 2; axis++)
                    {
                        float prevEnd = float.NaN;
                        for (int i = 0; i <= M; i++)
                        {
                            Float4 span = TileLattice.TileSpan(p, axis == 0 ? SlotOf(p, i, 0) : SlotOf(p, 0, i));
                            float l = axis == 0 ? span.x : span.y, h = axis == 0 ? span.z : span.w;
                            string at = $"pan {dx}, shrink {shrink}, axis {axis}, tile {i}";
                            Assert.That(l, Is.LessThanOrEqualTo(h), at);
                            if (i == 0) Assert.That(l, Is.EqualTo(axis == 0 ? r.x : r.y), at + ": starts at the range");
                            else Assert.That(l == prevEnd, Is.True, $"{at}: starts at {l:R}, the tile before ends at {prevEnd:R}");
                            prevEnd = h;
                        }
                        Assert.That(prevEnd, Is.EqualTo(axis == 0 ? r.z : r.w), $"pan {dx}, axis {axis}: ends at the range");
                    }
                }
        }

        [Test]
        public void SharedEdgesAreBitIdenticalFromBothTiles()
        {
            foreach (float dx in Pans)
            {
                TerrainParams p = Params(Panned(dx, 0.5f * dx), Lattice);
                for (int j = 0; j <= M; j++)
                    for (int i = 0; i < M; i++)
                        foreach (float t in Tess)
                        {
                            Float2 left = At(p, SlotOf(p, i, j), 1f, t), right = At(p, SlotOf(p, i + 1, j), 0f, t);
                            Assert.That(left.x == right.x && left.y == right.y, Is.True, $"pan {dx}: x edge of tiles {i}/{i + 1}, row {j}, t {t}: {left} vs {right}");
                            Float2 below = At(p, SlotOf(p, j, i), t, 1f), above = At(p, SlotOf(p, j, i + 1), t, 0f);
                            Assert.That(below.x == above.x && below.y == above.y, Is.True, $"pan {dx}: y edge of tiles {i}/{i + 1}, column {j}, s {t}: {below} vs {above}");
                        }
            }
        }

        [Test]
        public void APanMovesOnlyTheClippedTiles()
        {
            // Two ranges in the same lattice, the second crossing a lattice line (k0 moves by one):
            // every cell whole in both keeps its slot and its points bit for bit.
            float cell = (Lattice.z - Lattice.x) / M;
            TerrainParams a = Params(Panned(0.3f * cell, 0.6f * cell), Lattice);
            TerrainParams b = Params(Panned(1.4f * cell, 0.7f * cell), Lattice);
            int across = M + 1, kept = 0, moved = 0;
            for (int slot = 0; slot < across * across; slot++)
            {
                Float4 sa = TileLattice.TileSpan(a, slot), sb = TileLattice.TileSpan(b, slot);
                bool same = sa.x == sb.x && sa.y == sb.y && sa.z == sb.z && sa.w == sb.w;
                if (!same) { moved++; continue; }
                kept++;
                foreach (float s in Tess)
                    foreach (float t in Tess)
                    {
                        Float2 pa = At(a, slot, s, t), pb = At(b, slot, s, t);
                        Assert.That(pa.x == pb.x && pa.y == pb.y, Is.True, $"slot {slot} ({s}, {t}): {pa} vs {pb}");
                    }
            }
            // Whole in both: columns 2..M-1 of the first range's cells that the second still holds
            // whole (M - 2 of them) times rows 1..M-1 (M - 1): the rest are clipped in one of the two.
            Assert.That(kept, Is.EqualTo((M - 2) * (M - 1)), $"{kept} kept, {moved} moved");
        }

        /// <summary>
        /// The cells the factors are decided on: each holds its tile; a whole tile is its cell point
        /// for point; the part kept is 1 exactly on a whole axis, else the span over the cell, and
        /// shared along rows and columns (as are the cells' edge lengths), so tiles sharing an edge
        /// scale it alike; a pan that keeps a slot's cell keeps its cell points bit for bit.
        /// </summary>
        [Test]
        public void CellsHoldTheirTilesAndAPanKeepsThem()
        {
            TerrainParams p = Params(Panned(0.0123f, -0.0456f), Lattice);
            TerrainParams q = Params(Panned(0.0125f, -0.0451f), Lattice);   // the same first cells
            int clipped = 0;
            for (int j = 0; j <= M; j++)
                for (int i = 0; i <= M; i++)
                {
                    int slot = SlotOf(p, i, j);
                    string at = $"tile ({i}, {j})";
                    Float4 span = TileLattice.TileSpan(p, slot), cell = TileLattice.CellSpan(p, slot);
                    Assert.That(cell.x <= span.x && cell.y <= span.y && span.z <= cell.z && span.w <= cell.w, Is.True, $"{at}: {cell} holds {span}");
                    Float2 kept = TileLattice.TileKeptFraction(p, slot);
                    Assert.That(kept.x, Is.EqualTo(TileLattice.TileKeptFraction(p, SlotOf(p, i, 0)).x), $"{at}: a column shares its part");
                    Assert.That(kept.y, Is.EqualTo(TileLattice.TileKeptFraction(p, SlotOf(p, 0, j)).y), $"{at}: a row shares its part");
                    Assert.That(kept.x, Is.InRange(0f, 1f), at);
                    Assert.That(kept.y, Is.InRange(0f, 1f), at);
                    bool wholeX = span.x == cell.x && span.z == cell.z, wholeY = span.y == cell.y && span.w == cell.w;
                    Assert.That(kept.x == 1f, Is.EqualTo(wholeX || span.z - span.x == cell.z - cell.x), $"{at}: x");
                    if (!wholeX) Assert.That(kept.x, Is.EqualTo((span.z - span.x) / (cell.z - cell.x)).Within(1e-6f), at);
                    Float2 e = TileLattice.CellEdgeLengths(p, slot);
                    Assert.That(e.x, Is.EqualTo(TileLattice.CellEdgeLengths(p, SlotOf(p, i, 0)).x), $"{at}: a column shares its width");
                    Assert.That(e.y, Is.EqualTo(TileLattice.CellEdgeLengths(p, SlotOf(p, 0, j)).y), $"{at}: a row shares its height");
                    Assert.That(e.x, Is.EqualTo(cell.z - cell.x), at);
                    if (!(wholeX && wholeY)) clipped++;
                    foreach (float s in Tess)
                        foreach (float t in Tess)
                        {
                            Float2 c = TileLattice.CellToTerrainPoint(p, slot, s, t).local, cq = TileLattice.CellToTerrainPoint(q, slot, s, t).local;
                            Assert.That(c.x == cq.x && c.y == cq.y, Is.True, $"{at} ({s}, {t}): the pan kept the cell, {c} vs {cq}");
                            if (wholeX && wholeY)
                            {
                                Float2 tile = At(p, slot, s, t);
                                Assert.That(c.x == tile.x && c.y == tile.y, Is.True, $"{at} ({s}, {t}): a whole tile is its cell, {c} vs {tile}");
                            }
                        }
                }
            Assert.That(clipped, Is.EqualTo(4 * M), "the first and last row and column are clipped");
            Assert.That(TileLattice.LayoutWidth(p), Is.EqualTo(Lattice.z - Lattice.x), "the spacing follows the lattice");
            Assert.That(TileLattice.TileKeptFraction(Params(Lattice, new Float4(0f, 0f, 0f, 0f)), 5), Is.EqualTo(new Float2(1f, 1f)), "on the range: whole");
            Assert.Throws<InvalidOperationException>(() => TileLattice.CellSpan(Params(Lattice, new Float4(0f, 0f, 0f, 0f)), 0));
        }

        [Test]
        public void FollowKeepsTheLatticeWhileTheRangePansAndAnchorsAgainOnAZoom()
        {
            Float4 zero = new Float4(0f, 0f, 0f, 0f);
            Assert.That(TileLattice.Follow(zero, Lattice, M), Is.EqualTo(Lattice), "no lattice yet: anchor at the range");
            Float4 panned = Panned(0.2f, -0.1f);
            Assert.That(TileLattice.Follow(Lattice, panned, M), Is.EqualTo(Lattice), "a pan keeps it");
            var wider = new Float4(Lattice.x, Lattice.y, Lattice.z + 0.01f, Lattice.w);
            Assert.That(TileLattice.Follow(Lattice, wider, M), Is.EqualTo(wider), "wider than the lattice: anchor again");
            float w = Lattice.z - Lattice.x;
            var muchNarrower = new Float4(Lattice.x, Lattice.y, Lattice.x + w * (1f - 1.5f / M), Lattice.w);
            Assert.That(TileLattice.Follow(Lattice, muchNarrower, M), Is.EqualTo(muchNarrower), "a zoom of more than a tile: anchor again");
            var slightlyNarrower = new Float4(Lattice.x, Lattice.y, Lattice.x + w * (1f - 0.5f / M), Lattice.w);
            Assert.That(TileLattice.Follow(Lattice, slightlyNarrower, M), Is.EqualTo(Lattice), "less than a tile: kept");
        }

        [Test]
        public void ABadLatticeNamesTheFieldAndChangesNothing()
        {
            TerrainParams p = Params(Lattice, new Float4(0f, 0f, 0f, 0f));
            var bad = new[]
            {
                (new Float4(float.NaN, 0.3f, 0.65f, 0.7f), "NaN"),
                (new Float4(0.65f, 0.3f, 0.25f, 0.7f), "g > c"),
                (new Float4(0.25f, 0.3f, 0.6f, 0.7f), "narrower than the range"),
            };
            foreach (var (lattice, why) in bad)
            {
                var ex = Assert.Throws<ArgumentException>(() => p.WithTileLattice(lattice), why);
                Assert.That(ex.Message, Does.Contain("tileLattice").And.Contain(why), why);
                Assert.That(p.tileLattice, Is.EqualTo(new Float4(0f, 0f, 0f, 0f)), why + ": unchanged");
            }
            Assert.That(p.WithTileLattice(Lattice).TilesAnchored, Is.True);
            Assert.That(p.WithTileLattice(new Float4(0f, 0f, 0f, 0f)).TilesAnchored, Is.False);
        }

        [Test]
        public void TerrainVertexEvaluatesEveryAnchoredSlotAndNoMore()
        {
            PatchGrid grid = PatchGrid.CreateFlat(3, 3);
            TerrainParams p = TerrainParams.Create(grid, new TerrainRange(0.2, 0.2, 0.6, 0.6), RangeOrigin.zero,
                new TessellationSettings(M, 16f, 1f, 4f), NoiseSettings.Default, new HeightColorSettings(0.2f, 0.1f, 16f),
                new Float3(0f, 0f, 0f), new Float3(1f, 1f, 1f));
            p = p.WithTileLattice(p.range);
            p.range = new Float4(p.range.x + 0.013f, p.range.y + 0.021f, p.range.z + 0.013f, p.range.w + 0.021f);
            TerrainInputs inputs = TerrainInputs.Create(grid, p);
            int across = M + 1;
            for (int slot = 0; slot < across * across; slot++)
            {
                TerrainSurfacePoint s = TerrainVertex.EvaluateSurface(inputs, slot, new Float2(0.5f, 0.5f), TerrainKeywords.None);
                Float2 q = RangeMapping.Approximate(s.q);
                Assert.That(q.x >= p.range.x && q.x <= p.range.z && q.y >= p.range.y && q.y <= p.range.w, Is.True, $"slot {slot}: {q} inside the range");
            }
            Assert.Throws<ArgumentException>(() => TerrainVertex.EvaluateSurface(inputs, across * across, new Float2(0.5f, 0.5f), TerrainKeywords.None));
        }
    }
}
