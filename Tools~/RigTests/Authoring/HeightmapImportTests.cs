using System;
using NUnit.Framework;

namespace GregoryTerrain.Tests
{
    /// <summary>RAW and texture decoding: byte orders, float, size inference, errors naming the file.</summary>
    [TestFixture]
    public class HeightmapImportTests
    {
        [Test]
        public void RawSixteenBitInEitherByteOrder()
        {
            byte[] le = { 0x34, 0x12, 0xFF, 0xFF, 0x00, 0x00, 0x01, 0x00 };
            byte[] be = { 0x12, 0x34, 0xFF, 0xFF, 0x00, 0x00, 0x00, 0x01 };
            int w = 0, h = 0;
            RawHeightmap.InferSize("a.raw", le.Length, RawSampleFormat.UInt16LittleEndian, ref w, ref h);
            Assert.That((w, h), Is.EqualTo((2, 2)));
            Assert.That(RawHeightmap.Decode("a.raw", le, 2, 2, RawSampleFormat.UInt16LittleEndian), Is.EqualTo(new double[] { 0x1234, 65535, 0, 1 }));
            Assert.That(RawHeightmap.Decode("b.raw", be, 2, 2, RawSampleFormat.UInt16BigEndian), Is.EqualTo(new double[] { 0x1234, 65535, 0, 1 }));
            // SRTM: signed big-endian with -32768 as void.
            Assert.That(RawHeightmap.Decode("c.hgt", be, 2, 2, RawSampleFormat.Int16BigEndian, RawHeightmap.SrtmVoid), Is.EqualTo(new double[] { 0x1234, -1, 0, 1 }));
            byte[] voidBe = { 0x80, 0x00, 0x00, 0x05, 0x00, 0x00, 0x00, 0x01 };
            Assert.That(double.IsNaN(RawHeightmap.Decode("c.hgt", voidBe, 2, 2, RawSampleFormat.Int16BigEndian, RawHeightmap.SrtmVoid)[0]));
        }

        [Test]
        public void RawFloatInEitherByteOrder()
        {
            var le = new byte[16];
            var be = new byte[16];
            float[] v = { 1.5f, -2.25f, 1234.125f, float.NaN };
            for (int k = 0; k < 4; k++)
            {
                byte[] b = BitConverter.GetBytes(v[k]);
                if (!BitConverter.IsLittleEndian) Array.Reverse(b);
                for (int i = 0; i < 4; i++) { le[4 * k + i] = b[i]; be[4 * k + 3 - i] = b[i]; }
            }
            double[] a = RawHeightmap.Decode("f.r32", le, 2, 2, RawSampleFormat.Float32LittleEndian);
            double[] c = RawHeightmap.Decode("f.r32", be, 2, 2, RawSampleFormat.Float32BigEndian);
            Assert.That(new[] { a[0], a[1], a[2] }, Is.EqualTo(new[] { 1.5, -2.25, 1234.125 }));
            Assert.That(new[] { c[0], c[1], c[2] }, Is.EqualTo(new[] { 1.5, -2.25, 1234.125 }));
            Assert.That(double.IsNaN(a[3]) && double.IsNaN(c[3]));
        }

