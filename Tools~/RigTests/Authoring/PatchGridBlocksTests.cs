using System;
using System.Linq;
using NUnit.Framework;

namespace GregoryTerrain.Tests
{
    /// <summary>
    /// The grid asset's block layout (PatchGridBlocks): a whole grid survives the trip through blocks bit
    /// for bit, a control point move changes only the blocks it reports in advance (what the editor
    /// records for Undo), and those stay small on the largest grid the tools make (256 x 256).
    /// </summary>
    [TestFixture]
    public class PatchGridBlocksTests
    {
        static PatchGrid FittedGrid(int n, int m) => HeightmapFitter.Fit(HeightmapFitterTests.Samples(33, 33), 33, 33, n, m).Grid;

        static double[] Flat(PatchGrid g)
        {
            var a = new double[g.PatchCount * PatchGridBlocks.DoublesPerPatch];
            for (int p = 0; p < g.PatchCount; p++)
                for (int s = 0; s < GregoryPatch.SlotCount; s++)
                {
                    Double3 q = g.Patches[p][s];
                    int k = p * PatchGridBlocks.DoublesPerPatch + 3 * s;
                    a[k] = q.x; a[k + 1] = q.y; a[k + 2] = q.z;
                }
            return a;
        }

        static long Bits(double v) => BitConverter.DoubleToInt64Bits(v);

        [Test]
        public void ReadingOneBlockGivesEveryPointOfTheGrid()
        {
            PatchGrid g = FittedGrid(9, 8);   // 72 patches: the second block is partial
            double[][] blocks = PatchGridBlocks.FromGrid(g);
            for (int p = 0; p < g.PatchCount; p++)
                for (int s = 0; s < GregoryPatch.SlotCount; s++)
                {
                    Double3 q = PatchGridBlocks.Get(blocks[PatchGridBlocks.BlockOf(p)], p, s);
                    Double3 want = g.Patches[p][s];
                    Assert.That(new[] { Bits(q.x), Bits(q.y), Bits(q.z) }, Is.EqualTo(new[] { Bits(want.x), Bits(want.y), Bits(want.z) }),
                        $"patch {p} slot {s}");
                }
        }

        [Test]
        public void OldSingleArrayAndGridGiveTheSameBlocksBitForBit()
        {
            PatchGrid g = FittedGrid(9, 8);   // 72 patches: one full block and one of 8
            double[][] fromArray = PatchGridBlocks.Split(Flat(g), g.PatchCount);
            double[][] fromGrid = PatchGridBlocks.FromGrid(g);
            Assert.That(fromArray.Length, Is.EqualTo(2));
            Assert.That(fromArray[1].Length, Is.EqualTo(8 * 60));
            Assert.That(PatchGridBlocks.CheckShape(fromArray, g.PatchCount), Is.Null);
            for (int b = 0; b < 2; b++)
                Assert.That(fromArray[b].Select(Bits), Is.EqualTo(fromGrid[b].Select(Bits)), $"block {b}");
            GregoryPatch[] back = PatchGridBlocks.ToPatches(fromArray, g.PatchCount);
            for (int p = 0; p < g.PatchCount; p++)
                for (int s = 0; s < GregoryPatch.SlotCount; s++)
                    Assert.That(Bits(back[p][s].z), Is.EqualTo(Bits(g.Patches[p][s].z)));
        }

        [Test]
        public void SplitAndShapeNameTheBadLength()
        {
            var e = Assert.Throws<ArgumentException>(() => PatchGridBlocks.Split(new double[59], 1));
            Assert.That(e.Message, Does.Contain("controlPoints.Length = 59"));
            Assert.That(PatchGridBlocks.CheckShape(new[] { new double[61] }, 1), Does.Contain("blocks[0].Length = 61"));
        }

