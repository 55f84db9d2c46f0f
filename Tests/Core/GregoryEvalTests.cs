using System;
using NUnit.Framework;

namespace GregoryTerrain.Tests
{
    [TestFixture]
    public class GregoryEvalTests
    {
        /// <summary>Eq. 4-6 transcribed literally: S = sum B_i(u) B_j(v) Q_ij with the rational Q_ij.</summary>
        static Double3 DirectEq4to6(GregoryPatch g, double u, double v)
        {
            Double3 P(int i, int j) => g[4 * i + j];
            var Q = new Double3[4, 4];
            for (int i = 0; i < 4; i++)
                for (int j = 0; j < 4; j++)
                    Q[i, j] = P(i, j);
            Q[1, 1] = (u * g[GregoryPatch.P110] + v * g[GregoryPatch.P111]) / (u + v);
            Q[1, 2] = (u * g[GregoryPatch.P120] + (1 - v) * g[GregoryPatch.P121]) / (u + 1 - v);
            Q[2, 1] = ((1 - u) * g[GregoryPatch.P210] + v * g[GregoryPatch.P211]) / (1 - u + v);
            Q[2, 2] = ((1 - u) * g[GregoryPatch.P220] + (1 - v) * g[GregoryPatch.P221]) / (2 - u - v);
            Double3 s = Double3.zero;
            for (int i = 0; i < 4; i++)
                for (int j = 0; j < 4; j++)
                    s += TestPatches.B3(i, u) * TestPatches.B3(j, v) * Q[i, j];
            return s;
        }

        /// <summary>
        /// A patch 1e-6 across at coordinates near 0.5 (the TinyRegion hard case): the float
        /// derivatives sum control-point differences, so the float normal keeps the double's
        /// direction (summing the points themselves cancels ~1e6-fold).
        /// </summary>
        [Test]
        public void TinyPatchFarFromTheOriginKeepsItsNormalInFloat()
        {
            GregoryPatch shape = TestPatches.Random(11);
            var cpf = new Float3[GregoryPatch.SlotCount];
            var cpd = new Double3[GregoryPatch.SlotCount];
            for (int k = 0; k < GregoryPatch.SlotCount; k++)
            {
                Double3 q = new Double3(0.5, 0.5, 0.5) + 1e-6 * shape[k];
                cpf[k] = new Float3((float)q.x, (float)q.y, (float)q.z);
                cpd[k] = new Double3(cpf[k].x, cpf[k].y, cpf[k].z);   // the same points: only the arithmetic differs
            }
            double worst = 0;
            var rng = new Random(3);
            for (int n = 0; n < 2000; n++)
            {
                float u = (float)rng.NextDouble(), v = (float)rng.NextDouble();
                Float3 nf = GregoryEval.Normal(cpf, u, v);
                Double3 nd = GregoryEval.Normal(cpd, u, v);
                worst = Math.Max(worst, GMath.length(new Double3(nf.x, nf.y, nf.z) - nd));
            }
            TestContext.Out.WriteLine("tiny patch at 0.5: largest float-vs-double normal difference {0:G3}", worst);
            Assert.That(worst, Is.LessThan(1e-4));
        }

        [Test]
        public void MatchesDirectTranscriptionOfEq4To6()
        {
            var rng = new Random(7);
            double worst = 0;
            for (int n = 0; n < 20; n++)
            {
                var g = TestPatches.Random(100 + n);
                for (int r = 0; r < 500; r++)
                {
                    double u = rng.NextDouble(), v = rng.NextDouble();
                    Double3 p = GregoryEval.Position(g.Points, u, v);
                    worst = Math.Max(worst, TestPatches.Dist(p, DirectEq4to6(g, u, v)));
                }
            }
            TestContext.Out.WriteLine($"max |Gregory - eq.4-6| over 10,000 points: {worst:E3}");
            Assert.That(worst, Is.LessThan(1e-12));
        }

        static readonly (double u, double v, int slot)[] Corners =
            { (0, 0, GregoryPatch.Corner00), (0, 1, GregoryPatch.Corner03), (1, 0, GregoryPatch.Corner30), (1, 1, GregoryPatch.Corner33) };

        [Test]
        public void CornersAreExactInDoubleAndFloat()
        {
            for (int n = 0; n < 50; n++)
            {
                var g = TestPatches.Random(n, 1000.0);
                Float3[] f = TestPatches.ToFloat(g);
                foreach (var c in Corners)
                {
                    GregoryEval.Evaluate(g.Points, c.u, c.v, out Double3 pd, out _, out _);
                    GregoryEval.Evaluate(f, (float)c.u, (float)c.v, out Float3 pf, out _, out _);
                    Assert.That(pd, Is.EqualTo(g[c.slot]), $"double corner ({c.u}, {c.v})");
                    Assert.That(pf, Is.EqualTo(f[c.slot]), $"float corner ({c.u}, {c.v})");
                }
            }
        }

