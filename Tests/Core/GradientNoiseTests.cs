using System;
using NUnit.Framework;

namespace GregoryTerrain.Tests
{
    [TestFixture]
    public class GradientNoiseTests
    {
        [Test]
        public void AtLocalIsAtPointWithoutAHiPartBitForBit()
        {
            // The shaders' shortcut for points without a range origin must not change a single bit.
            var rng = new Random(11);
            for (int k = 0; k < 20000; k++)
            {
                var local = new Float2((float)(rng.NextDouble() * 2 - 0.5), (float)(rng.NextDouble() * 2 - 0.5));
                if (k % 7 == 0) local = new Float2(k % 14 == 0 ? 0f : -0f, (float)rng.NextDouble());
                float frequency = (float)Math.Pow(2, rng.NextDouble() * 20 - 2);
                Float2 offset = GradientNoise.StreamOffset((uint)(k % 17));
                float a = GradientNoise.AtLocal(local, frequency, offset, out Float2 ga);
                float b = GradientNoise.AtPoint(new TerrainPoint(k % 3 == 0 ? new Float2(-0f, -0f) : new Float2(0f, 0f), local), frequency, offset, out Float2 gb);
                Assert.That(BitConverter.SingleToInt32Bits(a), Is.EqualTo(BitConverter.SingleToInt32Bits(b)), $"value at {local} f {frequency:R}");
                Assert.That(BitConverter.SingleToInt32Bits(ga.x), Is.EqualTo(BitConverter.SingleToInt32Bits(gb.x)), $"d/dx at {local} f {frequency:R}");
                Assert.That(BitConverter.SingleToInt32Bits(ga.y), Is.EqualTo(BitConverter.SingleToInt32Bits(gb.y)), $"d/dy at {local} f {frequency:R}");
            }
        }

        [Test]
        public void ZeroOnLatticePointsFloatAndDouble()
        {
            var rng = new Random(1);
            for (int i = 0; i < 20000; i++)
            {
                int x = rng.Next(-100000, 100000), y = rng.Next(-100000, 100000);
                Assert.That(GradientNoise.Evaluate((float)x, (float)y, out _), Is.EqualTo(0f));
                Assert.That(GradientNoise.Evaluate((double)x, (double)y, out _), Is.EqualTo(0.0));
            }
        }

        [Test]
        public void BoundedByOne()
        {
            // Bound: the noise is a convex blend (fade weights >= 0, summing to 1) of the four corner
            // ramps g . (x - corner), each at most |x - corner| <= sqrt(2) in magnitude, so
            // |n| <= sqrt(2) * Scale = 2 is proven; the known sharper bound for unit gradients,
            // sqrt(2)/2 * Scale = 1, is what we measure.
            var rng = new Random(2);
            double maxAbs = 0;
            for (int i = 0; i < 1000000; i++)
            {
                float x = (float)(rng.NextDouble() * 2000 - 1000), y = (float)(rng.NextDouble() * 2000 - 1000);
                maxAbs = Math.Max(maxAbs, Math.Abs(GradientNoise.Evaluate(x, y, out _)));
            }
            TestContext.Out.WriteLine($"max |noise| over 1e6 samples = {maxAbs:F6}");
            Assert.That(maxAbs, Is.LessThanOrEqualTo(1.0 + 1e-6));
            Assert.That(maxAbs, Is.GreaterThan(0.8), "the scale must use most of [-1, 1]");
        }

        [Test]
        public void CellCentreWithAllGradientsInwardReachesOne()
        {
            // Search lattice cells for one whose four gradients are the inward diagonals: the maximum.
            for (int x = 0; x < 200000; x++)
            {
                bool inward = GradientNoise.Gradient(GradientNoise.Hash(x, 0)).Equals(GradientNoise.Gradient(1u))
                    && GradientNoise.Gradient(GradientNoise.Hash(x + 1, 0)).Equals(GradientNoise.Gradient(3u))
                    && GradientNoise.Gradient(GradientNoise.Hash(x, 1)).Equals(GradientNoise.Gradient(7u))
                    && GradientNoise.Gradient(GradientNoise.Hash(x + 1, 1)).Equals(GradientNoise.Gradient(5u));
                if (!inward) continue;
                double n = GradientNoise.Evaluate(x + 0.5, 0.5, out _);
                TestContext.Out.WriteLine($"cell ({x}, 0) has all gradients inward; noise at its centre = {n:R}");
                Assert.That(n, Is.EqualTo(1.0).Within(1e-6));
                return;
            }
            Assert.Fail("no cell with four inward gradients among 200000 (expected about 800)");
        }

        [Test]
        public void GradientMatchesFiniteDifferences()
        {
            var rng = new Random(3);
            const double h = 1e-6;
            for (int i = 0; i < 2000; i++)
            {
                double x = rng.NextDouble() * 200 - 100, y = rng.NextDouble() * 200 - 100;
                GradientNoise.Evaluate(x, y, out Double2 g);
                double gx = (GradientNoise.Evaluate(x + h, y, out _) - GradientNoise.Evaluate(x - h, y, out _)) / (2 * h);
                double gy = (GradientNoise.Evaluate(x, y + h, out _) - GradientNoise.Evaluate(x, y - h, out _)) / (2 * h);
                Assert.That(g.x, Is.EqualTo(gx).Within(1e-6));
                Assert.That(g.y, Is.EqualTo(gy).Within(1e-6));
                GradientNoise.Evaluate((float)x, (float)y, out Float2 gf);
                Assert.That(gf.x, Is.EqualTo(gx).Within(2e-3));
                Assert.That(gf.y, Is.EqualTo(gy).Within(2e-3));
            }
        }