        [Test]
        public void AMoveChangesOnlyTheBlocksItReportsAndKeepsSharedEdgesIdentical()
        {
            // 12 x 11 = 132 patches in 3 blocks; patch 63 ends block 0 and patch 64 starts block 1.
            PatchGrid g = FittedGrid(12, 11);
            Assert.That(g.PatchCount, Is.EqualTo(132));
            int checkedMoves = 0;
            foreach (int patch in new[] { 0, 63, 64, 65, 77, 131 })
                foreach (int slot in new[] { GregoryPatch.Corner00, GregoryPatch.Corner33, 1, 7, GregoryPatch.P110, GregoryPatch.P221 })
                {
                    double[][] blocks = PatchGridBlocks.FromGrid(g);
                    double[][] before = blocks.Select(a => (double[])a.Clone()).ToArray();
                    int[] reported = PatchGridBlocks.BlocksTouchedByMove(g.Columns, g.Rows, patch, slot);
                    Double3 old = PatchGridBlocks.Get(blocks, patch, slot);
                    int[] changed = PatchGridBlocks.MoveControlPoint(blocks, g.Columns, g.Rows, patch, slot, new Double3(old.x, old.y, old.z + 0.125));
                    for (int b = 0; b < blocks.Length; b++)
                    {
                        bool differs = !blocks[b].Select(Bits).SequenceEqual(before[b].Select(Bits));
                        Assert.That(changed.Contains(b), Is.EqualTo(differs), $"patch {patch} slot {slot}: block {b} changed = {differs}, reported as changed = {changed.Contains(b)}");
                        if (differs) Assert.That(reported, Does.Contain(b), $"patch {patch} slot {slot}: block {b} changed but was not reported for Undo");
                    }
                    var moved = new PatchGrid(g.Columns, g.Rows, g.XLines, g.YLines, PatchGridBlocks.ToPatches(blocks, g.PatchCount));
                    Assert.DoesNotThrow(moved.Validate, $"patch {patch} slot {slot}: shared boundary copies moved together");
                    checkedMoves++;
                }
            Assert.That(checkedMoves, Is.EqualTo(36));
        }

        [Test]
        public void OneDragOnTheLargestGridRecordsAtMostSixBlocks()
        {
            // 256 x 256 patches: 31,457,280 bytes of doubles in the old single array, recorded whole per drag.
            const int n = 256;
            long whole = (long)n * n * PatchGridBlocks.DoublesPerPatch * sizeof(double);
            int worst = 0;
            for (int patch = 0; patch < n * n; patch += 61)
                foreach (int slot in new[] { GregoryPatch.Corner00, GregoryPatch.Corner33, GregoryPatch.P110 })
                    worst = Math.Max(worst, PatchGridBlocks.BlocksTouchedByMove(n, n, patch, slot).Length);
            long recorded = (long)worst * PatchGridBlocks.BlockBytes;
            TestContext.Out.WriteLine($"256 x 256 grid: whole array {whole:N0} bytes; one drag records at most {worst} blocks = {recorded:N0} bytes");
            Assert.That(whole, Is.EqualTo(31_457_280));
            Assert.That(worst, Is.LessThanOrEqualTo(6));
            Assert.That(PatchGridBlocks.BlocksTouchedByMove(n, n, 1000, GregoryPatch.P110), Has.Length.EqualTo(1), "an interior point records its own block only");
        }

        [Test]
        public void BadPointsAreRefusedBeforeAnythingChanges()
        {
            double[][] blocks = PatchGridBlocks.FromGrid(PatchGrid.CreateFlat(2, 2));
            double[][] before = blocks.Select(a => (double[])a.Clone()).ToArray();
            Assert.Throws<ArgumentException>(() => PatchGridBlocks.MoveControlPoint(blocks, 2, 2, 0, 0, new Double3(double.NaN, 0, 0)));
            Assert.Throws<ArgumentOutOfRangeException>(() => PatchGridBlocks.MoveControlPoint(blocks, 2, 2, 4, 0, new Double3(0, 0, 0)));
            Assert.Throws<ArgumentOutOfRangeException>(() => PatchGridBlocks.BlocksTouchedByMove(2, 2, 0, 20));
            Assert.That(blocks[0].Select(Bits), Is.EqualTo(before[0].Select(Bits)));
        }

        [Test]
        public void TheFingerprintTellsEditsApart()
        {
            double[][] blocks = PatchGridBlocks.FromGrid(PatchGrid.CreateFlat(9, 9));
            ulong h = PatchGridBlocks.Fingerprint(blocks, 1);
            Assert.That(PatchGridBlocks.Fingerprint(blocks.Select(a => (double[])a.Clone()).ToArray(), 1), Is.EqualTo(h), "equal data, equal fingerprint");
            blocks[1][100] = BitConverter.Int64BitsToDouble(BitConverter.DoubleToInt64Bits(blocks[1][100]) ^ 1);   // one bit
            Assert.That(PatchGridBlocks.Fingerprint(blocks, 1), Is.Not.EqualTo(h));
            var p = TestPatches.Random(3);
            PatchGridBlocks.SetPatch(blocks, 70, p);
            for (int s = 0; s < GregoryPatch.SlotCount; s++) Assert.That(PatchGridBlocks.Get(blocks, 70, s), Is.EqualTo(p[s]));
        }
    }
}