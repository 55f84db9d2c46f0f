using System;
using NUnit.Framework;

namespace GregoryTerrain.Tests
{
    /// <summary>
    /// The adaptive knob (target screen-space error in pixels): pixel scale, edge chord error
    /// (sagitta), the factor that meets the target, tile culling with the noise margin, the
    /// adaptive triangle estimate.
    /// </summary>
    [TestFixture]
    public class TessellationErrorTests
    {
        static readonly Float2 Screen = new Float2(1600f, 900f);

        // Right-handed perspective looking down -z, clip w = -z_view; camera at the origin.
        static Float4x4 Perspective(float fovY, float aspect, float near, float far)
        {
            float f = 1f / (float)Math.Tan(fovY / 2);
            return Float4x4.FromRows(
                f / aspect, 0, 0, 0,
                0, f, 0, 0,
                0, 0, (far + near) / (near - far), 2 * far * near / (near - far),
                0, 0, -1, 0);
        }

        static Float2 Pixels(Float4x4 m, Float3 p) => TessellationPolicy.ClipToPixels(m.TransformPoint(p), Screen);

        [Test]
        public void PixelsPerUnitIsTheLargestScreenStretchOfASmallStep()
        {
            Float4x4 m = Perspective(1.0f, Screen.x / Screen.y, 0.1f, 100f);
            var rng = new Random(5);
            for (int n = 0; n < 200; n++)
            {
                var p = new Float3((float)(rng.NextDouble() * 4 - 2), (float)(rng.NextDouble() * 4 - 2), -(float)(1 + rng.NextDouble() * 9));
                float k = TessellationPolicy.PixelsPerUnit(m, p, Screen);
                // Finite differences in many directions: none stretches more than k, the best one about k.
                double best = 0;
                const float h = 1e-3f;
                for (int d = 0; d < 400; d++)
                {
                    double th = Math.Acos(2 * rng.NextDouble() - 1), ph = 2 * Math.PI * rng.NextDouble();
                    var dir = new Float3((float)(Math.Sin(th) * Math.Cos(ph)), (float)(Math.Sin(th) * Math.Sin(ph)), (float)Math.Cos(th));
                    Float2 a = Pixels(m, p - dir * h), b = Pixels(m, p + dir * h);
                    double stretch = Math.Sqrt((b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y)) / (2 * h);
                    Assert.That(stretch, Is.LessThanOrEqualTo(k * 1.01), $"point {p} direction {dir}");
                    best = Math.Max(best, stretch);
                }
                Assert.That(best, Is.GreaterThan(k * 0.95), $"point {p}");
            }
            // On the axis at distance w the scale is the focal length in pixels over w.
            float focalPixels = 0.5f * Screen.y / (float)Math.Tan(0.5);
            Assert.That(TessellationPolicy.PixelsPerUnit(m, new Float3(0, 0, -4), Screen), Is.EqualTo(focalPixels / 4).Within(1e-3).Percent);
            Assert.That(TessellationPolicy.PixelsPerUnit(m, new Float3(0, 0, 1), Screen), Is.EqualTo(float.PositiveInfinity), "behind the eye");
        }

        // A parabola z = k x^2 over [x0, x0 + L]: the chord's sagitta is k L^2 / 4 (= L^2 kappa / 8, kappa = 2k).
        static Float3 Parabola(float k, float x) => new Float3(x, 0f, k * x * x);

        [TestCase(0.5f, 1.0f, 0.0f)]
        [TestCase(2.0f, 0.25f, -0.3f)]
        [TestCase(0.1f, 3.0f, 1.7f)]
        public void EdgeSagittaOfAParabolaIsAnalytic(float k, float length, float x0)
        {
            Float3 P(double t) => Parabola(k, (float)(x0 + t * length));
            float s = TessellationPolicy.EdgeSagitta(P(0), P(0.25), P(0.5), P(0.75), P(1));
            Assert.That(s, Is.EqualTo(k * length * length / 4).Within(1e-4).Percent);
        }

