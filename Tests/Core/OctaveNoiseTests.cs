using System;
using NUnit.Framework;

namespace GregoryTerrain.Tests
{
    [TestFixture]
    public class OctaveNoiseTests
    {
        static readonly NoiseSettings Settings = new NoiseSettings(0.02f, 8f, 2f, 2f, 12);

        [Test]
        public void SettingsValidationNamesFieldAndValue()
        {
            Assert.DoesNotThrow(() => Settings.Validate());
            var bad = Settings; bad.alpha = 1f;
            Assert.That(Assert.Throws<ArgumentException>(() => bad.Validate()).Message, Does.Contain("noise.alpha (1)"));
            bad = Settings; bad.beta = 0f;
            Assert.That(Assert.Throws<ArgumentException>(() => bad.Validate()).Message, Does.Contain("noise.beta (0)"));
            bad = Settings; bad.octaves = 17;
            Assert.That(Assert.Throws<ArgumentException>(() => bad.Validate()).Message, Does.Contain("noise.octaves (17)"));
            bad = Settings; bad.octaves = -1;
            Assert.Throws<ArgumentException>(() => bad.Validate());
            bad = Settings; bad.amplitude = float.NaN;
            Assert.That(Assert.Throws<ArgumentException>(() => bad.Validate()).Message, Does.Contain("noise.amplitude (NaN)"));
            bad = Settings; bad.frequency = -1f;
            Assert.Throws<ArgumentException>(() => bad.Validate());
            bad = Settings; bad.octaves = 16; bad.alpha = 4f;   // 8 * 4^15 is far beyond 2^24
            Assert.Throws<ArgumentException>(() => bad.Validate());
            bad = Settings; bad.octaves = 0;
            Assert.DoesNotThrow(() => bad.Validate());
        }

        [Test]
        public void OctaveCountGrowsAsRangeNarrowsAndIsClamped()
        {
            double previous = -1;
            for (int k = 0; k <= 24; k++)
            {
                double width = Math.Pow(2, -k);
                double count = OctaveNoise.OctaveCount(width, 256, Settings);
                Assert.That(count, Is.GreaterThanOrEqualTo(previous));
                Assert.That(count, Is.InRange(0.0, Settings.octaves));
                // Every octave counted in full has a wavelength of at least two vertex spacings.
                for (int o = 0; o < (int)Math.Floor(count); o++)
                    Assert.That(1.0 / (Settings.frequency * Math.Pow(Settings.alpha, o)), Is.GreaterThanOrEqualTo(2 * width / 256 * (1 - 1e-12)));
                // ... and the first octave not counted at all is finer than that.
                int next = (int)Math.Ceiling(count);
                if (count < Settings.octaves && next < Settings.octaves)
                    Assert.That(1.0 / (Settings.frequency * Math.Pow(Settings.alpha, next)), Is.LessThan(2 * width / 256));
                previous = count;
            }
            Assert.That(OctaveNoise.OctaveCount(1.0, 256, Settings), Is.EqualTo(5.0).Within(1e-12), "1 + log2(256 / 16)");
            Assert.That(OctaveNoise.OctaveCount(1e-9, 256, Settings), Is.EqualTo((double)Settings.octaves));
            Assert.That(OctaveNoise.OctaveCount(1.0, 1, Settings), Is.EqualTo(0.0), "one vertex cannot show even octave 0");
            Assert.Throws<ArgumentException>(() => OctaveNoise.OctaveCount(0.0, 256, Settings));
            Assert.Throws<ArgumentException>(() => OctaveNoise.OctaveCount(1.0, double.NaN, Settings));
        }

        [Test]
        public void FadingAnOctaveInIsContinuous()
        {
            var rng = new Random(11);
            for (int i = 0; i < 200; i++)
            {
                double x = rng.NextDouble(), y = rng.NextDouble();
                for (int n = 1; n < Settings.octaves; n++)
                {
                    double below = OctaveNoise.Evaluate(x, y, Settings, n - 1e-6, out _);
                    double at = OctaveNoise.Evaluate(x, y, Settings, n, out _);
                    double above = OctaveNoise.Evaluate(x, y, Settings, n + 1e-6, out _);
                    Assert.That(Math.Abs(above - at), Is.LessThan(1e-6 * Settings.amplitude * 2));
                    Assert.That(Math.Abs(below - at), Is.LessThan(1e-6 * Settings.amplitude * 2));
                }
                // Half an octave is half its contribution.
                double two = OctaveNoise.Evaluate(x, y, Settings, 2, out _), three = OctaveNoise.Evaluate(x, y, Settings, 3, out _);
                Assert.That(OctaveNoise.Evaluate(x, y, Settings, 2.5, out _), Is.EqualTo(0.5 * (two + three)).Within(1e-15));
                Assert.That(OctaveNoise.Evaluate(x, y, Settings, 0, out Double2 g0), Is.EqualTo(0.0));
                Assert.That(g0.x == 0.0 && g0.y == 0.0, Is.True);
            }
        }

