using System;
using System.Collections.Generic;
using NUnit.Framework;

namespace GregoryTerrain.Tests
{
    [TestFixture]
    public class NormalEncodingTests
    {
        /// <summary>Unit normals spread evenly over the sphere (a Fibonacci lattice), in double.</summary>
        internal static IEnumerable<Double3> SphereNormals(int count)
        {
            double golden = Math.PI * (3.0 - Math.Sqrt(5.0));
            for (int i = 0; i < count; i++)
            {
                double y = 1.0 - 2.0 * (i + 0.5) / count, r = Math.Sqrt(1.0 - y * y);
                yield return new Double3(r * Math.Cos(golden * i), y, r * Math.Sin(golden * i));
            }
        }

        static Float3 ToFloat(Double3 n) => new Float3((float)n.x, (float)n.y, (float)n.z);

        static double AngleDegrees(Float3 a, Double3 b)
        {
            double d = (a.x * b.x + a.y * b.y + a.z * b.z) / Math.Sqrt(a.x * a.x + a.y * a.y + a.z * a.z);
            return Math.Acos(Math.Min(1.0, d)) * 180.0 / Math.PI;
        }

        [Test]
        public void RoundTripKeepsTheNormalAwayFromStraightDown()
        {
            double worst = 0, worstNearPole = 0;
            foreach (Double3 n in SphereNormals(100_000))
            {
                Float3 back = NormalEncoding.LambertDecodeNormal(NormalEncoding.LambertEncodeNormal(ToFloat(n)));
                double error = Math.Sqrt((back.x - n.x) * (back.x - n.x) + (back.y - n.y) * (back.y - n.y) + (back.z - n.z) * (back.z - n.z));
                if (n.y > -0.999) worst = Math.Max(worst, error);
                else worstNearPole = Math.Max(worstNearPole, error);
            }
            TestContext.Out.WriteLine("round trip, 100,000 normals: largest error {0:G3} (n.y > -0.999), {1:G3} within 2.6 degrees of straight down", worst, worstNearPole);
            Assert.That(worst, Is.LessThan(2e-5));
            Assert.That(worstNearPole, Is.LessThan(1e-4));
        }

        [Test]
        public void UpIsTheCentreAndStraightDownStaysFinite()
        {
            Assert.That(NormalEncoding.LambertEncodeNormal(new Float3(0f, 1f, 0f)), Is.EqualTo(new Float2(0f, 0f)));
            Assert.That(NormalEncoding.LambertDecodeNormal(new Float2(0f, 0f)), Is.EqualTo(new Float3(0f, 1f, 0f)));
            Float2 down = NormalEncoding.LambertEncodeNormal(new Float3(0f, -1f, 0f));
            Assert.That(down.IsFinite, Is.True, down.ToString());
            // The rim of the disk is straight down, whatever the direction.
            Float3 rim = NormalEncoding.LambertDecodeNormal(new Float2(0.6f * 2f, 0.8f * 2f));
            Assert.That(rim.y, Is.EqualTo(-1f));
            Assert.That(NormalEncoding.LambertDecodeNormal(new Float2(2.5f, 0f)).IsFinite, Is.True, "outside the disk (rounding) stays finite");
        }

        /// <summary>Every point of the disk (an interpolated code) decodes to a unit vector.</summary>
        [Test]
        public void EveryPointOfTheDiskIsAUnitNormal()
        {
            double worst = 0;
            for (int j = -200; j <= 200; j++)
                for (int i = -200; i <= 200; i++)
                {
                    var e = new Float2(i / 100f, j / 100f);
                    if (e.x * e.x + e.y * e.y > 4f) continue;
                    Float3 n = NormalEncoding.LambertDecodeNormal(e);
                    worst = Math.Max(worst, Math.Abs(Math.Sqrt(n.x * n.x + n.y * n.y + n.z * n.z) - 1.0));
                }
            Assert.That(worst, Is.LessThan(1e-6));
        }

        /// <summary>
        /// What the interpolant does: the midpoint of two codes against the normalised mean of the two
        /// normals, for pairs across the horizon (where an octahedral code folds) and on steep slopes.
        /// </summary>
        [TestCase(80.0, 100.0, 0.5)]
        [TestCase(30.0, 60.0, 0.5)]
        [TestCase(60.0, 120.0, 4.0)]
        public void MidpointOfTwoCodesIsNearTheMeanNormal(double theta0, double theta1, double boundDegrees)
        {
            for (int k = 0; k < 16; k++)
            {
                double phi = k * Math.PI / 8;
                Double3 Polar(double t) => new Double3(Math.Sin(t * Math.PI / 180) * Math.Cos(phi), Math.Cos(t * Math.PI / 180), Math.Sin(t * Math.PI / 180) * Math.Sin(phi));
                Double3 a = Polar(theta0), b = Polar(theta1);
                Float2 ea = NormalEncoding.LambertEncodeNormal(ToFloat(a)), eb = NormalEncoding.LambertEncodeNormal(ToFloat(b));
                Float3 mid = NormalEncoding.LambertDecodeNormal(new Float2(0.5f * (ea.x + eb.x), 0.5f * (ea.y + eb.y)));
                Double3 mean = a + b;
                double len = Math.Sqrt(mean.x * mean.x + mean.y * mean.y + mean.z * mean.z);
                Assert.That(AngleDegrees(mid, new Double3(mean.x / len, mean.y / len, mean.z / len)), Is.LessThan(boundDegrees), $"phi {phi}");
            }
        }
    }
}
