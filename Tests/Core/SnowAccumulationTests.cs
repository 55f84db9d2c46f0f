using System;
using NUnit.Framework;

namespace GregoryTerrain.Tests
{
    [TestFixture]
    public class SnowAccumulationTests
    {
        static readonly Float3 Up = new Float3(0f, 0f, 1f);

        [Test]
        public void CatchIsOneFacingUpZeroOnSmoothVerticalFacesAndOverhangs()
        {
            Assert.That(SnowAccumulation.Catch(Up, Up), Is.EqualTo(1f));
            Assert.That(SnowAccumulation.Catch(new Float3(1f, 0f, 0f), Up), Is.EqualTo(0f), "smooth wall: the paper's problem");
            Assert.That(SnowAccumulation.Catch(new Float3(0f, 0.6f, -0.8f), Up), Is.EqualTo(0f), "overhang: no negative rate");
            // The paper's fix: a detail normal on the wall tilts up and the wall catches some snow.
            var detail = GMath.normalize(new Float3(-1f, 0f, 0.5f));
            Assert.That(SnowAccumulation.Catch(detail, Up), Is.EqualTo(0.5 / Math.Sqrt(1.25)).Within(1e-6));
        }

        [Test]
        public void CrestMeasuresTheSlopeChangeIndependentlyOfResolution()
        {
            // h = -s |x| (a ridge of slope s each side) sampled at the crest, neighbours one cell away.
            const float s = 0.75f;
            foreach (int r in new[] { 64, 512, 4096 })
            {
                float cell = 1f / r;
                float c = SnowAccumulation.Crest(0f, -s * cell, -s * cell, 0f, 0f, r);
                Assert.That(c, Is.EqualTo(2f * s).Within(1e-5f), "R " + r);
            }
            // A plane has no crest, a valley a negative one; the edge term ignores valleys.
            Assert.That(SnowAccumulation.Crest(0.5f, 0.4f, 0.6f, 0.45f, 0.55f, 256f), Is.EqualTo(0f).Within(1e-4f));
            float valley = SnowAccumulation.Crest(0f, 0.01f, 0.01f, 0f, 0f, 256f);
            Assert.That(valley, Is.LessThan(0f));
            Assert.That(SnowAccumulation.EdgeTerm(valley, 1f, 0.5f), Is.EqualTo(0f));
            Assert.That(SnowAccumulation.EdgeTerm(10f, 0.8f, 0.5f), Is.EqualTo(0.8f));
            Assert.That(SnowAccumulation.EdgeTerm(0.25f, 1f, 0.5f), Is.EqualTo(0.5f).Within(1e-6f));
        }

        [Test]
        public void RateIsTheProductAndAStrongEdgeClearsCompletely()
        {
            Assert.That(SnowAccumulation.Rate(2f, 0.5f, 0.25f, 0.5f), Is.EqualTo(2.0 * 0.5 * 0.25 * 0.5).Within(1e-7));
            Assert.That(SnowAccumulation.Rate(2f, 1f, 1f, 1.7f), Is.EqualTo(0f), "max(1 - E, 0)");
        }

        [Test]
        public void StepAddsRateMinusMeltAndClampsToZeroAndCap()
        {
            Assert.That(SnowAccumulation.Step(0.1f, 0.02f, 0.5f, 1f, 0.004f), Is.EqualTo(0.1 + 0.016 * 0.5).Within(1e-7));
            Assert.That(SnowAccumulation.Step(0.99f, 1f, 1f, 1f, 0f), Is.EqualTo(1f));
            Assert.That(SnowAccumulation.Step(0.01f, 0f, 1f, 1f, 0.5f), Is.EqualTo(0f));
        }
    }
}
