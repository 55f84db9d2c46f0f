using System;
using NUnit.Framework;

namespace GregoryTerrain.Tests
{
    [TestFixture]
    public class RangeMappingTests
    {
        // ------------------------------------------------------------ TerrainRange

        [Test]
        public void RangeValidateAcceptsTouchingEdges()
        {
            Assert.DoesNotThrow(() => TerrainRange.full.Validate());
            Assert.DoesNotThrow(() => new TerrainRange(0.25, 0.5, 0.75, 1.0).Validate());
            Assert.That(new TerrainRange(0.25, 0.5, 0.75, 1.0).Width, Is.EqualTo(0.5));
            Assert.That(new TerrainRange(0.25, 0.5, 0.75, 1.0).Height, Is.EqualTo(0.5));
        }

        [Test]
        public void RangeValidateNamesFieldAndValue()
        {
            var ex = Assert.Throws<ArgumentException>(() => new TerrainRange(0.5, 0.0, 0.2, 1.0).Validate());
            Assert.That(ex.Message, Does.Contain("range.g (0.2) must be greater than range.c (0.5)"));
            ex = Assert.Throws<ArgumentException>(() => new TerrainRange(0.0, 0.3, 1.0, 0.3).Validate());
            Assert.That(ex.Message, Does.Contain("range.h (0.3) must be greater than range.d (0.3)"));
            ex = Assert.Throws<ArgumentException>(() => new TerrainRange(double.NaN, 0.0, 1.0, 1.0).Validate());
            Assert.That(ex.Message, Does.Contain("range.c (NaN)"));
            ex = Assert.Throws<ArgumentException>(() => new TerrainRange(0.0, 0.0, 1.5, 1.0).Validate());
            Assert.That(ex.Message, Does.Contain("range.g (1.5)"));
            ex = Assert.Throws<ArgumentException>(() => new TerrainRange(0.0, -0.1, 1.0, 1.0).Validate());
            Assert.That(ex.Message, Does.Contain("range.d (-0.1)"));
        }

        // ------------------------------------------------------------ eq. 10 and its erratum

        [Test]
        public void LocalCoordinateIsZeroAtAAndOneAtE()
        {
            Assert.That(RangeMapping.LocalCoordinate(0.25, 0.25, 0.5), Is.EqualTo(0.0));
            Assert.That(RangeMapping.LocalCoordinate(0.5, 0.25, 0.5), Is.EqualTo(1.0));
            Assert.That(RangeMapping.LocalCoordinate(0.375, 0.25, 0.5), Is.EqualTo(0.5));
            var uv = RangeMapping.LocalCoordinate(new Double2(0.3, 0.9), new Region(0.2, 0.8, 0.4, 1.0));
            Assert.That(uv.x, Is.EqualTo(0.5).Within(1e-15));
            Assert.That(uv.y, Is.EqualTo(0.5).Within(1e-15));
            Assert.Throws<ArgumentException>(() => RangeMapping.LocalCoordinate(0.3, 0.5, 0.5));
            Assert.Throws<ArgumentException>(() => RangeMapping.LocalCoordinate(double.NaN, 0.0, 0.5));
        }

        [Test]
        public void PrintedEq10IsWrongWhenCDiffersFromA()
        {
            // A worked example: c = 0, g = 1, patch [a, e] = [0.25, 0.5].
            double c = 0.0, g = 1.0, a = 0.25, e = 0.5;
            double printed0 = RangeMapping.PrintedEq10(c, g, a, e, 0.0);
            double printed1 = RangeMapping.PrintedEq10(c, g, a, e, 1.0);
            double right0 = RangeMapping.LocalCoordinate(c + 0.0 * (g - c), a, e);
            double right1 = RangeMapping.LocalCoordinate(c + 1.0 * (g - c), a, e);
            TestContext.Out.WriteLine($"printed eq. 10: u from {printed0} to {printed1}; corrected: {right0} to {right1}");
            Assert.That(printed0, Is.EqualTo(-1.0).Within(1e-15));
            Assert.That(printed1, Is.EqualTo(2.0).Within(1e-15));
            Assert.That(right0, Is.EqualTo(-1.0).Within(1e-15));
            Assert.That(right1, Is.EqualTo(3.0).Within(1e-15));
        }

