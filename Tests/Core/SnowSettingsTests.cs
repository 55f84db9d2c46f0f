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
            float[] p = s.PackParams(0.25f);
            Assert.That(p.Length, Is.EqualTo(4 * SnowSettings.ParamsFloat4Count));
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
            Assert.Throws<ArgumentException>(() => SnowSettings.Default.PackParams(-1f));
        }

        [Test]
        public void PackingIntoAnArrayGivesTheSameParamsAndAllocatesNothing()
        {
            var s = SnowSettings.Default;
            s.wind = new Float2(0.3f, -1.2f);
            float[] expected = s.PackParams(0.25f);
            var into = new float[SnowSettings.ParamsFloat4Count * 4];
            s.PackParams(0.25f, into);   // warm up (JIT)
            long before = System.GC.GetAllocatedBytesForCurrentThread();
            s.PackParams(0.25f, into);
            long allocated = System.GC.GetAllocatedBytesForCurrentThread() - before;
            Assert.That(into, Is.EqualTo(expected));
            Assert.That(allocated, Is.EqualTo(0), "bytes allocated by one step's packing");
            Assert.Throws<System.ArgumentException>(() => s.PackParams(0.25f, new float[19]));
        }
}
}
