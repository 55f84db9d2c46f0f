// gt-cli error's measure (Tools~/dotnet/Gt/ErrorMeasure.cs, compiled into this assembly) on surfaces
// with a known answer.
using System;
using System.Linq;
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

        // Integer partitioning (the vertex cache, GT_VERTEX_CACHE): n = ceil(F) equal segments, so the
        // largest error is k h^2 / 2 with h = L / ceil(F), not L / F as fractional_odd's longest segment.
        [TestCase(1.0, 1.0, 4.3)]
        [TestCase(3.0, 0.5, 8.0)]
        [TestCase(0.2, 2.0, 1.0)]
        [TestCase(2.0, 1.0, 1.01)]
        [TestCase(0.5, 1.0, 63.2)]
        public void IntegerPartitioningParaboloidErrorIsTheChordErrorAtCeilF(double k, double l, double factor)
        {
            var r = ErrorMeasure.Measure(Paraboloid(k, l), new[] { PatchFactors.Uniform(factor) }, null, fractionalOdd: false);
            int n = (int)Math.Ceiling(factor);
            double h = l / n;
            Assert.That(r.MaxWorld, Is.EqualTo(k * h * h / 2).Within(1e-9).Percent);
            Assert.That(r.Samples, Is.EqualTo(n * n * 4L + 2L * n + 4L * n));
            Assert.That(r.Triangles, Is.EqualTo(2L * n * n), "uniform n: 2 n^2 triangles");
            if (factor != n)
            {
                // fractional_odd at the same F has full segments of L / F: a different (smaller) error.
                var odd = ErrorMeasure.Measure(Paraboloid(k, l), new[] { PatchFactors.Uniform(factor) }, null, fractionalOdd: true);
                double full = l / Math.Min(factor, 63);   // fractional_odd's range ends at 63
                Assert.That(odd.MaxWorld, Is.EqualTo(k * full * full / 2).Within(1e-9).Percent);
                Assert.That(r.MaxWorld, Is.LessThan(odd.MaxWorld));
            }
        }

        // Height kx x^2 + ky y^2 over the unit patch: a cell hu x hv misses by (kx hu^2 + ky hv^2) / 4 at
        // its centre, a border segment of length h along u by kx h^2 / 4 (along v: ky h^2 / 4).
        static Func<int, double, double, double[]> Anisotropic(double kx, double ky) =>
            (p, s, t) => new[] { s, kx * s * s + ky * t * t, t };

        [TestCase(5.5, 2.2, 8, 8, 8, 8)]     // fine border: the inside grid (6 x 3 cells) sets the error
        [TestCase(5.5, 2.2, 8, 1, 8, 8)]     // edge v = 0 (along u) one segment: kx / 4
        [TestCase(5.5, 2.2, 1, 8, 8, 8)]     // edge u = 0 (along v) one segment: ky / 4
        [TestCase(4.0, 4.0, 8, 8, 8, 2.5)]   // edge v = 1 at 3 segments: kx / 36 < grid error
        [TestCase(2.0, 7.0, 3, 5, 2, 4)]
        public void IntegerPartitioningTakesTheGridFromInsideAndTheBorderFromEdgeFactors(double i0, double i1, double e0, double e1, double e2, double e3)
        {
            const double kx = 1.0, ky = 3.0;
            var f = new PatchFactors { e0 = e0, e1 = e1, e2 = e2, e3 = e3, i0 = i0, i1 = i1 };
            var r = ErrorMeasure.Measure(Anisotropic(kx, ky), new[] { f }, null, fractionalOdd: false);
            double N(double x) => Math.Ceiling(x);
            double hu = 1 / N(i0), hv = 1 / N(i1);
            double expected = (kx * hu * hu + ky * hv * hv) / 4;
            expected = Math.Max(expected, kx / (N(e1) * N(e1)) / 4);   // v = 0 runs along u
            expected = Math.Max(expected, kx / (N(e3) * N(e3)) / 4);   // v = 1
            expected = Math.Max(expected, ky / (N(e0) * N(e0)) / 4);   // u = 0 runs along v
            expected = Math.Max(expected, ky / (N(e2) * N(e2)) / 4);   // u = 1
            Assert.That(r.MaxWorld, Is.EqualTo(expected).Within(1e-9).Percent);
            long nu = (long)N(i0), nv = (long)N(i1);
            Assert.That(r.Samples, Is.EqualTo(4 * nu * nv + nu + nv + (long)(N(e0) + N(e1) + N(e2) + N(e3))));
        }

        [Test]
        public void IntegerTriangleCountIncludesTheTransitionRings()
        {
            for (int n = 1; n <= 64; n++)
                Assert.That(TessellationCells.IntegerTriangles(PatchFactors.Uniform(n)), Is.EqualTo(2L * n * n), $"uniform {n}");
            // Inside 2 x 2: the inner rectangle is a point, each side a fan of e triangles.
            Assert.That(TessellationCells.IntegerTriangles(new PatchFactors { e0 = 1, e1 = 2, e2 = 3, e3 = 4, i0 = 2, i1 = 2 }), Is.EqualTo(10));
            // Inside 1 beside a subdivided edge is drawn as 2 (as the cache writes it).
            Assert.That(TessellationCells.IntegerTriangles(new PatchFactors { e0 = 1, e1 = 2, e2 = 1, e3 = 1, i0 = 1, i1 = 1 }), Is.EqualTo(5));
            // 7 x 8 inside: 5 x 6 inner quads, strips e + (i - 2).
            Assert.That(TessellationCells.IntegerTriangles(new PatchFactors { e0 = 3, e1 = 4, e2 = 5, e3 = 6, i0 = 7, i1 = 8 }),
                        Is.EqualTo(2 * 5 * 6 + (4 + 5) + (6 + 5) + (3 + 6) + (5 + 6)));
            Assert.That(TessellationCells.IntegerTriangles(new PatchFactors { culled = true }), Is.EqualTo(0));
            Assert.Throws<ArgumentException>(() => TessellationCells.Integer(64.5));
            Assert.Throws<ArgumentException>(() => TessellationCells.Integer(double.NaN));
        }

        [Test]
        public void CoreFactorsBecomeTheCachesIntegers()
        {
            var all1 = new PatchFactors { e0 = 1, e1 = 0.4, e2 = 1, e3 = 1, i0 = 1, i1 = 0.9 }.CacheIntegers();
            Assert.That(new[] { all1.e0, all1.e1, all1.e2, all1.e3, all1.i0, all1.i1 }, Is.All.EqualTo(1.0));
            var one = new PatchFactors { e0 = 1.0001, e1 = 1, e2 = 1, e3 = 1, i0 = 1, i1 = 1 }.CacheIntegers();
            Assert.That(new[] { one.e0, one.e1, one.e2, one.e3, one.i0, one.i1 }, Is.EqualTo(new[] { 2.0, 1, 1, 1, 2, 2 }));
            var big = new PatchFactors { e0 = 63.01, e1 = 70, e2 = 3, e3 = 2.5, i0 = 5.0, i1 = 1.2 }.CacheIntegers();
            Assert.That(new[] { big.e0, big.e1, big.e2, big.e3, big.i0, big.i1 }, Is.EqualTo(new[] { 64.0, 64, 3, 3, 5, 2 }));
            var culled = new PatchFactors { e0 = 5, e1 = 5, e2 = 5, e3 = 5, i0 = 5, i1 = 5, culled = true }.CacheIntegers();
            Assert.That(culled.culled, Is.True);
            Assert.That(new[] { culled.e0, culled.i0, culled.i1 }, Is.All.EqualTo(0.0));
        }

        [Test]
        public void TileFactorsDumpIsReadAndItsIntegerContractChecked()
        {
            // Each tile's edge and inside float4, then its keys (zero here).
            float[] Dump(params float[][] tiles) => tiles.SelectMany(t => t.Concat(new float[PatchFactors.TileRecordFloats - 8])).ToArray();
            float[] drawn = { 3, 4, 5, 6, 7, 8, 0, 1 }, ones = { 1, 1, 1, 1, 1, 1, 0, 0 }, culled = { 0, 0, 0, 0, 0, 0, 1, 0 };
            var f = PatchFactors.FromTileFactors(Dump(drawn, ones, culled), 3);
            Assert.That(new[] { f[0].e0, f[0].e1, f[0].e2, f[0].e3, f[0].i0, f[0].i1 }, Is.EqualTo(new[] { 3.0, 4, 5, 6, 7, 8 }));
            Assert.That(f[0].culled || f[1].culled, Is.False);
            Assert.That(f[2].culled, Is.True);
            // Refused, naming the tile: never written (zero-filled), fractional, inside 1 beside a
            // subdivided edge, above 64, a culled tile with factors, a bad culled or evaluated flag, a
            // culled tile marked evaluated, a short dump.
            foreach (var bad in new[]
            {
                new float[] { 0, 0, 0, 0, 0, 0, 0, 0 }, new float[] { 3, 4, 5, 6, 7.5f, 8, 0, 0 }, new float[] { 2, 1, 1, 1, 1, 2, 0, 0 },
                new float[] { 65, 4, 5, 6, 7, 8, 0, 0 }, new float[] { 3, 0, 0, 0, 0, 0, 1, 0 }, new float[] { 3, 4, 5, 6, 7, 8, 0.5f, 0 },
                new float[] { 3, 4, 5, 6, 7, 8, 0, 0.5f }, new float[] { 0, 0, 0, 0, 0, 0, 1, 1 }, new float[] { float.NaN, 4, 5, 6, 7, 8, 0, 0 },
            })
                Assert.That(Assert.Throws<FormatException>(() => PatchFactors.FromTileFactors(Dump(ones, bad), 2)).Message, Does.Contain("tile 1"),
                            string.Join(",", bad));
            Assert.Throws<FormatException>(() => PatchFactors.FromTileFactors(Dump(ones), 2));
            // Core's prediction written in the dump's layout reads back as itself.
            var back = PatchFactors.FromTileFactors(PatchFactors.ToTileFactors(f), 3);
            Assert.That(back, Is.EqualTo(f));
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