        [TestCase(0.0, 1.0, 0.25, 0.5)]
        [TestCase(0.1, 0.7, 0.3, 0.45)]
        [TestCase(0.6, 0.9, 0.5, 0.75)]
        public void PrintedEq10EndpointIsCPlusGMinus2A(double c, double g, double a, double e)
        {
            // General end point (o = 1): printed gives (c + g - 2a)/(e - a), corrected (g - a)/(e - a).
            Assert.That(RangeMapping.PrintedEq10(c, g, a, e, 1.0), Is.EqualTo((c + g - 2 * a) / (e - a)).Within(1e-12));
            Assert.That(RangeMapping.LocalCoordinate(g, a, e), Is.EqualTo((g - a) / (e - a)).Within(1e-12));
            Assert.That(RangeMapping.PrintedEq10(c, g, a, e, 1.0) - RangeMapping.LocalCoordinate(g, a, e),
                Is.EqualTo((c - a) / (e - a)).Within(1e-12), "the error is (c - a)/(e - a)");
        }

        [TestCase(0.25, 1.0, 0.5)]
        [TestCase(0.0, 0.5, 0.125)]
        public void PrintedEq10AgreesWhenCEqualsA(double a, double g, double e)
        {
            double c = a;
            for (int k = 0; k <= 8; k++)
            {
                double o = k / 8.0;
                Assert.That(RangeMapping.PrintedEq10(c, g, a, e, o),
                    Is.EqualTo(RangeMapping.LocalCoordinate(c + o * (g - c), a, e)).Within(1e-12));
            }
        }

        // ------------------------------------------------------------ tile layout

        static readonly float[] EdgeAndInterior = { 0f, 1f, 1f / 3f, 0.5f, 0.1f, 0.999f, 1f / 64f, 63f / 64f };

        [TestCase(1)]
        [TestCase(3)]
        [TestCase(8)]
        [TestCase(16)]
        public void SharedTileEdgesAreBitIdentical(int tiles)
        {
            var range = new Float4(0.1234567f, 0.3f, 0.7654321f, 0.9f);
            var origin = RangeOrigin.Snap(new Double2(0.4, 0.6)).ToFloat4();
            var rangeRel = new Float4(range.x - origin.x, range.y - origin.y, range.z - origin.x, range.w - origin.y);
            int checkedEdges = 0;
            for (int tj = 0; tj < tiles; tj++)
            for (int ti = 0; ti < tiles; ti++)
            foreach (float t in EdgeAndInterior)
            {
                if (ti + 1 < tiles)
                {   // right edge of (ti, tj) == left edge of (ti + 1, tj)
                    Assert.That(RangeMapping.RangeCoordinate(ti, tj, 1f, t, tiles),
                        Is.EqualTo(RangeMapping.RangeCoordinate(ti + 1, tj, 0f, t, tiles)));
                    Assert.That(RangeMapping.PlainGlobalPoint(range, tiles, ti, tj, 1f, t),
                        Is.EqualTo(RangeMapping.PlainGlobalPoint(range, tiles, ti + 1, tj, 0f, t)));
                    Assert.That(RangeMapping.ToTerrainPoint(rangeRel, origin, tiles, ti, tj, 1f, t),
                        Is.EqualTo(RangeMapping.ToTerrainPoint(rangeRel, origin, tiles, ti + 1, tj, 0f, t)));
                    checkedEdges++;
                }
                if (tj + 1 < tiles)
                {   // top edge of (ti, tj) == bottom edge of (ti, tj + 1)
                    Assert.That(RangeMapping.RangeCoordinate(ti, tj, t, 1f, tiles),
                        Is.EqualTo(RangeMapping.RangeCoordinate(ti, tj + 1, t, 0f, tiles)));
                    Assert.That(RangeMapping.ToTerrainPoint(rangeRel, origin, tiles, ti, tj, t, 1f),
                        Is.EqualTo(RangeMapping.ToTerrainPoint(rangeRel, origin, tiles, ti, tj + 1, t, 0f)));
                    checkedEdges++;
                }
            }
            // Corners of the whole range map to exactly 0 and 1.
            Assert.That(RangeMapping.RangeCoordinate(0, 0, 0f, 0f, tiles), Is.EqualTo(new Float2(0f, 0f)));
            Assert.That(RangeMapping.RangeCoordinate(tiles - 1, tiles - 1, 1f, 1f, tiles), Is.EqualTo(new Float2(1f, 1f)));
            Assert.That(checkedEdges, Is.EqualTo(tiles == 1 ? 0 : 2 * tiles * (tiles - 1) * EdgeAndInterior.Length));
        }

