using NUnit.Framework;

namespace GregoryTerrain.Tests
{
    /// <summary>
    /// Factors of anchored tiles (<see cref="TileFactors.TileFactorsOfCell"/>): a clipped tile draws
    /// its cell's factors scaled to the part it keeps, so a pan changes no cell's factors, and tiles
    /// sharing an edge still agree on it bit for bit. Tools~/RigTests/VertexCacheGpuTests.cs checks
    /// the kernel, which keeps a cell's factors across such a pan, against this mirror.
    /// </summary>
    [TestFixture]
    public class AnchoredTileFactorsTests
    {
        const int M = 8;
        static readonly Float4 Lattice = new Float4(0.1f, 0.15f, 0.9f, 0.95f);

        static TerrainInputs Inputs(Float4 range, Float4 lattice) =>
            TriangleEstimateTests.Inputs(new TessellationSettings(M, 64f, 2f, 0f), null, new TerrainRange(range.x, range.y, range.z, range.w), lattice);

        static TileFactorSet Factors(TerrainInputs inputs, int slot) =>
            TileFactors.ComputeTileFactors(inputs, slot, TriangleEstimateTests.Oblique, TriangleEstimateTests.Screen, TerrainKeywords.Noise);

        [Test]
        public void TheCellsFactorsScaleByThePartKeptAlongEachLine()
        {
            var cell = new TileFactorSet(new Float4(8f, 6f, 5f, 3f), new Float2(7f, 9f));
            Assert.That(TileFactors.TileFactorsOfCell(cell, new Float2(1f, 1f)), Is.EqualTo(cell), "whole: the cell's, bit for bit");
            // Edges u = 0, 1 (x, z) run along v; v = 0, 1 (y, w) along u; inside.x subdivides along u.
            Assert.That(TileFactors.TileFactorsOfCell(cell, new Float2(0.5f, 1f)),
                        Is.EqualTo(new TileFactorSet(new Float4(8f, 3f, 5f, 1.5f), new Float2(3.5f, 9f))));
            Assert.That(TileFactors.TileFactorsOfCell(cell, new Float2(1f, 0.25f)),
                        Is.EqualTo(new TileFactorSet(new Float4(2f, 6f, 1.25f, 3f), new Float2(7f, 2.25f))));
            Assert.That(TileFactors.TileFactorsOfCell(cell, new Float2(0.01f, 0.1f)),
                        Is.EqualTo(new TileFactorSet(new Float4(1f, 1f, 1f, 1f), new Float2(1f, 1f))), "never below 1");
            Assert.That(TileFactors.TileFactorsOfCell(default, new Float2(0.5f, 0.5f)).IsCulled, Is.True, "culled stays culled");
        }

        /// <summary>
        /// Anchored at the lattice, then panned within the same cells: every tile draws its cell's
        /// factors of the anchoring frame (whole tiles bit for bit, clipped ones scaled), and every
        /// edge two drawn tiles share has one factor.
        /// </summary>
        [Test]
        public void APanKeepsEveryCellsFactorsAndSharedEdgesAgree()
        {
            TerrainInputs anchored = Inputs(Lattice, Lattice);
            Float4 panned = new Float4(Lattice.x + 0.0123f, Lattice.y + 0.0077f, Lattice.z + 0.0123f, Lattice.w + 0.0077f);
            TerrainInputs pan = Inputs(panned, Lattice);
            int across = M + 1, scaled = 0, pairs = 0;
            var f = new TileFactorSet[across * across];
            for (int slot = 0; slot < across * across; slot++) f[slot] = Factors(pan, slot);
            for (int j = 0; j < across; j++)
                for (int i = 0; i < across; i++)
                {
                    int slot = TileLatticeTests.SlotOf(pan.Params, i, j);
                    string at = $"tile ({i}, {j})";
                    if (i < M && j < M)   // cells 0..M-1: whole when anchored (cell M was empty then)
                    {
                        TileFactorSet cell = Factors(anchored, TileLatticeTests.SlotOf(anchored.Params, i, j));
                        Float2 kept = TileLattice.TileKeptFraction(pan.Params, slot);
                        Assert.That(f[slot], Is.EqualTo(TileFactors.TileFactorsOfCell(cell, kept)), at + ": its cell's factors, kept " + kept);
                        if (kept.x < 1f || kept.y < 1f) scaled++;
                    }
                    if (f[slot].IsCulled) continue;
                    if (i < M && !f[TileLatticeTests.SlotOf(pan.Params, i + 1, j)].IsCulled)
                    {
                        Assert.That(f[slot].edge.z, Is.EqualTo(f[TileLatticeTests.SlotOf(pan.Params, i + 1, j)].edge.x), at + ": the edge u = 1");
                        pairs++;
                    }
                    if (j < M && !f[TileLatticeTests.SlotOf(pan.Params, i, j + 1)].IsCulled)
                    {
                        Assert.That(f[slot].edge.w, Is.EqualTo(f[TileLatticeTests.SlotOf(pan.Params, i, j + 1)].edge.y), at + ": the edge v = 1");
                        pairs++;
                    }
                }
            TestContext.Out.WriteLine("{0} clipped tiles scaled from their cells, {1} shared edges agree", scaled, pairs);
            Assert.That(scaled, Is.GreaterThan(M), "the first row and column are clipped");
            Assert.That(pairs, Is.GreaterThan(M * M), "most edges are drawn on both sides");
        }
    }
}
