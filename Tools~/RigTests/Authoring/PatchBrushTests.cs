using System;
using NUnit.Framework;
using static GregoryTerrain.Tests.AuthoringGrids;

namespace GregoryTerrain.Tests
{
    /// <summary>
    /// Brush edits (Core's PatchBrush): after every dab the grid is valid (shared edges bit for bit),
    /// G1 to rounding, changed only under the brush and one patch around it, and bad input throws
    /// naming the field and value with the grid left as it was.
    /// </summary>
    [TestFixture]
    public class PatchBrushTests
    {
        /// <summary>Normals across shared edges agree to rounding (the grids start at about 1e-12 degrees).</summary>
        const double G1BoundDegrees = 1e-7;

        static PatchGrid Grid(bool uneven) => uneven ? Curved(Uneven, PatchGrid.UniformLines(5)) : Curved(PatchGrid.UniformLines(6), PatchGrid.UniformLines(6));

        /// <summary>The patches a dab may change: those under its bounding box and one more on each side.</summary>
        static PatchRect Reach(PatchGrid g, BrushDab d) => new PatchRect(
            Math.Max(0, PatchGrid.FindInterval(g.XLines, Math.Max(0, d.X - d.Radius)) - 1), Math.Max(0, PatchGrid.FindInterval(g.YLines, Math.Max(0, d.Y - d.Radius)) - 1),
            Math.Min(g.Columns - 1, PatchGrid.FindInterval(g.XLines, Math.Min(1, d.X + d.Radius)) + 1), Math.Min(g.Rows - 1, PatchGrid.FindInterval(g.YLines, Math.Min(1, d.Y + d.Radius)) + 1));

        /// <summary>Applies the dab and checks what every dab must keep; returns the grid before.</summary>
        static PatchGrid ApplyAndCheck(PatchGrid grid, BrushDab dab, PatchRect? limit = null)
        {
            PatchGrid before = grid.Clone();
            PatchEdit edit = PatchBrush.Apply(grid, dab, limit);
            Assert.That(AuthoringGrids.SameBits(before, grid), "Apply wrote the grid; it must only return the edit");
            edit.ApplyTo(grid);
            Assert.DoesNotThrow(grid.Validate, "shared edges must stay bit-identical");
            Assert.That(ContinuityMeasure.MaxNormalAngleDegrees(grid), Is.LessThan(G1BoundDegrees), $"G1 after {dab.Mode}");
            Assert.That(ContinuityMeasure.MaxPositionGap(grid), Is.EqualTo(0.0));
            PatchRect reach = Reach(grid, dab);
            if (limit is PatchRect l)
                reach = new PatchRect(Math.Max(reach.I0, l.I0 - 1), Math.Max(reach.J0, l.J0 - 1), Math.Min(reach.I1, l.I1 + 1), Math.Min(reach.J1, l.J1 + 1));
            Assert.That(ChangedOutside(before, grid, reach), Is.Null, $"changed outside {reach}");
            foreach (int p in edit.Patches) Assert.That(reach.Contains(p % grid.Columns, p / grid.Columns), $"edit lists patch {p} outside {reach}");
            for (int p = 0; p < grid.PatchCount; p++)
                if (Array.IndexOf(edit.Patches, p) < 0)
                    Assert.That(AuthoringGrids.SameBits(before.Patches[p], grid.Patches[p]), $"patch {p} is not in the edit but changed");
            return before;
        }

        [TestCase(false)]
        [TestCase(true)]
        public void RaiseAndLowerKeepG1AndStayLocal(bool uneven)
        {
            PatchGrid grid = Grid(uneven);
            Assert.That(ContinuityMeasure.MaxNormalAngleDegrees(grid), Is.LessThan(G1BoundDegrees), "the test grid itself must be G1");
            var raise = new BrushDab(BrushMode.Raise, 0.43, 0.57, 0.2, 0.05);
            PatchGrid before = ApplyAndCheck(grid, raise);
            double rise = Height(grid, 0.43, 0.57) - Height(before, 0.43, 0.57);
            TestContext.Out.WriteLine($"uneven {uneven}: rise at the centre {rise:G4} for strength 0.05; G1 {ContinuityMeasure.MaxNormalAngleDegrees(grid):E2} deg");
            Assert.That(rise, Is.InRange(0.5 * 0.05, 1.0 * 0.05), "the surface rises by about the strength at the centre");
            Assert.That(Height(grid, 0.95, 0.05), Is.EqualTo(Height(before, 0.95, 0.05)), "far away nothing moves");
            // A dab on a grid vertex and one at the terrain's edge, lowering.
            ApplyAndCheck(grid, new BrushDab(BrushMode.Raise, uneven ? 0.45 : 0.5, 0.4, 0.12, -0.03));
            ApplyAndCheck(grid, new BrushDab(BrushMode.Raise, 0.0, 1.0, 0.3, -0.03));
        }

