using System;
using System.Collections.Generic;
using System.Threading;
using NUnit.Framework;

namespace GregoryTerrain.Tests
{
    [TestFixture]
    public class HeightmapFitterTests
    {
        /// <summary>A smooth test terrain: two sines and two gaussians, heights within about +-0.15.</summary>
        public static double Terrain(double x, double y) =>
            0.05 * Math.Sin(2 * Math.PI * x) * Math.Cos(Math.PI * y)
            + 0.03 * Math.Sin(3 * Math.PI * (x + 0.5 * y))
            + 0.08 * Math.Exp(-((x - 0.3) * (x - 0.3) + (y - 0.6) * (y - 0.6)) / 0.05)
            - 0.04 * Math.Exp(-((x - 0.75) * (x - 0.75) + (y - 0.25) * (y - 0.25)) / 0.03);

        public static double[] Samples(int w, int h)
        {
            var a = new double[w * h];
            for (int r = 0; r < h; r++)
                for (int c = 0; c < w; c++)
                    a[r * w + c] = Terrain((double)c / (w - 1), (double)r / (h - 1));
            return a;
        }

        internal static HeightmapFit Fit5x5() => HeightmapFitter.Fit(Samples(129, 129), 129, 129, 5, 5);

        // Stated tolerances: the terrain's heights span about 0.25 and its gaussians are about one
        // patch wide; a 5 x 5 grid must reproduce the samples to 1% of that range at worst (2.5e-3)
        // and 0.4% RMS (1e-3).
        const double MaxTolerance = 2.5e-3, RmsTolerance = 1e-3;

        [Test]
        public void FittedGridIsG1AndReproducesHeights()
        {
            HeightmapFit fit = Fit5x5();
            Assert.DoesNotThrow(fit.Grid.Validate);
            double angle = ContinuityMeasure.MaxNormalAngleDegrees(fit.Grid);
            TestContext.Out.WriteLine($"5x5 fit of 129x129 samples: max error {fit.MaxError:E3}, RMS {fit.RmsError:E3} (tolerances {MaxTolerance:E1}, {RmsTolerance:E1}); max normal angle across shared edges {angle:E3} deg ({ContinuityMeasure.DefaultSamplesPerEdge} samples per edge)");
            Assert.That(angle, Is.LessThan(0.1));
            Assert.That(ContinuityMeasure.MaxPositionGap(fit.Grid), Is.EqualTo(0.0));
            Assert.That(fit.MaxError, Is.LessThan(MaxTolerance));
            Assert.That(fit.RmsError, Is.LessThan(RmsTolerance));
        }

        [Test]
        public void ErrorFallsWithFinerGrids()
        {
            double[] a = Samples(129, 129);
            HeightmapFit coarse = HeightmapFitter.Fit(a, 129, 129, 4, 4), fine = HeightmapFitter.Fit(a, 129, 129, 8, 8);
            TestContext.Out.WriteLine($"max error 4x4: {coarse.MaxError:E3}, 8x8: {fine.MaxError:E3} (ratio {coarse.MaxError / fine.MaxError:F1}); RMS {coarse.RmsError:E3}, {fine.RmsError:E3}");
            // Least squares in bicubic G1 nets: fourth order on smooth data, so halving h divides the error by > 6.
            Assert.That(fine.MaxError, Is.LessThan(coarse.MaxError / 6));
            Assert.That(ContinuityMeasure.MaxNormalAngleDegrees(fine.Grid), Is.LessThan(0.1));
        }

        [Test]
        public void ReportedErrorMatchesAnIndependentCheck()
        {
            HeightmapFit fit = Fit5x5();
            // Recompute at every 4th sample by evaluating through regions found independently.
            double max = 0;
            for (int r = 0; r < 129; r += 4)
                for (int c = 0; c < 129; c += 4)
                {
                    double x = c / 128.0, y = r / 128.0;
                    int i = Math.Min(4, (int)Math.Floor(x * 5)), j = Math.Min(4, (int)Math.Floor(y * 5));
                    Region reg = fit.Grid.RegionOf(i, j);
                    Double3 p = GregoryEval.Position(fit.Grid.Patch(i, j).Points, (x - reg.a) / reg.Width, (y - reg.b) / reg.Height);
                    Assert.That(p.x, Is.EqualTo(x).Within(1e-14));
                    Assert.That(p.y, Is.EqualTo(y).Within(1e-14));
                    max = Math.Max(max, Math.Abs(p.z - Terrain(x, y)));
                }
            Assert.That(max, Is.LessThanOrEqualTo(fit.MaxError + 1e-15));
            Assert.That(max, Is.GreaterThan(0.0));
        }

