using System;
using NUnit.Framework;

namespace GregoryTerrain.Tests
{
    [TestFixture]
    public class SnowExposureTests
    {
        [TestCase(0.3, 1.0, 0.4)]
        [TestCase(-0.2, 0.5, 1.2)]
        [TestCase(0.0, 0.01, 0.01)]
        [TestCase(2.0, 0.001, 1.5)]
        public void OcclusionIsTheSineOfTheElevationAboveTheFallLine(double dz, double t, double fallAngle)
        {
            double expected = Math.Sin(Math.Atan2(dz, t) - fallAngle);
            float o = SnowExposure.Occlusion((float)dz, (float)t, (float)Math.Cos(fallAngle), (float)Math.Sin(fallAngle));
            Assert.That(o, Is.EqualTo(expected).Within(1e-5));
        }

        [Test]
        public void FromOcclusionIsOneBelowTheFallLineAndZeroAboveTheSoftBand()
        {
            Assert.That(SnowExposure.FromOcclusion(-0.5f, 0.1f), Is.EqualTo(1f));
            Assert.That(SnowExposure.FromOcclusion(0f, 0.1f), Is.EqualTo(1f));
            Assert.That(SnowExposure.FromOcclusion(0.05f, 0.1f), Is.EqualTo(0.5f).Within(1e-6f));
            Assert.That(SnowExposure.FromOcclusion(0.2f, 0.1f), Is.EqualTo(0f));
        }

        [Test]
        public void SampleHeightInterpolatesBetweenCellCentres()
        {
            // h = 0.3 x + 0.1 y at the cell centres: bilinear interpolation reproduces a plane exactly.
            const int r = 64;
            var f = new SnowField(r);
            for (int j = 0; j < r; j++)
                for (int i = 0; i < r; i++)
                    f.Set(i, j, new Float3(0f, 0f, 1f), 0.3f * (i + 0.5f) / r + 0.1f * (j + 0.5f) / r);
            var grid = new Float4(r, 1f / r, 0.25f, 8f);
            var rng = new Random(3);
            for (int n = 0; n < 200; n++)
            {
                float x = 0.01f + 0.98f * (float)rng.NextDouble(), y = 0.01f + 0.98f * (float)rng.NextDouble();
                Assert.That(SnowExposure.SampleHeight(f.Data, grid, new Float2(x, y)), Is.EqualTo(0.3 * x + 0.1 * y).Within(1e-6));
            }
        }

        [Test]
        public void LeeSideOfARidgeIsShieldedTheWindwardSideIsNot()
        {
            const int r = 128;
            var field = SnowTestTerrain.Ridge(r, 0.1f, 0.1f);  // faces of slope 1
            var s = SnowSettings.Default;
            s.resolution = r; s.wind = new Float2(2f, 0f); s.fallSpeed = 1f;  // fall line slope 0.5 < 1
            float[] p = s.Params(0f).Pack();
            var grid = new Float4(p[0], p[1], p[2], p[3]);
            var fall = new Float4(p[4], p[5], p[6], p[7]);
            int windward = SnowTestTerrain.Column(r, 0.45), lee = SnowTestTerrain.Column(r, 0.55);
            float lw = SnowExposure.Evaluate(field.Data, windward, 64, grid, fall, s.exposureSoftness);
            float ll = SnowExposure.Evaluate(field.Data, lee, 64, grid, fall, s.exposureSoftness);
            TestContext.Out.WriteLine($"exposure windward {lw}, lee {ll}");
            Assert.That(lw, Is.EqualTo(1f));
            Assert.That(ll, Is.EqualTo(0f));
            // Far downwind the ridge sinks below the fall line again: exposed. Level ground upwind: exposed.
            Assert.That(SnowExposure.Evaluate(field.Data, SnowTestTerrain.Column(r, 0.95), 64, grid, fall, s.exposureSoftness), Is.EqualTo(1f));
            Assert.That(SnowExposure.Evaluate(field.Data, 3, 64, grid, fall, s.exposureSoftness), Is.EqualTo(1f));
            // Wind from the other side swaps the roles.
            s.wind = new Float2(-2f, 0f);
            p = s.Params(0f).Pack();
            fall = new Float4(p[4], p[5], p[6], p[7]);
            Assert.That(SnowExposure.Evaluate(field.Data, windward, 64, grid, fall, s.exposureSoftness), Is.EqualTo(0f));
            Assert.That(SnowExposure.Evaluate(field.Data, lee, 64, grid, fall, s.exposureSoftness), Is.EqualTo(1f));
        }

        [Test]
        public void ZeroWindExposesEverythingWithoutNaN()
        {
            const int r = 64;
            var field = SnowTestTerrain.Ridge(r, 0.3f, 0.02f);  // very steep faces
            var s = SnowSettings.Default;
            s.resolution = r; s.wind = new Float2(0f, 0f);
            Float4 fall = s.FallLine;
            Assert.That(fall, Is.EqualTo(new Float4(0f, 0f, 0f, 1f)));
            float[] p = s.Params(0f).Pack();
            var grid = new Float4(p[0], p[1], p[2], p[3]);
            for (int i = 0; i < r; i++)
                Assert.That(SnowExposure.Evaluate(field.Data, i, 10, grid, fall, s.exposureSoftness), Is.EqualTo(1f));
            // Nearly horizontal snowfall (wind 1e6 times the fall speed): finite, fall line nearly flat.
            s.wind = new Float2(0f, 1e6f);
            fall = s.FallLine;
            Assert.That(fall.IsFinite && fall.z > 0.999f && fall.w > 0f, Is.True, fall.ToString());
            for (int i = 0; i < r; i++)
            {
                float l = SnowExposure.Evaluate(field.Data, i, 10, grid, fall, s.exposureSoftness);
                Assert.That(GMath.isfinite(l) && l >= 0f && l <= 1f, Is.True, "L " + l);
            }
        }
    }
}