        [Test]
        public void EdgeSagittaSeesAnSCurveAndIsSymmetric()
        {
            // (t - 1/2)^3: the middle lies on the chord, the halves do not.
            Float3 P(double t) => new Float3((float)t, 0f, (float)Math.Pow(t - 0.5, 3));
            float s = TessellationPolicy.EdgeSagitta(P(0), P(0.25), P(0.5), P(0.75), P(1));
            float midOnly = GMath.length(P(0.5) - 0.5f * (P(0) + P(1)));
            Assert.That(midOnly, Is.LessThan(1e-7f));
            Assert.That(s, Is.GreaterThan(0.05f));
            var rng = new Random(9);
            for (int n = 0; n < 10000; n++)
            {
                Float3 R() => new Float3((float)rng.NextDouble(), (float)rng.NextDouble(), (float)rng.NextDouble());
                Float3 a = R(), b = R(), c = R(), d = R(), e = R();
                Assert.That(TessellationPolicy.EdgeSagitta(a, b, c, d, e), Is.EqualTo(TessellationPolicy.EdgeSagitta(e, d, c, b, a)), "walked the other way");
                Assert.That(TessellationPolicy.EdgeSagittaPixels(a, b, c, d, e, 2f, 3f, 5f),
                    Is.EqualTo(TessellationPolicy.EdgeSagittaPixels(e, d, c, b, a, 5f, 3f, 2f)));
            }
        }

        [TestCase(40f, 1f)]
        [TestCase(300f, 0.5f)]
        [TestCase(7f, 2f)]
        public void ErrorTessFactorMeetsTheTargetOnAParabola(float sagittaPixels, float target)
        {
            float f = TessellationPolicy.ErrorTessFactor(sagittaPixels, target, 64f);
            Assert.That(f, Is.EqualTo((float)Math.Sqrt(2 * sagittaPixels / target)).Within(1e-5).Percent);
            // Split a parabola whose sagitta is sagittaPixels into ceil(F) equal segments and measure
            // the chord error at each segment's middle: within half the target (the other half is
            // the other direction's, in a cell), and not far below it.
            int segments = (int)Math.Ceiling(f);
            double k = 4.0 * sagittaPixels;   // z = k x^2 on [0, 1] has sagitta k / 4
            double worst = 0;
            for (int i = 0; i < segments; i++)
            {
                double x0 = (double)i / segments, x1 = (double)(i + 1) / segments, xm = 0.5 * (x0 + x1);
                worst = Math.Max(worst, 0.5 * (k * x0 * x0 + k * x1 * x1) - k * xm * xm);
            }
            Assert.That(worst, Is.LessThanOrEqualTo(0.5 * target * 1.0001));
            Assert.That(worst, Is.GreaterThan(0.5 * target * Math.Pow(f / (f + 1), 2) * 0.999));
        }

        [Test]
        public void ErrorTessFactorClampsAndRejectsBadInput()
        {
            Assert.That(TessellationPolicy.ErrorTessFactor(0f, 1f, 64f), Is.EqualTo(1f));
            Assert.That(TessellationPolicy.ErrorTessFactor(1e9f, 1f, 16f), Is.EqualTo(16f));
            Assert.That(TessellationPolicy.ErrorTessFactor(float.PositiveInfinity, 1f, 32f), Is.EqualTo(32f));
            Assert.That(TessellationPolicy.ErrorTessFactor(float.NaN, 1f, 32f), Is.EqualTo(32f));
            Assert.That(Assert.Throws<ArgumentException>(() => TessellationPolicy.ErrorTessFactor(4f, 0f, 64f)).Message, Does.Contain("(0)"));
            Assert.That(Assert.Throws<ArgumentException>(() => TessellationPolicy.ErrorTessFactor(4f, 1f, 0.5f)).Message, Does.Contain("maxFactor (0.5)"));
        }

