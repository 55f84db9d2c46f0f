using System;
using System.Threading;
using NUnit.Framework;
using static GregoryTerrain.Tests.AuthoringGrids;

namespace GregoryTerrain.Tests
{
    /// <summary>
    /// Refitting a region to a new heightmap (Core's PatchRegionFit): the region follows the new
    /// heights, patches outside it keep every bit, the grid stays valid and G1, bad input throws
    /// naming the field and value and changes nothing.
    /// </summary>
    [TestFixture]
    public class PatchRegionFitTests
    {
        const double G1BoundDegrees = 1e-7;
        const int Samples = 121;

        /// <summary>The old surface plus a bump of 0.05 in the middle of the terrain and a wave everywhere.</summary>
        static double Bumped(double x, double y) => F(x, y) + 0.05 * Math.Exp(-((x - 0.5) * (x - 0.5) + (y - 0.5) * (y - 0.5)) / 0.01) + 0.01 * Math.Cos(9 * x + 4 * y);

        static double RegionRms(PatchGrid g, PatchRect r, Func<double, double, double> f)
        {
            double x0 = g.XLines[r.I0], x1 = g.XLines[r.I1 + 1], y0 = g.YLines[r.J0], y1 = g.YLines[r.J1 + 1], sum = 0;
            int count = 0;
            for (int s = 0; s <= 40; s++)
                for (int t = 0; t <= 40; t++)
                {
                    double x = x0 + (x1 - x0) * s / 40, y = y0 + (y1 - y0) * t / 40, e = Height(g, x, y) - f(x, y);
                    sum += e * e;
                    count++;
                }
            return Math.Sqrt(sum / count);
        }

        [TestCase(false, 2, 2, 3, 3)]
        [TestCase(true, 2, 1, 4, 3)]
        [TestCase(false, 0, 0, 2, 1)]   // on the terrain's corner: the fit reaches the border there
        [TestCase(false, 0, 0, 5, 5)]   // the whole grid
        public void TheRegionFollowsTheNewHeightsAndTheRestKeepsItsBits(bool uneven, int i0, int j0, int i1, int j1)
        {
            PatchGrid grid = uneven ? Curved(Uneven, PatchGrid.UniformLines(6)) : Curved(PatchGrid.UniformLines(6), PatchGrid.UniformLines(6));
            PatchGrid before = grid.Clone();
            var region = new PatchRect(i0, j0, i1, j1);
            double[] heights = AuthoringGrids.Samples(Bumped, Samples, Samples);
            RegionFitResult fit = PatchRegionFit.Fit(grid, region, heights, Samples, Samples);
            Assert.That(AuthoringGrids.SameBits(before, grid), "Fit must not write the grid");
            double oldRms = RegionRms(grid, region, Bumped);
            fit.Edit.ApplyTo(grid);
            double newRms = RegionRms(grid, region, Bumped);
            double angle = ContinuityMeasure.MaxNormalAngleDegrees(grid);
            TestContext.Out.WriteLine($"{region}, uneven {uneven}: RMS against the new heights {oldRms:E3} -> {newRms:E3} (fit reports max {fit.MaxError:E3}, RMS {fit.RmsError:E3} on {fit.SampleWidth} x {fit.SampleHeight} samples); G1 {angle:E2} deg; {fit.Edit.Patches.Length} patches changed");
            Assert.DoesNotThrow(grid.Validate);
            Assert.That(angle, Is.LessThan(G1BoundDegrees));
            Assert.That(ChangedOutside(before, grid, region), Is.Null, "patches outside the region must keep their bits (continuous, G1 border kept on their side)");
            Assert.That(newRms, Is.LessThan(0.5 * oldRms), "the region must follow the new heights");
            Assert.That(fit.RmsError, Is.LessThan(0.5 * oldRms));
        }

        [Test]
        public void WithoutTheBorderRepairTheJoinIsKinked()
        {
            // What the G1 check above guards against: the fitted patches pasted in as they come.
            PatchGrid grid = Curved(PatchGrid.UniformLines(6), PatchGrid.UniformLines(6));
            var region = new PatchRect(2, 2, 3, 3);
            HeightmapFit alone = HeightmapFitter.Fit(AuthoringGrids.Samples(Bumped, Samples, Samples), Samples, Samples, 6, 6);
            for (int j = region.J0; j <= region.J1; j++)
                for (int i = region.I0; i <= region.I1; i++) alone.Grid.Patch(i, j).Points.CopyTo(grid.Patch(i, j).Points, 0);
            Assert.That(ContinuityMeasure.MaxNormalAngleDegrees(grid), Is.GreaterThan(1000 * G1BoundDegrees));
        }

        [Test]
        public void BadInputThrowsNamingTheFieldAndChangesNothing()
        {
            PatchGrid grid = Curved(PatchGrid.UniformLines(6), PatchGrid.UniformLines(6)), before = grid.Clone();
            double[] good = AuthoringGrids.Samples(Bumped, Samples, Samples);
            void Expect<T>(TestDelegate call, string field, string text) where T : ArgumentException
            {
                var e = Assert.Throws(Is.InstanceOf<T>(), call);
                TestContext.Out.WriteLine(e.Message);
                Assert.That(((ArgumentException)e).ParamName, Is.EqualTo(field));
                Assert.That(e.Message, Does.Contain(text));
                Assert.That(AuthoringGrids.SameBits(before, grid));
            }
            Expect<ArgumentOutOfRangeException>(() => PatchRegionFit.Fit(grid, new PatchRect(0, 0, 6, 2), good, Samples, Samples), "region.I1", "region.I1 = 6");
            Expect<ArgumentOutOfRangeException>(() => PatchRegionFit.Fit(grid, new PatchRect(0, -2, 1, 2), good, Samples, Samples), "region.J0", "region.J0 = -2");
            Expect<ArgumentOutOfRangeException>(() => PatchRegionFit.Fit(grid, new PatchRect(3, 0, 2, 2), good, Samples, Samples), "region.I1", "region.I1 = 2");
            Expect<ArgumentException>(() => PatchRegionFit.Fit(grid, new PatchRect(0, 0, 1, 1), good, Samples - 1, Samples), "heights", "heights.Length = 14641");
            double[] nan = (double[])good.Clone();
            nan[500] = double.NaN;
            Expect<ArgumentException>(() => PatchRegionFit.Fit(grid, new PatchRect(0, 0, 1, 1), nan, Samples, Samples), "heights", "heights[500]");
            using var cancel = new CancellationTokenSource();
            cancel.Cancel();
            Assert.Throws(Is.InstanceOf<OperationCanceledException>(), () => PatchRegionFit.Fit(grid, new PatchRect(0, 0, 1, 1), good, Samples, Samples, null, cancel.Token));
            Assert.That(AuthoringGrids.SameBits(before, grid));
        }
    }
}
