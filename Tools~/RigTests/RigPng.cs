// The harness's PNGs (RGBA8, filter 0, stored or deflated zlib) decoded to pixels, for tests that
// compare two images pixel by pixel.
using System;
using System.IO;
using System.IO.Compression;
using System.Text;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    public sealed class RigPng
    {
        public int Width, Height;
        /// <summary>RGBA, row-major, top row first.</summary>
        public byte[] Rgba;

        public static RigPng Read(string path)
        {
            byte[] png = File.ReadAllBytes(path);
            Assert.That(png.Length, Is.GreaterThan(8), path);
            var idat = new MemoryStream();
            var image = new RigPng();
            for (int i = 8; i + 8 <= png.Length;)
            {
                int len = (int)BigEndian(png, i);
                string type = Encoding.ASCII.GetString(png, i + 4, 4);
                if (type == "IHDR") { image.Width = (int)BigEndian(png, i + 8); image.Height = (int)BigEndian(png, i + 12); }
                if (type == "IDAT") idat.Write(png, i + 8, len);
                i += 12 + len;
            }
            byte[] raw;
            using (var inflate = new ZLibStream(new MemoryStream(idat.ToArray()), CompressionMode.Decompress))
            using (var o = new MemoryStream())
            {
                inflate.CopyTo(o);
                raw = o.ToArray();
            }
            int stride = 1 + 4 * image.Width;
            Assert.That(raw.Length, Is.EqualTo(image.Height * stride), path);
            image.Rgba = new byte[4 * image.Width * image.Height];
            for (int y = 0; y < image.Height; y++)
            {
                Assert.That(raw[y * stride], Is.EqualTo(0), "filter byte of row " + y + " in " + path);
                Buffer.BlockCopy(raw, y * stride + 1, image.Rgba, y * 4 * image.Width, 4 * image.Width);
            }
            return image;
        }

        /// <summary>Pixels whose RGB differ from <paramref name="other"/>'s by more than <paramref name="tolerance"/> in some channel.</summary>
        public int PixelsDifferingFrom(RigPng other, int tolerance)
        {
            Assert.That((other.Width, other.Height), Is.EqualTo((Width, Height)), "image sizes");
            int n = 0;
            for (int p = 0; p < Width * Height; p++)
            {
                bool differs = false;
                for (int c = 0; c < 3; c++) differs |= Math.Abs(Rgba[4 * p + c] - other.Rgba[4 * p + c]) > tolerance;
                if (differs) n++;
            }
            return n;
        }

        /// <summary>How many different RGB values the image holds.</summary>
        public int DistinctColours()
        {
            var seen = new System.Collections.Generic.HashSet<int>();
            for (int p = 0; p < Width * Height; p++) seen.Add(Rgba[4 * p] << 16 | Rgba[4 * p + 1] << 8 | Rgba[4 * p + 2]);
            return seen.Count;
        }

        static uint BigEndian(byte[] b, int i) => (uint)(b[i] << 24 | b[i + 1] << 16 | b[i + 2] << 8 | b[i + 3]);
    }
}