        [Test]
        public void IsTheLeastSquaresOptimumOfItsSpace()
        {
            // Along any one unknown of the G1 net (a vertex height or offset, an edge's cross offset)
            // the sum of squared errors, measured on the Gregory grid itself, is a parabola; moving to
            // its minimum must gain almost nothing: the fit is the optimum of its space, up to the tiny
            // ridge and CG's tolerance.
            int w = 65, h = 49;
            double[] a = Samples(w, h);
            HeightmapFit fit = HeightmapFitter.Fit(a, w, h, 4, 3);
            double best = SquaredError(fit.Grid, a, w, h);
            Assert.That(Math.Sqrt(best / (w * h)), Is.EqualTo(fit.RmsError).Within(1e-12));
            double[] x = fit.Unknowns;
            // Every kind of unknown: vertices (z, dx, dy), vertical and horizontal edges.
            var picks = new List<int> { fit.Net.Vertex(2, 1), fit.Net.Vertex(2, 1) + 1, fit.Net.Vertex(1, 2) + 2, fit.Net.Vertex(4, 3) + 1,
                fit.Net.VerticalEdge(2, 1), fit.Net.VerticalEdge(0, 2) + 1, fit.Net.HorizontalEdge(1, 1), fit.Net.HorizontalEdge(3, 3) + 1 };
            var rng = new Random(27);
            for (int trial = 0; trial < 8; trial++) picks.Add(rng.Next(x.Length));
            const double step = 1e-3;
            double worst = 0;
            foreach (int k in picks)
            {
                double Moved(double d)
                {
                    var m = (double[])x.Clone();
                    m[k] += d;
                    return SquaredError(fit.Net.ToPatchGrid(m), a, w, h);
                }
                double lo = Moved(-step), hi = Moved(step), curvature = lo - 2 * best + hi;
                Assert.That(curvature, Is.GreaterThan(0), $"unknown {k}: the error does not depend on it");
                double gain = (hi - lo) * (hi - lo) / (8 * curvature);
                worst = Math.Max(worst, gain / best);
            }
            TestContext.Out.WriteLine($"largest gain from moving one unknown to its own optimum: {worst:E2} of the sum of squares");
            Assert.That(worst, Is.LessThan(1e-6));
        }

        [Test]
        public void BeatsTheC1SplineItStartsFrom()
        {
            // The net space holds the C1 splines (pairs coincident), so the fit can only be closer;
            // on this terrain the Gregory pairs' freedom shows.
            double[] a = Samples(129, 129);
            foreach (int n in new[] { 3, 5, 8 })
            {
                HeightmapFit fit = HeightmapFitter.Fit(a, 129, 129, n, n);
                double spline = Math.Sqrt(SquaredError(fit.Surface.ToPatchGrid(), a, 129, 129) / (129 * 129));
                TestContext.Out.WriteLine($"{n}x{n}: Gregory net RMS {fit.RmsError:E3}, C1 spline RMS {spline:E3} (ratio {fit.RmsError / spline:F3}), {fit.Iterations} CG iterations");
                Assert.That(fit.RmsError, Is.LessThan(0.99 * spline));
            }
        }

        [Test]
        public void TheSplineFromTheSharedPassIsTheSeparableFit()
        {
            // The C1 spline is solved from T^T S^T z (GregoryNet.SplineRightHandSide) instead of its own
            // pass over the samples: the two must agree to rounding.
            int w = 61, h = 45;
            double[] a = Samples(w, h);
            SplineSurface direct = SplineSurface.Fit(a, w, h, 5, 3, null, CancellationToken.None);
            HeightmapFit fit = HeightmapFitter.Fit(a, w, h, 5, 3);
            double scale = 0;
            foreach (double c in direct.Coefficients) scale = Math.Max(scale, Math.Abs(c));
            for (int k = 0; k < direct.Coefficients.Length; k++)
                Assert.That(fit.Surface.Coefficients[k], Is.EqualTo(direct.Coefficients[k]).Within(1e-12 * scale), $"coefficient {k}");
        }

        [Test]
        public void SplineToNetMapsAgree()
        {
            // x = T c two ways (the coefficient formulas, and differences of the spline's Bezier net),
            // and T^T (SplineRightHandSide) the transpose of T: r . (T c) = (T^T r) . c.
            var net = new GregoryNet(4, 3);
            var bx = new C1SplineBasis(4);
            var by = new C1SplineBasis(3);
            var rng = new Random(5);
            var c = new double[bx.Count * by.Count];
            for (int k = 0; k < c.Length; k++) c[k] = rng.NextDouble() - 0.5;
            var r = new double[net.Count];
            for (int k = 0; k < r.Length; k++) r[k] = rng.NextDouble() - 0.5;
            var x = new double[net.Count];
            net.FromSpline(c, x);
            double[] viaNet = net.FromBezierNet(new SplineSurface(bx, by, c).BezierNet());
            for (int k = 0; k < x.Length; k++) Assert.That(x[k], Is.EqualTo(viaNet[k]).Within(1e-14), $"unknown {k}");
            double[] tr = net.SplineRightHandSide(r);
            double lhs = 0, rhs = 0;
            for (int k = 0; k < x.Length; k++) lhs += r[k] * x[k];
            for (int k = 0; k < c.Length; k++) rhs += tr[k] * c[k];
            Assert.That(lhs, Is.EqualTo(rhs).Within(1e-12));
        }