        [Test]
        public void EdgeErrorTessFactorHalvingTheTargetMultipliesTheFactorBySqrt2()
        {
            Float4x4 m = Perspective(1.0f, Screen.x / Screen.y, 0.1f, 100f);
            // A bent edge 5 units in front of the camera.
            Float3 P(double t) => new Float3((float)(t - 0.5), (float)(0.2 * (t - 0.5) * (t - 0.5)), -5f);
            float f1 = TessellationPolicy.EdgeErrorTessFactor(m, P(0), P(0.25), P(0.5), P(0.75), P(1), Screen, 1f, 64f);
            float f05 = TessellationPolicy.EdgeErrorTessFactor(m, P(0), P(0.25), P(0.5), P(0.75), P(1), Screen, 0.5f, 64f);
            Assert.That(f1, Is.GreaterThan(1f));
            Assert.That(f05 / f1, Is.EqualTo(Math.Sqrt(2)).Within(1e-4).Percent);
            // Sagitta 0.05 units at w = 5: about 0.05 * focal / 5 pixels.
            double focal = 0.5 * Screen.y / Math.Tan(0.5);
            Assert.That(f1, Is.EqualTo(Math.Sqrt(2 * 0.05 * focal / 5)).Within(1).Percent);
        }

        [Test]
        public void TileJustOutsideTheViewIsKeptWhenItsNoiseCouldReachIn()
        {
            // Camera at the origin looking down -z; object y is height. A flat tile lies just below the
            // bottom plane of the view at distance 10: culled without noise, kept with a noise margin
            // large enough to lift the surface into the view, culled again when the margin cannot.
            float fov = 1.0f;
            Float4x4 m = Perspective(fov, 1f, 0.1f, 100f);
            float bottom = -10f * (float)Math.Tan(fov / 2);   // view's lower edge at z = -10
            float y = bottom - 0.3f;
            var corners = new[] { new Float3(-1, y, -9.9f), new Float3(1, y, -9.9f), new Float3(-1, y, -10.1f), new Float3(1, y, -10.1f) };
            Assert.That(TessellationPolicy.TileCulled(m, corners, 0f), Is.True, "flat, no noise: outside");
            var noise = new NoiseSettings(0.2f, 8f, 2f, 2f, 4);   // bound 0.2 * (1 + 1/2 + 1/4 + 1/8) = 0.375
            float bound = TessellationPolicy.NoiseHeightBound(noise);
            Assert.That(bound, Is.EqualTo(0.375f).Within(1e-6));
            Assert.That(TessellationPolicy.TileCulled(m, corners, bound), Is.False, "noise could reach into the view");
            Assert.That(TessellationPolicy.TileCulled(m, corners, 0.1f), Is.True, "0.1 cannot bridge 0.3 (+ the slant)");
            Assert.Throws<ArgumentException>(() => TessellationPolicy.TileCulled(m, new Float3[3], 0f));
            Assert.Throws<ArgumentException>(() => TessellationPolicy.TileCulled(m, corners, -1f));
            // Snow only raises the surface: a raise of 0.375 lifts the box into the view as the noise
            // did; the same tile above the view's upper edge is not brought in by any raise.
            Assert.That(TessellationPolicy.TileCulled(m, corners, 0f, 0.375f), Is.False, "snow could reach into the view");
            Assert.That(TessellationPolicy.TileCulled(m, corners, 0f, 0.1f), Is.True);
            float above = -bottom + 0.3f;
            var high = new[] { new Float3(-1, above, -9.9f), new Float3(1, above, -9.9f), new Float3(-1, above, -10.1f), new Float3(1, above, -10.1f) };
            Assert.That(TessellationPolicy.TileCulled(m, high, 0f, 10f), Is.True, "a raise never lowers the box");
            Assert.That(TessellationPolicy.TileCulled(m, high, 0.375f), Is.False, "noise lowers it as well as raising it");
            var e = Assert.Throws<ArgumentException>(() => TessellationPolicy.TileCulled(m, corners, 0f, float.NaN));
            StringAssert.Contains("raiseBound (NaN)", e.Message);
        }