        [Test]
        public void RangeCoordinateMatchesDoubleReference()
        {
            for (int tiles = 1; tiles <= 16; tiles++)
            for (int ti = 0; ti < tiles; ti++)
            foreach (float s in EdgeAndInterior)
            {
                Float2 f = RangeMapping.RangeCoordinate(ti, 0, s, s, tiles);
                Double2 d = RangeMapping.RangeCoordinate(ti, 0, (double)s, s, tiles);
                Assert.That((double)f.x, Is.EqualTo(d.x).Within(1e-7 * Math.Max(d.x, 1e-30)));
            }
            Assert.Throws<ArgumentException>(() => RangeMapping.RangeCoordinate(3, 0, 0f, 0f, 3));
            Assert.Throws<ArgumentException>(() => RangeMapping.RangeCoordinate(0, 0, 1.5f, 0f, 3));
            Assert.Throws<ArgumentException>(() => RangeMapping.RangeCoordinate(0, 0, 0f, 0f, 0));
        }

        // ------------------------------------------------------------ range origin

        [Test]
        public void OriginZeroReducesToPlainRangeBitForBit()
        {
            var range = new TerrainRange(0.1, 0.2, 0.8, 0.65);
            RangeMapping.EncodeRange(range, RangeOrigin.zero, out Float4 rangeF, out Float4 originF);
            Assert.That(originF, Is.EqualTo(Float4.zero));
            Assert.That(rangeF, Is.EqualTo(new Float4(0.1f, 0.2f, 0.8f, 0.65f)));
            var region = new Float4(0.25f, 0.125f, 0.5f, 0.375f);
            foreach (int tiles in new[] { 1, 3, 8 })
            for (int ti = 0; ti < tiles; ti++)
            foreach (float s in EdgeAndInterior)
            foreach (float t in EdgeAndInterior)
            {
                Float2 plain = RangeMapping.PlainGlobalPoint(rangeF, tiles, ti, tiles - 1 - ti, s, t);
                TerrainPoint p = RangeMapping.ToTerrainPoint(rangeF, originF, tiles, ti, tiles - 1 - ti, s, t);
                Assert.That(p.local, Is.EqualTo(plain));
                Assert.That(RangeMapping.Approximate(p), Is.EqualTo(plain));
                var uv = RangeMapping.PatchLocalUV(p, region);
                Assert.That(uv.x, Is.EqualTo((plain.x - region.x) / (region.z - region.x)));
                Assert.That(uv.y, Is.EqualTo((plain.y - region.y) / (region.w - region.y)));
            }
        }

        [Test]
        public void SnappedOriginIsExactlyAFloatPair()
        {
            var o = RangeOrigin.Snap(new Double2(0.7000001234567891, 0.123456789012345));
            Assert.That(o.Value.x, Is.EqualTo(0.7000001234567891).Within(1e-15));
            Assert.That(o.Value.y, Is.EqualTo(0.123456789012345).Within(1e-15));
            Assert.That((double)(float)o.Value.x, Is.EqualTo((double)o.hi.x), "hi is the float nearest the origin");
            Assert.That(o.Value.x - o.hi.x, Is.EqualTo((double)o.lo.x), "the remainder is exactly lo");
            Assert.That(RangeOrigin.For(TerrainRange.full), Is.EqualTo(RangeOrigin.zero));
            Assert.That(RangeOrigin.For(new TerrainRange(0.7, 0.7, 0.7 + 1e-6, 0.7 + 1e-6)), Is.Not.EqualTo(RangeOrigin.zero));
            Assert.Throws<ArgumentException>(() => RangeOrigin.Snap(new Double2(double.PositiveInfinity, 0)));
        }