        [Test]
        public void BezierReduction()
        {
            var rng = new Random(3);
            var net = new Double3[16];
            for (int k = 0; k < 16; k++) net[k] = new Double3(rng.NextDouble(), rng.NextDouble(), rng.NextDouble());
            var g = GregoryPatch.FromBezier(net);
            Assert.That(g[GregoryPatch.P111], Is.EqualTo(net[GregoryPatch.P110]));
            Assert.That(g[GregoryPatch.P221], Is.EqualTo(net[GregoryPatch.P220]));
            for (int r = 0; r < 1000; r++)
            {
                double u = rng.NextDouble(), v = rng.NextDouble();
                Double3 bez = Double3.zero;
                for (int i = 0; i < 4; i++)
                    for (int j = 0; j < 4; j++)
                        bez += TestPatches.B3(i, u) * TestPatches.B3(j, v) * net[4 * i + j];
                Assert.That(TestPatches.Dist(GregoryEval.Position(g.Points, u, v), bez), Is.LessThan(1e-14));
            }
        }

        [Test]
        public void DerivativesMatchCentralDifferences()
        {
            var rng = new Random(11);
            const double h = 1e-5;
            double worst = 0;
            for (int n = 0; n < 10; n++)
            {
                var g = TestPatches.Random(200 + n);
                for (int r = 0; r < 200; r++)
                {
                    double u = h + (1 - 2 * h) * rng.NextDouble(), v = h + (1 - 2 * h) * rng.NextDouble();
                    GregoryEval.Evaluate(g.Points, u, v, out _, out Double3 du, out Double3 dv);
                    Double3 fdu = (GregoryEval.Position(g.Points, u + h, v) - GregoryEval.Position(g.Points, u - h, v)) / (2 * h);
                    Double3 fdv = (GregoryEval.Position(g.Points, u, v + h) - GregoryEval.Position(g.Points, u, v - h)) / (2 * h);
                    // Relative to |second derivative| scale: the rational blend is steep near corners,
                    // so compare relative to the local derivative size plus an absolute floor.
                    double scale = 1 + TestPatches.MaxAbs(du) + TestPatches.MaxAbs(dv);
                    worst = Math.Max(worst, Math.Max(TestPatches.Dist(du, fdu), TestPatches.Dist(dv, fdv)) / scale);
                }
            }
            TestContext.Out.WriteLine($"max relative |analytic - central FD| (h = {h}): {worst:E3}");
            Assert.That(worst, Is.LessThan(1e-5));
        }

        [Test]
        public void WeightsSumToOneAndDerivativesToZero()
        {
            var rng = new Random(5);
            Span<double> w = stackalloc double[20], wu = stackalloc double[20], wv = stackalloc double[20];
            for (int r = 0; r < 1000; r++)
            {
                GregoryBasis.Weights(rng.NextDouble(), rng.NextDouble(), w, wu, wv);
                double s = 0, su = 0, sv = 0;
                for (int k = 0; k < 20; k++) { s += w[k]; su += wu[k]; sv += wv[k]; }
                Assert.That(s, Is.EqualTo(1.0).Within(1e-14));
                Assert.That(su, Is.EqualTo(0.0).Within(1e-13));
                Assert.That(sv, Is.EqualTo(0.0).Within(1e-13));
            }
        }

        [Test]
        public void FloatEvaluatorTracksDouble()
        {
            var rng = new Random(9);
            var g = TestPatches.Random(42);
            Float3[] f = TestPatches.ToFloat(g);
            var gf = new GregoryPatch();
            for (int k = 0; k < 20; k++) gf[k] = f[k]; // the float-rounded points, in double
            double worst = 0;
            for (int r = 0; r < 10000; r++)
            {
                double u = rng.NextDouble(), v = rng.NextDouble();
                GregoryEval.Evaluate(f, (float)u, (float)v, out Float3 pf, out Float3 duf, out Float3 dvf);
                GregoryEval.Evaluate(gf.Points, (float)u, (float)v, out Double3 pd, out Double3 dud, out Double3 dvd);
                worst = Math.Max(worst, TestPatches.Dist(pf, pd));
                Assert.That(TestPatches.Dist(duf, dud), Is.LessThan(1e-4));
                Assert.That(TestPatches.Dist(dvf, dvd), Is.LessThan(1e-4));
            }
            TestContext.Out.WriteLine($"random patch, float vs double position: {worst:E3}");
            Assert.That(worst, Is.LessThan(1e-5));
        }

        [Test]
        public void NormalIsUnitAndPerpendicular()
        {
            var g = TestPatches.Random(77);
            Double3 n = GregoryEval.Normal(g.Points, 0.3, 0.6);
            GregoryEval.Evaluate(g.Points, 0.3, 0.6, out _, out Double3 du, out Double3 dv);
            Assert.That(GMath.length(n), Is.EqualTo(1.0).Within(1e-14));
            Assert.That(GMath.dot(n, du), Is.EqualTo(0.0).Within(1e-12));
            Assert.That(GMath.dot(n, dv), Is.EqualTo(0.0).Within(1e-12));
        }

        [Test]
        public void RejectsWrongControlPointCount()
        {
            var ex = Assert.Throws<ArgumentException>(() => GregoryEval.Evaluate(new Double3[16], 0.5, 0.5, out _, out _, out _));
            Assert.That(ex.Message, Does.Contain("16"));
        }
    }
}