        [Test]
        public void ContinuousWithLipschitzBoundFromGradient()
        {
            // |n(a) - n(b)| <= max|grad n| * |a - b|; measure max|grad| and check small steps respect it,
            // including steps that cross cell boundaries (where a table bug or a fade bug would jump).
            var rng = new Random(4);
            double maxGrad = 0;
            for (int i = 0; i < 200000; i++)
            {
                GradientNoise.Evaluate(rng.NextDouble() * 100, rng.NextDouble() * 100, out Double2 g);
                maxGrad = Math.Max(maxGrad, GMath.length(g));
            }
            double lipschitz = maxGrad * 1.05;
            TestContext.Out.WriteLine($"max |gradient| over 2e5 samples = {maxGrad:F4}");
            const double step = 1e-4;
            for (int i = 0; i < 100000; i++)
            {
                double x = Math.Round(rng.NextDouble() * 100) - step * rng.NextDouble(), y = rng.NextDouble() * 100;
                double a = GradientNoise.Evaluate(x, y, out _), b = GradientNoise.Evaluate(x + step, y + step, out _);
                Assert.That(Math.Abs(a - b), Is.LessThanOrEqualTo(lipschitz * step * Math.Sqrt(2)));
            }
            Assert.That(maxGrad, Is.LessThan(10.0));
        }

        [Test]
        public void FloatAgreesWithDoubleAndIsDeterministic()
        {
            var rng = new Random(5);
            double maxDiff = 0;
            for (int i = 0; i < 100000; i++)
            {
                float x = (float)(rng.NextDouble() * 512 - 256), y = (float)(rng.NextDouble() * 512 - 256);
                float nf = GradientNoise.Evaluate(x, y, out Float2 gf);
                double nd = GradientNoise.Evaluate((double)x, (double)y, out Double2 gd);
                maxDiff = Math.Max(maxDiff, Math.Abs(nf - nd));
                Assert.That(GradientNoise.Evaluate(x, y, out Float2 gf2), Is.EqualTo(nf));
                Assert.That(gf2, Is.EqualTo(gf));
            }
            TestContext.Out.WriteLine($"max |float - double| noise over 1e5 samples in [-256, 256]^2 = {maxDiff:E3}");
            Assert.That(maxDiff, Is.LessThan(1e-5));
        }

        [Test]
        public void HashSpreadsGradientsEvenly()
        {
            var counts = new int[8];
            for (int y = -100; y < 100; y++)
            for (int x = -100; x < 100; x++)
                counts[GradientNoise.Hash(x, y) & 7u]++;
            foreach (int c in counts) Assert.That(c, Is.InRange(40000 / 8 * 0.9, 40000 / 8 * 1.1));
        }

        [Test]
        public void NegativeAndLargeCoordinatesAreFinite()
        {
            foreach (float x in new[] { -0.5f, -1f, -1e3f + 0.25f, 1e6f, -1e6f, 1e6f + 0.3f, 8e6f })
            {
                float n = GradientNoise.Evaluate(x, x * 0.7f, out Float2 g);
                Assert.That(GMath.isfinite(n) && g.IsFinite, Is.True, $"x = {x}");
                Assert.That(Math.Abs(n), Is.LessThanOrEqualTo(1f + 1e-5f));
            }
            // Negative side is continuous across 0 (floor, not truncation).
            double a = GradientNoise.Evaluate(-1e-9, 0.3, out _), b = GradientNoise.Evaluate(1e-9, 0.3, out _);
            Assert.That(Math.Abs(a - b), Is.LessThan(1e-7));
        }

        [Test]
        public void TwoProductIsExact()
        {
            var rng = new Random(6);
            for (int i = 0; i < 10000; i++)
            {
                float a = (float)rng.NextDouble(), b = (float)(rng.NextDouble() * 1e5);
                float p = GradientNoise.TwoProduct(a, b, out float e);
                Assert.That((double)p + e, Is.EqualTo((double)a * b));
            }
        }

        [Test]
        public void AtPointWithOriginZeroMatchesPlainEvaluate()
        {
            var rng = new Random(8);
            for (int i = 0; i < 10000; i++)
            {
                var q = new Float2((float)rng.NextDouble(), (float)rng.NextDouble());
                float f = 37f;
                var off = GradientNoise.StreamOffset(3);
                float a = GradientNoise.AtPoint(TerrainPoint.FromFloat(q), f, off, out _);
                double r = GradientNoise.Evaluate((double)f * q.x + off.x, (double)f * q.y + off.y, out _);
                Assert.That(a, Is.EqualTo(r).Within(2e-5));
            }
        }
    }
}
