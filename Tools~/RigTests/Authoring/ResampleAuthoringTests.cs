using System;
using NUnit.Framework;
using static GregoryTerrain.Tests.AuthoringGrids;

namespace GregoryTerrain.Tests
{
    /// <summary>
    /// ResampleAuthoring: a grid resampled to another patch count keeps its surface (measured at
    /// points off the samples), and the error it reports is the one there is.
    /// </summary>
    [TestFixture]
    public class ResampleAuthoringTests
    {
        /// <summary>Height units; the test surface spans about 0.3, so this is 0.03% of its relief.</summary>
        const double Tolerance = 1e-4;

        [Test]
        public void ResampledFinerGridKeepsTheSurface()
        {
            PatchGrid old = Curved(PatchGrid.UniformLines(4), Uneven);
            HeightmapFit fit = ResampleAuthoring.Resample(old, 16, 16);
            Assert.That(fit.Grid.Columns, Is.EqualTo(16));
            Assert.That(fit.Grid.Rows, Is.EqualTo(16));
            double measured = MaxDifference(old, fit.Grid);
            TestContext.Out.WriteLine($"4 x 6 -> 16 x 16: largest |new - old| {measured:G3} off the samples, reported max {fit.MaxError:G3}, RMS {fit.RmsError:G3} (surface relief about 0.3)");
            Assert.That(measured, Is.LessThan(Tolerance), "largest |new - old| height at 97 x 97 points");
            Assert.That(fit.MaxError, Is.LessThan(Tolerance), "reported error");
        }

        [Test]
        public void CoarserGridReportsTheErrorItHas()
        {
            PatchGrid old = Curved(PatchGrid.UniformLines(8), PatchGrid.UniformLines(8));
            HeightmapFit fit = ResampleAuthoring.Resample(old, 1, 1);
            double measured = MaxDifference(old, fit.Grid);
            TestContext.Out.WriteLine($"8 x 8 -> 1 x 1: largest |new - old| {measured:G3}, reported max {fit.MaxError:G3}");
            Assert.That(measured, Is.GreaterThan(Tolerance), "one patch cannot hold the surface");
            Assert.That(fit.MaxError, Is.EqualTo(measured).Within(0.25 * measured), "reported max error against the one measured off the samples");
        }

        [Test]
        public void BadPatchCountIsRefusedByName()
        {
            PatchGrid old = PatchGrid.CreateFlat(2, 2);
            var e = Assert.Throws<ArgumentException>(() => ResampleAuthoring.Resample(old, 0, 4));
            Assert.That(e.ParamName, Is.EqualTo("columns"));
            Assert.That(e.Message, Does.Contain("columns = 0"));
        }

        static double MaxDifference(PatchGrid a, PatchGrid b)
        {
            double worst = 0;
            for (int r = 0; r <= 96; r++)
                for (int c = 0; c <= 96; c++)
                {
                    double x = c / 96.0, y = r / 96.0;
                    worst = Math.Max(worst, Math.Abs(ResampleAuthoring.Height(a, x, y) - ResampleAuthoring.Height(b, x, y)));
                }
            return worst;
        }
    }
}