        [Test]
        public void ADabWithoutTheG1RepairFailsTheAngleCheck()
        {
            // What ApplyAndCheck's G1 assertion guards against: the same raise added to every control
            // point as is (no corner lines, no edge joins) leaves kinks along the shared edges.
            PatchGrid grid = Grid(false);
            var dab = new BrushDab(BrushMode.Raise, 0.43, 0.57, 0.2, 0.05);
            foreach (GregoryPatch p in grid.Patches)
                for (int k = 0; k < GregoryPatch.SlotCount; k++)
                {
                    Double3 q = p[k];
                    double t = Math.Sqrt((q.x - dab.X) * (q.x - dab.X) + (q.y - dab.Y) * (q.y - dab.Y)) / dab.Radius;
                    p[k] = new Double3(q.x, q.y, q.z + dab.Strength * PatchBrush.Falloff(t));
                }
            Assert.DoesNotThrow(grid.Validate);
            Assert.That(ContinuityMeasure.MaxNormalAngleDegrees(grid), Is.GreaterThan(1000 * G1BoundDegrees));
        }

        [Test]
        public void SmoothFlattensBumpsAndKeepsG1()
        {
            PatchGrid grid = Grid(false), smooth = grid.Clone();
            // Roughen the middle with a few alternating raises first.
            for (int k = 0; k < 6; k++) ApplyAndCheck(grid, new BrushDab(BrushMode.Raise, 0.3 + 0.07 * k, 0.5, 0.06, k % 2 == 0 ? 0.03 : -0.03));
            double before = Roughness(grid, smooth);
            for (int k = 0; k < 12; k++) ApplyAndCheck(grid, new BrushDab(BrushMode.Smooth, 0.5, 0.5, 0.5, 1.0));
            double after = Roughness(grid, smooth);
            TestContext.Out.WriteLine($"roughness (mean |second difference| of the bumps on a 0.01 lattice over the brush) {before:E3} -> {after:E3}");
            Assert.That(after, Is.LessThan(0.3 * before));
        }

        [Test]
        public void FlattenMovesHeightsToTheTarget()
        {
            PatchGrid grid = Grid(true);
            double target = 0.02;
            double gap0 = Math.Abs(Height(grid, 0.5, 0.5) - target);
            for (int k = 0; k < 4; k++) ApplyAndCheck(grid, new BrushDab(BrushMode.Flatten, 0.5, 0.5, 0.25, 0.8, target));
            double gap1 = Math.Abs(Height(grid, 0.5, 0.5) - target);
            TestContext.Out.WriteLine($"distance to the target at the centre {gap0:E3} -> {gap1:E3}");
            Assert.That(gap1, Is.LessThan(0.2 * gap0));
        }

        [Test]
        public void AStrokeOfManyDabsStaysG1()
        {
            PatchGrid grid = Grid(true);
            for (int k = 0; k <= 40; k++)
                ApplyAndCheck(grid, new BrushDab(k % 3 == 2 ? BrushMode.Smooth : BrushMode.Raise, 0.05 + 0.9 * k / 40, 0.3 + 0.4 * k / 40, 0.08, k % 3 == 2 ? 0.5 : 0.004));
        }

        [Test]
        public void ALimitConfinesTheBrushToTheSelection()
        {
            PatchGrid grid = Grid(false);
            var limit = new PatchRect(2, 2, 3, 3);
            ApplyAndCheck(grid, new BrushDab(BrushMode.Raise, 0.5, 0.5, 0.45, 0.05), limit);
            Assert.That(PatchBrush.Apply(grid, new BrushDab(BrushMode.Raise, 0.05, 0.05, 0.04, 0.05), limit).IsEmpty, "a dab outside the selection changes nothing");
            Assert.That(PatchBrush.Apply(grid, new BrushDab(BrushMode.Raise, 3, 3, 0.5, 0.05)).IsEmpty, "a dab off the terrain changes nothing");
        }

