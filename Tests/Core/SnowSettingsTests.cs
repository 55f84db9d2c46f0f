using System;
using NUnit.Framework;

namespace GregoryTerrain.Tests
{
    [TestFixture]
    public class SnowSettingsTests
    {
        [Test]
        public void DefaultIsValidAndGnIsOppositeToGravity()
        {
            var s = SnowSettings.Default;
            s.Validate();
            Assert.That(s.Up, Is.EqualTo(new Float3(0f, 0f, 1f)));
            s.gravity = new Float3(0f, 0f, -9.81f);
            Assert.That(s.Up, Is.EqualTo(new Float3(0f, 0f, 1f)), "only the direction of gravity counts");
        }

        [Test]
        public void FallLineAndParameterPacking()
        {
            var s = SnowSettings.Default;
            s.resolution = 256; s.wind = new Float2(2f, 0f); s.fallSpeed = 1f; s.scale = 0.003f;
            s.rayLength = 0.5f; s.raySteps = 16; s.edgeStrength = 0.7f; s.edgeWidth = 0.4f; s.exposureSoftness = 0.2f;
            s.depthCap = 0.03f; s.meltRate = 0.0001f;
            float[] p = s.Params(0.25f).Pack();
            Assert.That(p.Length, Is.EqualTo(4 * SnowParams.Float4Count));
            // Snow moves along +x and down at 1:2; it comes from -x, rising at atan(1/2).
            float[] expected =
            {
                256f, 1f / 256f, 0.5f, 16f,
                -1f, 0f, (float)(2 / Math.Sqrt(5)), (float)(1 / Math.Sqrt(5)),
                0f, 0f, 1f, 0.003f,
                0.7f, 0.4f, 0.2f, 0f,
                0.25f, 0.03f, 0.0001f, 0f,
            };
            for (int k = 0; k < expected.Length; k++) Assert.That(p[k], Is.EqualTo(expected[k]).Within(1e-7f), "float " + k);
        }

        [TestCase("resolution", 100)]
        [TestCase("resolution", 32)]
        [TestCase("resolution", 8192)]
        [TestCase("scale", -1)]
        [TestCase("fallSpeed", 0)]
        [TestCase("edgeStrength", -0.5)]
        [TestCase("edgeWidth", 0)]
        [TestCase("depthCap", 0)]
        [TestCase("meltRate", -1)]
        [TestCase("rayLength", 3)]
        [TestCase("raySteps", 0)]
        [TestCase("raySteps", 257)]
        [TestCase("exposureSoftness", 0)]
        public void ValidationNamesTheFieldAndTheValue(string field, double value)
        {
            var s = SnowSettings.Default;
            switch (field)
            {
                case "resolution": s.resolution = (int)value; break;
                case "scale": s.scale = (float)value; break;
                case "fallSpeed": s.fallSpeed = (float)value; break;
                case "edgeStrength": s.edgeStrength = (float)value; break;
                case "edgeWidth": s.edgeWidth = (float)value; break;
                case "depthCap": s.depthCap = (float)value; break;
                case "meltRate": s.meltRate = (float)value; break;
                case "rayLength": s.rayLength = (float)value; break;
                case "raySteps": s.raySteps = (int)value; break;
                case "exposureSoftness": s.exposureSoftness = (float)value; break;
            }
            var e = Assert.Throws<ArgumentException>(() => s.Validate());
            Assert.That(e.Message, Does.Contain(FormattableString.Invariant($"snow.{field} ({value})")));
        }

        [Test]
        public void GravityMustPointDownAndEverythingMustBeFinite()
        {
            var s = SnowSettings.Default;
            s.gravity = new Float3(0f, 0f, 1f);
            Assert.That(Assert.Throws<ArgumentException>(() => s.Validate()).Message, Does.Contain("snow.gravity"));
            s = SnowSettings.Default; s.wind = new Float2(float.NaN, 0f);
            Assert.That(Assert.Throws<ArgumentException>(() => s.Validate()).Message, Does.Contain("snow.wind"));
            s = SnowSettings.Default; s.scale = float.PositiveInfinity;
            Assert.That(Assert.Throws<ArgumentException>(() => s.Validate()).Message, Does.Contain("snow.scale"));
            Assert.Throws<ArgumentException>(() => SnowSettings.Default.Params(-1f).Pack());
        }

        [Test]
        public void TheParamsOfAStepAllocateNothing()
        {
            var s = SnowSettings.Default;
            s.wind = new Float2(0.3f, -1.2f);
            SnowParams p = s.Params(0.25f);   // warm up (JIT)
            // The fewest bytes of three calls: a per-step allocation shows in every call, the
            // runtime's own one-off work (tiered JIT) in one.
            long allocated = long.MaxValue;
            for (int i = 0; i < 3; i++)
            {
                long before = System.GC.GetAllocatedBytesForCurrentThread();
                p = s.Params(0.25f);
                allocated = System.Math.Min(allocated, System.GC.GetAllocatedBytesForCurrentThread() - before);
            }
            Assert.That(allocated, Is.EqualTo(0), "bytes allocated by one step's constants");
            Assert.That(p.snowStep, Is.EqualTo(new Float4(0.25f, s.depthCap, s.meltRate, 0f)));
            Assert.That(p.Pack(), Has.Length.EqualTo(4 * SnowParams.Float4Count));
        }
}
}