        [Test]
        public void NoiseHeightBoundHoldsForSampledNoise()
        {
            var noise = new NoiseSettings(0.05f, 3f, 2f, 1.7f, 6);
            float bound = TessellationPolicy.NoiseHeightBound(noise);
            var rng = new Random(2);
            double worst = 0;
            for (int i = 0; i < 200000; i++)
                worst = Math.Max(worst, Math.Abs(OctaveNoise.Evaluate(rng.NextDouble() * 50, rng.NextDouble() * 50, noise, noise.octaves, out _)));
            TestContext.Out.WriteLine($"largest |noise| {worst:G4} of bound {bound:G4}");
            Assert.That(worst, Is.LessThanOrEqualTo(bound));
            Assert.That(worst, Is.GreaterThan(0.3 * bound), "the bound is not absurdly loose");
        }

        [Test]
        public void AdaptiveTriangleEstimateScalesWithOneOverTheTarget()
        {
            var s = new TessellationSettings(16, 64f, 1f, 0f);
            double t1 = TessellationPolicy.EstimateTriangleCount(s, 20000.0);
            s.targetPixels = 0.5f;
            double t05 = TessellationPolicy.EstimateTriangleCount(s, 20000.0);
            Assert.That(t1, Is.EqualTo(4 * 20000.0 / 1.0).Within(1e-9).Percent, "unclamped: 4 sagitta / target");
            Assert.That(t05 / t1, Is.EqualTo(2.0).Within(1e-9).Percent);
            Assert.That(TessellationPolicy.EstimateTriangleCount(s, double.PositiveInfinity), Is.EqualTo(2.0 * 16 * 16 * 64 * 64));
            Assert.That(TessellationPolicy.EstimateTriangleCount(s, 0.0), Is.EqualTo(2.0 * 16 * 16), "at least one segment per edge");
            Assert.That(TessellationPolicy.EstimateTriangleCount(TessellationSettings.Uniform(8, 5f), 1e9), Is.EqualTo(2.0 * 64 * 25));
            Assert.That(Assert.Throws<ArgumentException>(() => TessellationPolicy.EstimateTriangleCount(s, -1.0)).Message, Does.Contain("rangeSagittaPixels (-1)"));
        }

        [Test]
        public void SampledEdgeSagittaMatchesTheFivePointFormAndSeesFinerBumps()
        {
            var rng = new Random(11);
            for (int n = 0; n < 50; n++)
            {
                var p = new Float3[5];
                var k = new float[5];
                for (int i = 0; i < 5; i++)
                {
                    p[i] = new Float3((float)rng.NextDouble(), (float)rng.NextDouble(), (float)rng.NextDouble());
                    k[i] = (float)(1 + rng.NextDouble() * 10);
                }
                Assert.That(TessellationPolicy.EdgeSagittaPixels(p, k),
                    Is.EqualTo(TessellationPolicy.EdgeSagittaPixels(p[0], p[1], p[2], p[3], p[4], k[1], k[2], k[3])), "n = 4 is the five-point form");
                Array.Reverse(p); Array.Reverse(k);
                Assert.That(TessellationPolicy.EdgeSagittaPixels(p, k),
                    Is.EqualTo(TessellationPolicy.EdgeSagittaPixels(p[0], p[1], p[2], p[3], p[4], k[1], k[2], k[3])), "walked the other way");
            }
            // A parabola: every level gives the same sagitta k L^2 / 4, with 9 points as with 5.
            var par = new Float3[9];
            var ones = new float[9];
            for (int i = 0; i < 9; i++) { par[i] = Parabola(2f, 0.5f * i / 8f); ones[i] = 1f; }
            Assert.That(TessellationPolicy.EdgeSagittaPixels(par, ones), Is.EqualTo(2f * 0.25f / 4f).Within(1e-4).Percent);
            // A bump of width 1/8 between the five-point samples: only the nine-point form sees it.
            var bump = new Float3[9];
            for (int i = 0; i < 9; i++) bump[i] = new Float3(i / 8f, 0f, i == 3 ? 0.01f : 0f);
            Float3 B(int i) => bump[i];
            Assert.That(TessellationPolicy.EdgeSagittaPixels(B(0), B(2), B(4), B(6), B(8), 1f, 1f, 1f), Is.EqualTo(0f));
            Assert.That(TessellationPolicy.EdgeSagittaPixels(bump, ones), Is.EqualTo(16f * 0.01f).Within(1e-4).Percent);
            Assert.Throws<ArgumentException>(() => TessellationPolicy.EdgeSagittaPixels(new Float3[6], new float[6]));
            Assert.Throws<ArgumentException>(() => TessellationPolicy.EdgeSagittaPixels(par, new float[3]));
        }

