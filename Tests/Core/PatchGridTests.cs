using System;
using NUnit.Framework;

namespace GregoryTerrain.Tests
{
    [TestFixture]
    public class PatchGridTests
    {
        static PatchGrid Grid3x2() => PatchGrid.CreateFlat(3, 2, new[] { 0.0, 0.25, 0.5, 1.0 }, new[] { 0.0, 0.75, 1.0 });

        [Test]
        public void FlatGridValidatesAndRegionsComeFromLines()
        {
            var g = Grid3x2();
            Assert.DoesNotThrow(g.Validate);
            Assert.That(g.RegionOf(1, 1), Is.EqualTo(new Region(0.25, 0.75, 0.5, 1.0)));
            Assert.That(g.RegionOf(g.Index(2, 0)), Is.EqualTo(new Region(0.5, 0.0, 1.0, 0.75)));
            Assert.That(g.Index(2, 1), Is.EqualTo(1 * 3 + 2));
        }

        [TestCase(0.0, 0.0, 0, 0)]
        [TestCase(0.25, 0.1, 1, 0)]    // on the line x = 0.25: the higher-index column
        [TestCase(0.2499, 0.1, 0, 0)]
        [TestCase(0.5, 0.75, 2, 1)]    // on both interior lines
        [TestCase(1.0, 1.0, 2, 1)]     // the last line stays in the last patch
        [TestCase(0.75, 1.0, 2, 1)]
        [TestCase(-0.5, 2.0, 0, 1)]    // outside: clamped to border patches
        public void FindPatchOnBoundaries(double x, double y, int i, int j)
        {
            var g = Grid3x2();
            Assert.That(g.FindPatch(x, y), Is.EqualTo(j * 3 + i));
            Assert.That(g.RegionOf(g.FindPatch(x, y)).Contains(Math.Max(0, Math.Min(1, x)), Math.Max(0, Math.Min(1, y))), Is.True);
        }

        [Test]
        public void FindIntervalFloatAgreesWithDoubleOnRepresentableLines()
        {
            var lines = new[] { 0.0, 0.125, 0.25, 0.5, 0.625, 1.0 };
            var f = Array.ConvertAll(lines, d => (float)d);
            var rng = new Random(2);
            for (int r = 0; r < 2000; r++)
            {
                double x = r < lines.Length ? lines[r] : rng.NextDouble();
                Assert.That(PatchGrid.FindInterval(f, (float)x), Is.EqualTo(PatchGrid.FindInterval(lines, (float)x)));
            }
        }

        [Test]
        public void FindPatchRejectsNaN()
        {
            var ex = Assert.Throws<ArgumentException>(() => Grid3x2().FindPatch(double.NaN, 0.5));
            Assert.That(ex.Message, Does.Contain("x = NaN"));
        }

        [Test]
        public void ValidateCatchesGapAtTheEdge()
        {
            var g = Grid3x2();
            g.XLines[3] = 0.9;
            var ex = Assert.Throws<ArgumentException>(g.Validate);
            Assert.That(ex.Message, Does.Contain("xLines[3] = 0.9").And.Contain("exactly 1"));
        }

        [Test]
        public void ValidateCatchesOverlap()
        {
            var g = Grid3x2();
            g.XLines[2] = 0.2; // below xLines[1] = 0.25: columns 1 and 2 overlap
            var ex = Assert.Throws<ArgumentException>(g.Validate);
            Assert.That(ex.Message, Does.Contain("xLines[2] = 0.2").And.Contain("xLines[1] = 0.25"));
        }

        [Test]
        public void ValidateCatchesNaNLine()
        {
            var g = Grid3x2();
            g.YLines[1] = double.NaN;
            var ex = Assert.Throws<ArgumentException>(g.Validate);
            Assert.That(ex.Message, Does.Contain("yLines[1] = NaN"));
        }

        [Test]
        public void ValidateCatchesNaNControlPoint()
        {
            var g = Grid3x2();
            g.Patch(2, 1)[GregoryPatch.P121] = new Double3(0.5, double.NaN, 0);
            var ex = Assert.Throws<ArgumentException>(g.Validate);
            Assert.That(ex.Message, Does.Contain("patch (2, 1)").And.Contain("slot 17").And.Contain("NaN"));
        }

        [Test]
        public void ValidateCatchesMismatchedSharedEdge()
        {
            var g = Grid3x2();
            Double3 p = g.Patch(0, 0)[GregoryPatch.Slot(3, 2)];
            g.Patch(0, 0)[GregoryPatch.Slot(3, 2)] = new Double3(p.x, p.y, 1e-300); // a tiny z, still not identical
            var ex = Assert.Throws<ArgumentException>(g.Validate);
            Assert.That(ex.Message, Does.Contain("patch (0, 0)").And.Contain("patch (1, 0)").And.Contain("slot 14").And.Contain("slot 2").And.Contain("1E-300"));

            var h = Grid3x2();
            h.Patch(1, 1)[GregoryPatch.Slot(2, 0)] = new Double3(0.4, 0.75, 0.0);
            ex = Assert.Throws<ArgumentException>(h.Validate);
            Assert.That(ex.Message, Does.Contain("patch (1, 0)").And.Contain("patch (1, 1)").And.Contain("y = 0.75").And.Contain("slot 8"));
        }

        [Test]
        public void ConstructorRejectsWrongCounts()
        {
            var ex = Assert.Throws<ArgumentException>(() => new PatchGrid(2, 2, new double[3], new double[2], new GregoryPatch[4]));
            Assert.That(ex.Message, Does.Contain("yLines.Length = 2"));
            ex = Assert.Throws<ArgumentException>(() => new PatchGrid(0, 2, new double[1], new double[3], new GregoryPatch[0]));
            Assert.That(ex.Message, Does.Contain("columns = 0"));
        }

        [Test]
        public void ContinuityOfFlatGridIsPerfectAndAKinkIsSeen()
        {
            var g = Grid3x2();
            Assert.That(ContinuityMeasure.MaxNormalAngleDegrees(g), Is.EqualTo(0.0).Within(1e-12));
            Assert.That(ContinuityMeasure.MaxPositionGap(g), Is.EqualTo(0.0));
            // Lift the right patch's first interior column: a crease along x = 0.25 between (0,0) and (1,0).
            var p = g.Patch(1, 0);
            for (int k = 0; k < 4; k++)
            {
                int s = GregoryPatch.Slot(1, k);
                p[s] = new Double3(p[s].x, p[s].y, 0.01);
            }
            PatchGrid.SetSecondPointsToFirst(p);
            // du of patch (1,0) at u = 0 is 3 * (1/12, 0, 0.01): the normal tilts by atan(0.01 / (1/12)).
            double expected = Math.Atan(0.01 * 12) * 180 / Math.PI;
            Assert.That(ContinuityMeasure.MaxNormalAngleDegrees(g), Is.EqualTo(expected).Within(1e-9));
        }
    }
}