        static readonly (BrushDab dab, string field, string value)[] BadDabs =
        {
            (new BrushDab(BrushMode.Raise, 0.5, 0.5, 0.2, double.NaN), "dab.Strength", "NaN"),
            (new BrushDab(BrushMode.Raise, 0.5, 0.5, 0.2, double.PositiveInfinity), "dab.Strength", "Infinity"),
            (new BrushDab(BrushMode.Raise, 0.5, 0.5, 0, 0.1), "dab.Radius", "= 0"),
            (new BrushDab(BrushMode.Raise, 0.5, 0.5, -0.25, 0.1), "dab.Radius", "-0.25"),
            (new BrushDab(BrushMode.Raise, 0.5, 0.5, double.NaN, 0.1), "dab.Radius", "NaN"),
            (new BrushDab(BrushMode.Raise, double.NaN, 0.5, 0.2, 0.1), "dab.X", "NaN"),
            (new BrushDab(BrushMode.Smooth, 0.5, 0.5, 0.2, 1.5), "dab.Strength", "1.5"),
            (new BrushDab(BrushMode.Flatten, 0.5, 0.5, 0.2, 0.5, double.NaN), "dab.Target", "NaN"),
            (new BrushDab((BrushMode)7, 0.5, 0.5, 0.2, 0.5), "dab.Mode", "7"),
            (new BrushDab(BrushMode.Raise, 0.5, 0.5, 0.2, 1e300), "dab.Strength", "outside float32"),
        };

        [Test]
        public void BadDabsThrowNamingTheFieldAndLeaveTheGridAlone([Range(0, 9)] int k)
        {
            (BrushDab dab, string field, string value) = BadDabs[k];
            PatchGrid grid = Grid(false), before = grid.Clone();
            var e = Assert.Throws(Is.InstanceOf<ArgumentException>(), () => PatchBrush.Apply(grid, dab).ApplyTo(grid));
            TestContext.Out.WriteLine(e.Message);
            Assert.That(((ArgumentException)e).ParamName, Is.EqualTo(field));
            Assert.That(e.Message, Does.Contain(value));
            Assert.That(AuthoringGrids.SameBits(before, grid), "a throw must leave the grid as it was");
        }

        [TestCase(-1, 0, 1, 1, "limit.I0", "-1")]
        [TestCase(0, 0, 6, 1, "limit.I1", "6")]
        [TestCase(3, 0, 2, 1, "limit.I1", "2")]
        [TestCase(0, 2, 1, 9, "limit.J1", "9")]
        public void ALimitOutOfRangeThrows(int i0, int j0, int i1, int j1, string field, string value)
        {
            PatchGrid grid = Grid(false), before = grid.Clone();
            var e = Assert.Throws<ArgumentOutOfRangeException>(() => PatchBrush.Apply(grid, new BrushDab(BrushMode.Raise, 0.5, 0.5, 0.2, 0.1), new PatchRect(i0, j0, i1, j1)));
            Assert.That(e.ParamName, Is.EqualTo(field));
            Assert.That(e.Message, Does.Contain(field + " = " + value));
            Assert.That(AuthoringGrids.SameBits(before, grid));
        }

        [Test]
        public void AGridWithSplitEdgesIsRefused()
        {
            PatchGrid grid = Grid(false);
            GregoryPatch p = grid.Patch(2, 2);
            p[GregoryPatch.Slot(3, 1)] = p[GregoryPatch.Slot(3, 1)] + new Double3(0, 0, 1e-9);
            PatchGrid before = grid.Clone();
            var e = Assert.Throws<ArgumentException>(() => PatchBrush.Apply(grid, new BrushDab(BrushMode.Raise, 0.5, 0.5, 0.2, 0.1)));
            Assert.That(e.ParamName, Is.EqualTo("grid"));
            Assert.That(e.Message, Does.Contain("patch (2, 2) and patch (3, 2)"));
            Assert.That(AuthoringGrids.SameBits(before, grid));
        }

        /// <summary>Mean |second difference| along x of the height added to <paramref name="smooth"/>, on a 0.01 lattice over [0.3, 0.7]^2.</summary>
        static double Roughness(PatchGrid g, PatchGrid smooth)
        {
            double Height(PatchGrid _, double x, double y) => AuthoringGrids.Height(g, x, y) - AuthoringGrids.Height(smooth, x, y);
            double sum = 0;
            int count = 0;
            for (double y = 0.3; y <= 0.7; y += 0.01)
                for (double x = 0.31; x <= 0.69; x += 0.01)
                {
                    sum += Math.Abs(Height(g, x - 0.01, y) - 2 * Height(g, x, y) + Height(g, x + 0.01, y));
                    count++;
                }
            return sum / count;
        }
    }
}