        [Test]
        public void SizeIsInferredWhenSquareAndCheckedOtherwise()
        {
            int w = 0, h = 0;
            RawHeightmap.InferSize("t.raw", 2L * 513 * 513, RawSampleFormat.UInt16LittleEndian, ref w, ref h);
            Assert.That((w, h), Is.EqualTo((513, 513)));
            w = 0; h = 0;
            var ex = Assert.Throws<ArgumentException>(() => RawHeightmap.InferSize("t.raw", 2L * 513 * 512, RawSampleFormat.UInt16LittleEndian, ref w, ref h));
            Assert.That(ex.Message, Does.Contain("t.raw").And.Contain("not a square"));
            w = 513; h = 0;
            RawHeightmap.InferSize("t.raw", 2L * 513 * 512, RawSampleFormat.UInt16LittleEndian, ref w, ref h);
            Assert.That(h, Is.EqualTo(512));
            w = 512; h = 512;
            ex = Assert.Throws<ArgumentException>(() => RawHeightmap.InferSize("t.raw", 2L * 513 * 512, RawSampleFormat.UInt16LittleEndian, ref w, ref h));
            Assert.That(ex.Message, Does.Contain("t.raw").And.Contain("512 x 512 needs 262144"));
            w = h = 0;
            ex = Assert.Throws<ArgumentException>(() => RawHeightmap.InferSize("odd.r32", 4L * 9 + 2, RawSampleFormat.Float32LittleEndian, ref w, ref h));
            Assert.That(ex.Message, Does.Contain("odd.r32").And.Contain("not a whole number of 4-byte samples"));
        }

        [Test]
        public void TextureTexelsKeepTheirPrecision()
        {
            // Two 16-bit values one step apart stay apart (through 8-bit grey they would merge).
            byte[] r16 = { 0x00, 0x80, 0x01, 0x80, 0xFF, 0xFF, 0x00, 0x00 };
            double[] a = TextureHeights.Decode("h16", r16, 2, 2, HeightTexelFormat.R16);
            Assert.That(a, Is.EqualTo(new[] { 0x8000 / 65535.0, 0x8001 / 65535.0, 1.0, 0.0 }));
            // Half: 1.0 = 0x3C00, 0.5 = 0x3800, 65504 = 0x7BFF, smallest subnormal 0x0001.
            byte[] rh = { 0x00, 0x3C, 0x00, 0x38, 0xFF, 0x7B, 0x01, 0x00 };
            Assert.That(TextureHeights.Decode("hh", rh, 2, 2, HeightTexelFormat.RHalf), Is.EqualTo(new[] { 1.0, 0.5, 65504.0, Math.Pow(2, -24) }));
            var ex = Assert.Throws<ArgumentException>(() => TextureHeights.Decode("short", new byte[7], 2, 2, HeightTexelFormat.R16));
            Assert.That(ex.Message, Does.Contain("short").And.Contain("need 8"));
        }

        [Test]
        public void FillRefusesAnAllVoidMap()
        {
            var a = new[] { double.NaN, double.NaN, double.NaN, double.NaN };
            var ex = Assert.Throws<ArgumentException>(() => HeightmapVoids.Fill(a, 2, 2));
            Assert.That(ex.Message, Does.Contain("all 4 samples are voids"));
        }

        [Test]
        public void UnityTerrainHeightsBecomeTerrainUnitsOfItsWidth()
        {
            // A 2 x 2 Unity heightmap [z, x] of fractions, 500 m wide, 600 m high, 400 m deep.
            var f = new float[,] { { 0f, 0.5f }, { 1f, 0.25f } };
            double[] z = TerrainHeights.FromUnity(f, 500, 600, 400);
            Assert.That(z, Is.EqualTo(new[] { 0.0, 0.5 * 600 / 500, 600.0 / 500, 0.25 * 600 / 500 }).Within(1e-15));
            var ex = Assert.Throws<ArgumentException>(() => TerrainHeights.FromUnity(f, 500, 0, 400));
            Assert.That(ex.Message, Does.Contain("size.y = 0"));
            // Round trip through a fit: the fitted grid reproduces a smooth terrain's heights.
            int n = 65;
            var g = new float[n, n];
            for (int r = 0; r < n; r++)
                for (int c = 0; c < n; c++) g[r, c] = (float)(0.5 + 0.4 * Math.Sin(3.0 * c / (n - 1)) * Math.Cos(2.0 * r / (n - 1)));
            HeightmapFit fit = HeightmapFitter.Fit(TerrainHeights.FromUnity(g, 1000, 200, 1000), n, n, 8, 8);
            Assert.That(fit.MaxError * 1000, Is.LessThan(0.01), "metres: a smooth terrain converts to within 1 cm");
        }
    }
}