        [Test]
        public void FirstOctaveIsTheGradientNoiseAtFrequencyAndOffset()
        {
            double x = 0.3, y = 0.77;
            Double2 off = GradientNoise.StreamOffset(0);
            double expected = Settings.amplitude * GradientNoise.Evaluate(8.0 * x + off.x, 8.0 * y + off.y, out _);
            Assert.That(OctaveNoise.Evaluate(x, y, Settings, 1, out _), Is.EqualTo(expected).Within(1e-15));
            // Second octave: frequency * alpha, weight 1 / beta, its own offset.
            Double2 off1 = GradientNoise.StreamOffset(1);
            double second = Settings.amplitude / 2.0 * GradientNoise.Evaluate(16.0 * x + off1.x, 16.0 * y + off1.y, out _);
            Assert.That(OctaveNoise.Evaluate(x, y, Settings, 2, out _), Is.EqualTo(expected + second).Within(1e-15));
            Assert.That(off1, Is.Not.EqualTo(off));
        }

        [Test]
        public void GradientMatchesFiniteDifferencesAndFloatMatchesDouble()
        {
            var rng = new Random(12);
            const double h = 1e-8;
            double maxDiff = 0;
            for (int i = 0; i < 500; i++)
            {
                double x = rng.NextDouble(), y = rng.NextDouble();
                double count = rng.NextDouble() * Settings.octaves;
                double n = OctaveNoise.Evaluate(x, y, Settings, count, out Double2 g);
                double gx = (OctaveNoise.Evaluate(x + h, y, Settings, count, out _) - OctaveNoise.Evaluate(x - h, y, Settings, count, out _)) / (2 * h);
                double gy = (OctaveNoise.Evaluate(x, y + h, Settings, count, out _) - OctaveNoise.Evaluate(x, y - h, Settings, count, out _)) / (2 * h);
                Assert.That(g.x, Is.EqualTo(gx).Within(1e-4 * (1 + Math.Abs(gx))));
                Assert.That(g.y, Is.EqualTo(gy).Within(1e-4 * (1 + Math.Abs(gy))));
                var q = new Float2((float)x, (float)y);
                float nf = OctaveNoise.Evaluate(TerrainPoint.FromFloat(q), Settings, (float)count, out Float2 gf);
                double nr = OctaveNoise.Evaluate(q.x, q.y, Settings, (float)count, out Double2 gr);
                maxDiff = Math.Max(maxDiff, Math.Abs(nf - nr));
                Assert.That(gf.x, Is.EqualTo(gr.x).Within(1e-3 * (1 + Math.Abs(gr.x))));
            }
            TestContext.Out.WriteLine($"octave noise (amplitude {Settings.amplitude}): max |float - double| = {maxDiff:E3}");
            Assert.That(maxDiff, Is.LessThan(1e-5 * Settings.amplitude * 10));
        }

        [Test]
        public void DeepZoomNoiseThroughTerrainPointMatchesDouble()
        {
            var settings = new NoiseSettings(0.02f, 8f, 2f, 1.25f, 16);
            const double width = 1e-6;
            var range = new TerrainRange(0.7, 0.3, 0.7 + width, 0.3 + width);
            RangeMapping.EncodeRange(range, RangeOrigin.For(range), out Float4 rangeF, out Float4 originF);
            RangeMapping.EncodeRange(range, RangeOrigin.zero, out Float4 plainF, out _);
            double maxOrigin = 0, maxPlain = 0, spread = 0;
            double first = double.NaN;
            for (int k = 0; k <= 64; k++)
            {
                float s = k / 64f;
                Double2 q = RangeMapping.GlobalPoint(range, 1, 0, 0, s, s);
                double reference = OctaveNoise.Evaluate(q.x, q.y, settings, settings.octaves, out _);
                TerrainPoint p = RangeMapping.ToTerrainPoint(rangeF, originF, 1, 0, 0, s, s);
                TerrainPoint plain = TerrainPoint.FromFloat(RangeMapping.PlainGlobalPoint(plainF, 1, 0, 0, s, s));
                maxOrigin = Math.Max(maxOrigin, Math.Abs(OctaveNoise.Evaluate(p, settings, settings.octaves, out _) - reference));
                maxPlain = Math.Max(maxPlain, Math.Abs(OctaveNoise.Evaluate(plain, settings, settings.octaves, out _) - reference));
                if (k == 0) first = reference; else spread = Math.Max(spread, Math.Abs(reference - first));
            }
            TestContext.Out.WriteLine($"deep zoom (width 1e-6, 16 octaves, beta 1.25): noise varies by {spread:E3} across the view; " +
                $"max error TerrainPoint path {maxOrigin:E3}, plain float q {maxPlain:E3}");
            Assert.That(maxOrigin, Is.LessThan(spread * 1e-3), "the error must be invisible against the detail shown");
            Assert.That(maxPlain, Is.GreaterThan(maxOrigin * 10), "plain float q must be visibly worse");
        }
    }
}
