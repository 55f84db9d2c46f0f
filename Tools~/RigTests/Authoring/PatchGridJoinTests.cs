using System;
using NUnit.Framework;
using static GregoryTerrain.Tests.AuthoringGrids;

namespace GregoryTerrain.Tests
{
    /// <summary>
    /// PatchGridJoin: a G1 grid cut into tiles and joined back (north-south, and 2 x 2 as two
    /// west-east joins and one north-south) is valid, bit-identical along the seams and G1 again.
    /// </summary>
    [TestFixture]
    public class PatchGridJoinTests
    {
        const double G1BoundDegrees = 1e-7;

        static PatchGrid Whole() => Curved(PatchGrid.UniformLines(4), new[] { 0, 0.2, 0.5, 0.6, 0.8, 1.0 });

        [Test]
        public void SouthNorthJoinsTheCutGridBackG1()
        {
            PatchGrid whole = Whole();
            PatchGrid south = Cut(whole, new PatchRect(0, 0, 3, 2)), north = Cut(whole, new PatchRect(0, 3, 3, 4));
            PatchGrid joined = PatchGridJoin.SouthNorth(south, north, 0.6);
            Assert.DoesNotThrow(joined.Validate, "the seam must be bit-identical");
            Assert.That(joined.Rows, Is.EqualTo(5));
            Assert.That(joined.YLines[3], Is.EqualTo(0.6));
            double angle = ContinuityMeasure.MaxNormalAngleDegrees(joined);
            TestContext.Out.WriteLine($"south-north: G1 {angle:E2} deg, largest difference to the uncut grid {MaxDifference(whole, joined):E2}");
            Assert.That(angle, Is.LessThan(G1BoundDegrees));
            Assert.That(MaxDifference(whole, joined), Is.LessThan(1e-15));
            // A wrong share stretches one side: the seam stays watertight but the kink shows, which
            // is what the angle check above would catch.
            PatchGrid skewed = PatchGridJoin.SouthNorth(south, north, 0.4);
            Assert.DoesNotThrow(skewed.Validate);
            Assert.That(ContinuityMeasure.MaxNormalAngleDegrees(skewed), Is.GreaterThan(1000 * G1BoundDegrees));
        }

        [Test]
        public void TwoByTwoIsTwoWestEastJoinsThenOneSouthNorth()
        {
            PatchGrid whole = Whole();
            PatchGrid sw = Cut(whole, new PatchRect(0, 0, 1, 1)), se = Cut(whole, new PatchRect(2, 0, 3, 1));
            PatchGrid nw = Cut(whole, new PatchRect(0, 2, 1, 4)), ne = Cut(whole, new PatchRect(2, 2, 3, 4));
            PatchGrid joined = PatchGridJoin.SouthNorth(PatchGridJoin.WestEast(sw, se, 0.5), PatchGridJoin.WestEast(nw, ne, 0.5), 0.5);
            Assert.DoesNotThrow(joined.Validate);
            double angle = ContinuityMeasure.MaxNormalAngleDegrees(joined);
            TestContext.Out.WriteLine($"2 x 2: G1 {angle:E2} deg");
            Assert.That(angle, Is.LessThan(G1BoundDegrees));
            Assert.That(MaxDifference(whole, joined), Is.LessThan(1e-15));
        }

        [Test]
        public void BadInputThrowsNamingTheField()
        {
            PatchGrid whole = Whole();
            PatchGrid south = Cut(whole, new PatchRect(0, 0, 3, 2)), north = Cut(whole, new PatchRect(0, 3, 3, 4));
            var e = Assert.Throws<ArgumentException>(() => PatchGridJoin.SouthNorth(south, north, 1.0));
            Assert.That(e.ParamName, Is.EqualTo("southShare"));
            Assert.That(e.Message, Does.Contain("southShare = 1"));
            e = Assert.Throws<ArgumentException>(() => PatchGridJoin.SouthNorth(south, Cut(whole, new PatchRect(0, 3, 2, 4)), 0.5));
            Assert.That(e.ParamName, Is.EqualTo("north"));
            Assert.That(e.Message, Does.Contain("north.Columns = 3"));
            PatchGrid other = PatchGrid.CreateFlat(4, 2, new[] { 0, 0.3, 0.5, 0.75, 1.0 }, PatchGrid.UniformLines(2));
            e = Assert.Throws<ArgumentException>(() => PatchGridJoin.SouthNorth(south, other, 0.5));
            Assert.That(e.Message, Does.Contain("north.XLines[1] = 0.3"));
        }

        static double MaxDifference(PatchGrid a, PatchGrid b)
        {
            double worst = 0;
            for (int p = 0; p < a.PatchCount; p++)
                for (int k = 0; k < GregoryPatch.SlotCount; k++) worst = Math.Max(worst, TestPatches.Dist(a.Patches[p][k], b.Patches[p][k]));
            return worst;
        }
    }
}
