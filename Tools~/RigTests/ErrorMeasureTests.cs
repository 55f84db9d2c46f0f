// gt-cli error's measure (Tools~/dotnet/Gt/ErrorMeasure.cs, compiled into this assembly) on surfaces
// with a known answer.
using System;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    [TestFixture]
    public class ErrorMeasureTests
    {
        // Paraboloid height k (x^2 + y^2) over one L x L patch; object space is (x, height, y).
        static Func<int, double, double, double[]> Paraboloid(double k, double l) =>
            (p, s, t) => new[] { s * l, k * (s * l * s * l + t * l * t * l), t * l };

        [TestCase(1.0, 1.0, 5)]
        [TestCase(3.0, 0.5, 9)]
        [TestCase(0.2, 2.0, 1)]
        public void ParaboloidErrorIsTheAnalyticChordError(double k, double l, int factor)
        {
            // Cells h = L / F wide. Linear interpolation of k (x^2 + y^2) misses by k h^2 / 4 at an
            // edge's middle (the sagitta L^2 kappa / 8, kappa = 2k) and by k (h^2 + h^2) / 4 = k h^2 / 2
            // at a cell's centre, on either diagonal: the largest error.
            var r = ErrorMeasure.Measure(Paraboloid(k, l), new[] { PatchFactors.Uniform(factor) }, null, fractionalOdd: false);
            double h = l / factor;
            Assert.That(r.MaxWorld, Is.EqualTo(k * h * h / 2).Within(1e-9).Percent);
            // Samples: per cell 2 edges + 2 diagonals, plus the last row/column's far edges, plus the border segments.
            long expected = factor * factor * 4L + 2L * factor + 4L * factor;
            Assert.That(r.Samples, Is.EqualTo(expected));
            // RMS: edge samples k h^2 / 4, diagonal samples k h^2 / 2.
            long edges = 2L * factor * factor + 2L * factor + 4L * factor, diagonals = 2L * factor * factor;
            double rms = Math.Sqrt((edges * Math.Pow(k * h * h / 4, 2) + diagonals * Math.Pow(k * h * h / 2, 2)) / (edges + diagonals));
            Assert.That(r.RmsWorld, Is.EqualTo(rms).Within(1e-9).Percent);
        }

        [Test]
        public void FractionalOddCellsHaveFullSegmentsOfOneOverF()
        {
            foreach (double f in new[] { 1.0, 1.5, 3.0, 4.2, 7.9, 17.3, 63.0, 64.0 })
            {
                double[] x = TessellationCells.FractionalOdd(f);
                int n = x.Length - 1;
                Assert.That(n % 2, Is.EqualTo(1), $"F {f}: odd segment count");
                Assert.That(n, Is.GreaterThanOrEqualTo(Math.Min(f, 63) - 1e-9));
                Assert.That(x[0], Is.EqualTo(0.0)); Assert.That(x[n], Is.EqualTo(1.0));
                double longest = 0;
                for (int i = 0; i < n; i++) { Assert.That(x[i + 1], Is.GreaterThan(x[i])); longest = Math.Max(longest, x[i + 1] - x[i]); }
                Assert.That(longest, Is.EqualTo(1.0 / Math.Max(1.0, Math.Min(f, 63))).Within(1e-12), $"F {f}");
            }
        }

        [Test]
        public void PixelErrorIsWorldErrorTimesPixelsPerUnitAndOnlyVisibleSamplesCount()
        {
            var cam = RigCamera.LookAt(new[] { 0.5, 2.0, -1.5 }, new[] { 0.5, 0.0, 0.5 }, 50, 800, 600, 0.01, 20, RigCamera.Scale(1, 1, 1));
            var r = ErrorMeasure.Measure(Paraboloid(0.5, 1.0), new[] { PatchFactors.Uniform(4) }, cam, fractionalOdd: false);
            double h = 0.25, kmax = 0;
            for (double s = 0; s <= 1; s += 0.125)
                for (double t = 0; t <= 1; t += 0.125)
                    kmax = Math.Max(kmax, cam.PixelsPerUnit(new[] { s, 0.5 * (s * s + t * t), t }));
            Assert.That(r.MaxPixels, Is.LessThanOrEqualTo(0.5 * h * h / 2 * kmax * 1.0001));
            Assert.That(r.MaxPixels, Is.GreaterThan(0.5 * h * h / 4 * kmax * 0.5));
            var behind = RigCamera.LookAt(new[] { 0.5, 0.2, -3.0 }, new[] { 0.5, 0.2, -6.0 }, 50, 800, 600, 0.01, 20, RigCamera.Scale(1, 1, 1));
            Assert.That(ErrorMeasure.Measure(Paraboloid(0.5, 1.0), new[] { PatchFactors.Uniform(4) }, behind, fractionalOdd: false).Samples, Is.EqualTo(0));
        }

        [Test]
        public void ACulledPatchIsNotMeasuredAndBadReadbackIsRefused()
        {
            var f = new[] { PatchFactors.Uniform(3), new PatchFactors { culled = true } };
            var r = ErrorMeasure.Measure(Paraboloid(1, 1), f, null, fractionalOdd: false);
            Assert.That(r.CulledPatches, Is.EqualTo(1));
            var nan = new float[16]; nan[9] = float.NaN;
            Assert.That(Assert.Throws<FormatException>(() => PatchFactors.FromReadback(nan, 2)).Message, Does.Contain("patch 1"));
            Assert.Throws<FormatException>(() => PatchFactors.FromReadback(new float[8], 2));
        }
    }
}