        static double SquaredError(PatchGrid g, double[] a, int w, int h)
        {
            double s = 0;
            for (int r = 0; r < h; r++)
                for (int c = 0; c < w; c++)
                {
                    double x = (double)c / (w - 1), y = (double)r / (h - 1);
                    int p = g.FindPatch(x, y);
                    Region reg = g.RegionOf(p);
                    double e = GregoryEval.Position(g.Patches[p].Points, (x - reg.a) / reg.Width, (y - reg.b) / reg.Height).z - a[r * w + c];
                    s += e * e;
                }
            return s;
        }

        [Test]
        public void FitToTargetPicksTheFewestPatchesThatMeetIt()
        {
            double[] a = Samples(129, 129);
            double target = HeightmapFitter.Fit(a, 129, 129, 6, 6).MaxError * 1.0001;
            HeightmapFit f = HeightmapFitter.FitToTarget(a, 129, 129, target, FitErrorKind.Max, 64);
            Assert.That(f.MaxError, Is.LessThanOrEqualTo(target));
            Assert.That(f.Grid.Columns, Is.LessThanOrEqualTo(6));
            Assert.That(HeightmapFitter.Fit(a, 129, 129, f.Grid.Columns - 1, f.Grid.Columns - 1).MaxError, Is.GreaterThan(target));
            // Out of reach: the largest grid comes back, its error above the target.
            HeightmapFit capped = HeightmapFitter.FitToTarget(a, 129, 129, 1e-12, FitErrorKind.Rms, 4);
            Assert.That(capped.Grid.Columns, Is.EqualTo(4));
            Assert.That(capped.RmsError, Is.GreaterThan(1e-12));
        }

        [Test]
        public void ReproducesAPlaneExactly()
        {
            // A plane lies in the spline space and the smoothing term vanishes on it.
            int w = 17, h = 9;
            var a = new double[w * h];
            for (int r = 0; r < h; r++)
                for (int c = 0; c < w; c++)
                    a[r * w + c] = 0.25 + 0.5 * c / (w - 1.0) - 0.125 * r / (h - 1.0);
            HeightmapFit fit = HeightmapFitter.Fit(a, w, h, 3, 2);
            Assert.That(fit.MaxError, Is.LessThan(1e-14));
        }

        [Test]
        public void ReportsProgressUpToOne()
        {
            var seen = new List<float>();
            HeightmapFitter.Fit(Samples(33, 33), 33, 33, 2, 2, new SyncProgress(seen));
            Assert.That(seen.Count, Is.GreaterThan(2));
            Assert.That(seen[seen.Count - 1], Is.EqualTo(1f));
            for (int k = 1; k < seen.Count; k++) Assert.That(seen[k], Is.GreaterThanOrEqualTo(seen[k - 1]));
        }

        [Test]
        public void CancellationThrows()
        {
            using var cts = new CancellationTokenSource();
            cts.Cancel();
            Assert.Throws<OperationCanceledException>(() => HeightmapFitter.Fit(Samples(33, 33), 33, 33, 2, 2, null, cts.Token));
            // Cancelled from the progress callback, mid-way.
            using var cts2 = new CancellationTokenSource();
            var p = new SyncProgress(new List<float>(), f => { if (f > 0.3f) cts2.Cancel(); });
            Assert.Throws<OperationCanceledException>(() => HeightmapFitter.Fit(Samples(33, 33), 33, 33, 4, 4, p, cts2.Token));
        }

        [Test]
        public void RejectsBadInput()
        {
            var ex = Assert.Throws<ArgumentException>(() => HeightmapFitter.Fit(new double[10], 3, 3, 1, 1));
            Assert.That(ex.Message, Does.Contain("heights.Length = 10"));
            var bad = Samples(5, 5);
            bad[7] = double.PositiveInfinity;
            ex = Assert.Throws<ArgumentException>(() => HeightmapFitter.Fit(bad, 5, 5, 1, 1));
            Assert.That(ex.Message, Does.Contain("heights[7]").And.Contain("column 2, row 1").And.Contain("Infinity"));
            ex = Assert.Throws<ArgumentException>(() => HeightmapFitter.Fit(Samples(5, 5), 5, 5, 0, 1));
            Assert.That(ex.Message, Does.Contain("columns = 0"));
            ex = Assert.Throws<ArgumentException>(() => HeightmapFitter.Fit(new double[5], 5, 1, 1, 1));
            Assert.That(ex.Message, Does.Contain("height = 1"));
        }

        /// <summary>IProgress that reports synchronously (System.Progress posts to a context).</summary>
        sealed class SyncProgress : IProgress<float>
        {
            readonly List<float> seen;
            readonly Action<float> also;
            public SyncProgress(List<float> seen, Action<float> also = null) { this.seen = seen; this.also = also; }
            public void Report(float value) { seen.Add(value); also?.Invoke(value); }
        }
    }
}