        [Test]
        public void GradientNoiseCurvatureBoundsTheNoiseSecondDerivative()
        {
            // Second differences along x and y (step h, error O(h^2) of a C^2 function: quintic fade) on
            // 256 x 256 lattice cells, 8 x 8 samples each, away from lattice lines.
            const double h = 1e-3;
            double largest = 0;
            for (int cy = 0; cy < 256; cy++)
                for (int cx = 0; cx < 256; cx++)
                    for (int sy = 0; sy < 8; sy++)
                        for (int sx = 0; sx < 8; sx++)
                        {
                            double x = cx - 128 + (sx + 0.5) / 8, y = cy - 128 + (sy + 0.5) / 8;
                            double c = GradientNoise.Evaluate(x, y, out _);
                            double dxx = (GradientNoise.Evaluate(x + h, y, out _) - 2 * c + GradientNoise.Evaluate(x - h, y, out _)) / (h * h);
                            double dyy = (GradientNoise.Evaluate(x, y + h, out _) - 2 * c + GradientNoise.Evaluate(x, y - h, out _)) / (h * h);
                            largest = Math.Max(largest, Math.Max(Math.Abs(dxx), Math.Abs(dyy)));
                        }
            TestContext.Out.WriteLine($"largest |d2 noise / dx2| on the grid: {largest:G4} (bound {TessellationPolicy.GradientNoiseCurvature})");
            Assert.That(largest, Is.LessThanOrEqualTo(TessellationPolicy.GradientNoiseCurvature));
            Assert.That(largest, Is.GreaterThan(0.5 * TessellationPolicy.GradientNoiseCurvature), "the bound is not loose by more than 2x");
        }

        [Test]
        public void GradientNoiseSlopeBoundsTheNoiseGradient()
        {
            // The analytic gradient on 256 x 256 lattice cells, 16 x 16 samples each (cell corners included).
            double largest = 0;
            for (int cy = 0; cy < 256; cy++)
                for (int cx = 0; cx < 256; cx++)
                    for (int sy = 0; sy <= 16; sy++)
                        for (int sx = 0; sx <= 16; sx++)
                        {
                            GradientNoise.Evaluate(cx - 128 + sx / 16.0, cy - 128 + sy / 16.0, out Double2 g);
                            largest = Math.Max(largest, Math.Sqrt(g.x * g.x + g.y * g.y));
                        }
            TestContext.Out.WriteLine($"largest |grad noise| on the grid: {largest:G4} (bound {TessellationPolicy.GradientNoiseSlope})");
            Assert.That(largest, Is.LessThanOrEqualTo(TessellationPolicy.GradientNoiseSlope));
            Assert.That(largest, Is.GreaterThan(0.8 * TessellationPolicy.GradientNoiseSlope), "the bound is not loose by more than 1.25x");
        }