        [Test]
        public void DeepZoomTerrainPointMatchesDoubleWherePlainFloatFails()
        {
            const double width = 1e-6;
            var range = new TerrainRange(0.7, 0.7123, 0.7 + width, 0.7123 + width);
            RangeOrigin origin = RangeOrigin.For(range);
            RangeMapping.EncodeRange(range, origin, out Float4 rangeF, out Float4 originF);
            RangeMapping.EncodeRange(range, RangeOrigin.zero, out Float4 plainF, out _);
            const int tiles = 8;
            double maxOrigin = 0, maxPlain = 0;
            for (int tj = 0; tj < tiles; tj++)
            for (int ti = 0; ti < tiles; ti++)
            for (int k = 0; k <= 16; k++)
            {
                float s = k / 16f, t = (16 - k) / 16f;
                Double2 reference = RangeMapping.GlobalPoint(range, tiles, ti, tj, s, t);
                Double2 viaOrigin = RangeMapping.ToTerrainPoint(rangeF, originF, tiles, ti, tj, s, t).ToDouble();
                Double2 plain = RangeMapping.PlainGlobalPoint(plainF, tiles, ti, tj, s, t);
                maxOrigin = Math.Max(maxOrigin, Math.Max(Math.Abs(viaOrigin.x - reference.x), Math.Abs(viaOrigin.y - reference.y)));
                maxPlain = Math.Max(maxPlain, Math.Max(Math.Abs(plain.x - reference.x), Math.Abs(plain.y - reference.y)));
            }
            TestContext.Out.WriteLine($"range width {width:E0} near 0.7: max |q - q_double| origin+local float = {maxOrigin:E3}, plain float c + o(g - c) = {maxPlain:E3}");
            TestContext.Out.WriteLine($"vertex spacing at 8 tiles x 16 = {width / 128:E3}");
            Assert.That(maxOrigin, Is.LessThan(1e-12));
            Assert.That(maxPlain, Is.GreaterThan(1e-9), "plain float must show the quantisation the origin removes");
        }

        [Test]
        public void DeepZoomPatchLocalUVMatchesDouble()
        {
            // Range of width 1e-6 inside patch [0.625, 0.75] x [0.5, 0.75] (float-exact region).
            var range = new TerrainRange(0.7, 0.6, 0.7 + 1e-6, 0.6 + 1e-6);
            var region = new Region(0.625, 0.5, 0.75, 0.75);
            var regionF = new Float4(0.625f, 0.5f, 0.75f, 0.75f);
            RangeMapping.EncodeRange(range, RangeOrigin.For(range), out Float4 rangeF, out Float4 originF);
            double maxErr = 0;
            for (int k = 0; k <= 32; k++)
            {
                float s = k / 32f;
                TerrainPoint p = RangeMapping.ToTerrainPoint(rangeF, originF, 4, k % 4, 3 - k % 4, s, 1f - s);
                Double2 uvRef = RangeMapping.LocalCoordinate(RangeMapping.GlobalPoint(range, 4, k % 4, 3 - k % 4, s, 1.0 - s), region);
                Float2 uv = RangeMapping.PatchLocalUV(p, regionF);
                maxErr = Math.Max(maxErr, Math.Max(Math.Abs(uv.x - uvRef.x), Math.Abs(uv.y - uvRef.y)));
            }
            TestContext.Out.WriteLine($"deep zoom: max |uv - uv_double| = {maxErr:E3} (float ulp of 0.6 = {Math.Pow(2, -24):E3})");
            Assert.That(maxErr, Is.LessThanOrEqualTo(Math.Pow(2, -24)), "within one float ulp of u");
        }

        [Test]
        public void TwoSumIsExact()
        {
            var rng = new Random(7);
            for (int i = 0; i < 10000; i++)
            {
                float a = (float)rng.NextDouble(), b = -(float)(rng.NextDouble() * Math.Pow(2, -rng.Next(0, 30)));
                float s = RangeMapping.TwoSum(a, b, out float err);
                Assert.That((double)s + err, Is.EqualTo((double)a + b));
            }
        }
    }
}
