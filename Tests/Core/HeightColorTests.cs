using System;
using NUnit.Framework;

namespace GregoryTerrain.Tests
{
    [TestFixture]
    public class HeightColorTests
    {
        static readonly Float3 Low = new Float3(0.1f, 0.4f, 0.05f), High = new Float3(0.9f, 0.9f, 0.95f);

        [Test]
        public void EndpointsAndMidpoint()
        {
            Assert.That(HeightColor.Blend(0f, 0f, 0.5f, Low, High), Is.EqualTo(Low));
            Assert.That(HeightColor.Blend(0f, 0.5f, 0.5f, Low, High), Is.EqualTo(High));
            Assert.That(HeightColor.Weight(0.25f, 0.125f, 0.5f), Is.EqualTo(0.5f));
            Float3 mid = HeightColor.Blend(0.5f, 0f, 0.5f, Low, High);
            Assert.That(mid.x, Is.EqualTo(0.5f * (Low.x + High.x)).Within(1e-6f));
            Assert.That(mid.z, Is.EqualTo(0.5f * (Low.z + High.z)).Within(1e-6f));
        }

        [Test]
        public void SaturatesOutsideTheBlendBand()
        {
            Assert.That(HeightColor.Blend(0f, 100f, 0.5f, Low, High), Is.EqualTo(High));
            Assert.That(HeightColor.Blend(0f, -100f, 0.5f, Low, High), Is.EqualTo(Low));
            Assert.That(HeightColor.Weight(2f, 0f, 1f), Is.EqualTo(1f));
            Assert.That(HeightColor.Weight(-2f, 0f, 1f), Is.EqualTo(0f));
            // A negative gamma flips the direction: low ground gets the high colour.
            Assert.That(HeightColor.Weight(0f, -1f, -0.5f), Is.EqualTo(1f));
        }

        [Test]
        public void GammaValidation()
        {
            Assert.That(Assert.Throws<ArgumentException>(() => HeightColor.Weight(0f, 0f, 0f)).Message, Does.Contain("gamma (0)"));
            Assert.Throws<ArgumentException>(() => HeightColor.Weight(0f, 0f, float.NaN));
            Assert.Throws<ArgumentException>(() => new HeightColorSettings(float.PositiveInfinity, 0.1f, 4f).Validate());
            Assert.Throws<ArgumentException>(() => new HeightColorSettings(1f, 0.1f, 0f).Validate());
            Assert.That(new HeightColorSettings(1f, 0.1f, 4f).ToFloat4(), Is.EqualTo(new Float4(1f, 0.1f, 4f, 0f)));
        }

        [Test]
        public void ColorNoiseIsScaledOneOctaveOnItsOwnStream()
        {
            var settings = new HeightColorSettings(0.3f, 0.25f, 5f);
            var rng = new Random(21);
            double maxAbs = 0, maxDiff = 0;
            bool differsFromOctave0 = false;
            for (int i = 0; i < 2000; i++)
            {
                var q = new Float2((float)rng.NextDouble(), (float)rng.NextDouble());
                float l = HeightColor.ColorNoise(TerrainPoint.FromFloat(q), settings);
                double lr = HeightColor.ColorNoise(q.x, q.y, settings);
                maxDiff = Math.Max(maxDiff, Math.Abs(l - lr));
                maxAbs = Math.Max(maxAbs, Math.Abs(lr));
                Double2 off0 = GradientNoise.StreamOffset(0);
                double octave0 = settings.noiseAmplitude * GradientNoise.Evaluate(5.0 * q.x + off0.x, 5.0 * q.y + off0.y, out _);
                if (Math.Abs(octave0 - lr) > 1e-3) differsFromOctave0 = true;
            }
            Assert.That(maxDiff, Is.LessThan(1e-6));
            Assert.That(maxAbs, Is.LessThanOrEqualTo(settings.noiseAmplitude * (1 + 1e-6)));
            Assert.That(maxAbs, Is.GreaterThan(settings.noiseAmplitude * 0.3));
            Assert.That(differsFromOctave0, Is.True, "colour noise must not repeat the height noise");
        }

        [Test]
        public void ColorNoiseAtLocalIsColorNoiseWithoutAHiPartBitForBit()
        {
            // What the tessellated stages draw without the range origin's code must not change a bit.
            var rng = new Random(22);
            for (int i = 0; i < 5000; i++)
            {
                var settings = new HeightColorSettings(0.3f, 0.25f, (float)Math.Pow(2, rng.NextDouble() * 16 - 2));
                var local = new Float2((float)(rng.NextDouble() * 1.5 - 0.25), (float)(rng.NextDouble() * 1.5 - 0.25));
                float a = HeightColor.ColorNoiseAtLocal(local, settings);
                float b = HeightColor.ColorNoise(new TerrainPoint(new Float2(0f, 0f), local), settings);
                Assert.That(BitConverter.SingleToInt32Bits(a), Is.EqualTo(BitConverter.SingleToInt32Bits(b)), $"at {local} f {settings.noiseFrequency:R}");
            }
        }
    }
}