        [Test]
        public void NoiseDifferenceBoundHoldsAroundTheOrigin()
        {
            // |p(q) - p(O)| at the settings' octaves (and at fewer: every term only shrinks) for q at
            // distance d from O, random O and directions; near O the slope term, far away 2 * amplitude.
            var noise = NoiseSettings.Default;
            var rng = new Random(5);
            double worst = 0;
            foreach (double d in new[] { 1e-4, 1e-3, 0.01, 0.1, 1.0 })
            {
                float bound = TessellationPolicy.NoiseDifferenceBound(noise, noise.octaves, (float)d);
                for (int n = 0; n < 20000; n++)
                {
                    double ox = rng.NextDouble(), oy = rng.NextDouble(), t = rng.NextDouble() * 2 * Math.PI, r = d * Math.Sqrt(rng.NextDouble());
                    double octaves = noise.octaves - (n % 3) * 0.5;
                    double diff = Math.Abs(OctaveNoise.Evaluate(ox + r * Math.Cos(t), oy + r * Math.Sin(t), noise, octaves, out _) - OctaveNoise.Evaluate(ox, oy, noise, octaves, out _));
                    Assert.That(diff, Is.LessThanOrEqualTo(bound), $"d {d} at ({ox}, {oy})");
                    worst = Math.Max(worst, diff / bound);
                }
            }
            TestContext.Out.WriteLine($"largest |p(q) - p(O)| / bound: {worst:G3}");
            Assert.That(TessellationPolicy.NoiseDifferenceBound(noise, noise.octaves, 0f), Is.EqualTo(0f));
            Assert.That(TessellationPolicy.NoiseDifferenceBound(noise, noise.octaves, 1e9f), Is.EqualTo(2f * TessellationPolicy.NoiseHeightBound(noise)).Within(1e-5).Percent, "far: twice the height bound");
            Assert.That(Assert.Throws<ArgumentException>(() => TessellationPolicy.NoiseDifferenceBound(noise, noise.octaves, float.NaN)).Message, Does.Contain("distance (NaN)"));
        }

        [Test]
        public void NoiseSagittaBoundsTheChordErrorOfOctaveNoise()
        {
            var noise = NoiseSettings.Default;
            float curvature = TessellationPolicy.NoiseCurvatureBound(noise, 3.5f);
            // One octave: amplitude * C * f^2; 3.5 octaves: f^2 (1 + alpha^2/beta + (alpha^2/beta)^2 + 0.5 (alpha^2/beta)^3).
            float one = TessellationPolicy.NoiseCurvatureBound(noise, 1f);
            Assert.That(one, Is.EqualTo(noise.amplitude * TessellationPolicy.GradientNoiseCurvature * noise.frequency * noise.frequency).Within(1e-5).Percent);
            Assert.That(curvature, Is.EqualTo(one * (1 + 2 + 4 + 0.5 * 8)).Within(1e-5).Percent);
            Assert.That(TessellationPolicy.NoiseCurvatureBound(noise, 0f), Is.EqualTo(0f));
            // Chords of length L along x anywhere: the middle's deviation never exceeds the bound.
            var rng = new Random(3);
            double worst = 0;
            foreach (double length in new[] { 0.002, 0.01, 0.05 })
            {
                float bound = TessellationPolicy.NoiseSagittaPixels(curvature, (float)length, 1f);
                for (int n = 0; n < 20000; n++)
                {
                    double x = rng.NextDouble(), y = rng.NextDouble();
                    double a = OctaveNoise.Evaluate(x, y, noise, 3.5, out _), b = OctaveNoise.Evaluate(x + length, y, noise, 3.5, out _);
                    double m = OctaveNoise.Evaluate(x + 0.5 * length, y, noise, 3.5, out _);
                    double dev = Math.Abs(m - 0.5 * (a + b));
                    Assert.That(dev, Is.LessThanOrEqualTo(bound), $"L {length} at ({x}, {y})");
                    worst = Math.Max(worst, dev / bound);
                }
            }
            TestContext.Out.WriteLine($"largest noise chord deviation / bound: {worst:G3}");
            Assert.Throws<ArgumentException>(() => TessellationPolicy.NoiseCurvatureBound(noise, float.NaN));
        }
    }
}
