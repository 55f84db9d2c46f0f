using System;
using NUnit.Framework;

namespace GregoryTerrain.Tests
{
    [TestFixture]
    public class PatchGridJsonTests
    {
        static PatchGrid Sample()
        {
            // Awkward doubles on purpose: thirds, tiny and huge magnitudes, -0, subnormals.
            var g = HeightmapFitter.Fit(HeightmapFitterTests.Samples(17, 13), 17, 13, 3, 2).Grid;
            g.Patch(0, 0)[GregoryPatch.P111] = new Double3(-0.0, 4.9e-324, 1.0 / 3.0);
            g.Patch(2, 1)[GregoryPatch.P220] = new Double3(3.4e38, -2.2250738585072014e-308, 0.1);
            return g;
        }

        static long Bits(double d) => BitConverter.DoubleToInt64Bits(d);

        [Test]
        public void RoundTripsBitForBit()
        {
            var g = Sample();
            var r = PatchGridJson.Read(PatchGridJson.Write(g));
            Assert.That(r.Columns, Is.EqualTo(g.Columns));
            Assert.That(r.Rows, Is.EqualTo(g.Rows));
            for (int k = 0; k < g.XLines.Length; k++) Assert.That(Bits(r.XLines[k]), Is.EqualTo(Bits(g.XLines[k])));
            for (int k = 0; k < g.YLines.Length; k++) Assert.That(Bits(r.YLines[k]), Is.EqualTo(Bits(g.YLines[k])));
            for (int p = 0; p < g.PatchCount; p++)
                for (int s = 0; s < 20; s++)
                {
                    Double3 a = g.Patches[p][s], b = r.Patches[p][s];
                    Assert.That(Bits(b.x), Is.EqualTo(Bits(a.x)), $"patch {p} slot {s} x");
                    Assert.That(Bits(b.y), Is.EqualTo(Bits(a.y)), $"patch {p} slot {s} y");
                    Assert.That(Bits(b.z), Is.EqualTo(Bits(a.z)), $"patch {p} slot {s} z");
                }
            Assert.That(PatchGridJson.Write(r), Is.EqualTo(PatchGridJson.Write(g)));
        }

        [Test]
        public void NumberTextRoundTripsRandomDoubles()
        {
            var rng = new Random(1);
            var buf = new byte[8];
            for (int n = 0; n < 20000; n++)
            {
                rng.NextBytes(buf);
                double d = BitConverter.ToDouble(buf, 0);
                if (!GMath.isfinite(d)) continue;
                string s = PatchGridJson.Number(d);
                Assert.That(Bits(double.Parse(s, System.Globalization.CultureInfo.InvariantCulture)), Is.EqualTo(Bits(d)), s);
            }
        }

        static string Good => PatchGridJson.Write(PatchGrid.CreateFlat(2, 1));

        static void Rejects(string json, params string[] parts)
        {
            var ex = Assert.Throws<FormatException>(() => PatchGridJson.Read(json));
            foreach (string p in parts) Assert.That(ex.Message, Does.Contain(p));
        }

        [Test]
        public void RejectsTruncatedFile() => Rejects(Good.Substring(0, Good.Length / 2), "truncated", "line");

        [Test]
        public void RejectsWrongVersion() => Rejects(Good.Replace("\"version\":1", "\"version\":2"), "version", "is 2");

        [Test]
        public void RejectsWrongFormat() => Rejects(Good.Replace("gregory-terrain-grid", "something-else"), "format", "something-else");

        [Test]
        public void RejectsMissingField() => Rejects(Good.Replace("\"rows\":1,", ""), "rows", "missing");

        [Test]
        public void RejectsWrongCounts()
        {
            Rejects(Good.Replace("\"columns\":2", "\"columns\":3"), "xLines", "has 3 numbers, need columns + 1 = 4");
            Rejects(Good.Replace("\"xLines\":[0,0.5,1]", "\"xLines\":[0,1]"), "xLines", "has 2");
        }

        [Test]
        public void RejectsNaNAndOverflow()
        {
            Rejects(Good.Replace("\"yLines\":[0,1]", "\"yLines\":[0,NaN]"), "NaN", "line 3");
            Rejects(Good.Replace("\"yLines\":[0,1]", "\"yLines\":[0,1e999]"), "yLines[1]", "1e999", "not a finite");
        }

        [Test]
        public void RejectsAPointOfTheWrongShape()
        {
            int at = Good.IndexOf("[[", Good.IndexOf("\"patches\"", StringComparison.Ordinal), StringComparison.Ordinal);
            string bad = Good.Substring(0, at) + "[[0,0]" + Good.Substring(Good.IndexOf(']', at) + 1);
            Rejects(bad, "patches[0] (patch (0, 0))[0]", "has 2 numbers, need 3");
        }

        [Test]
        public void RejectsAnInvalidGrid() => Rejects(Good.Replace("\"xLines\":[0,0.5,1]", "\"xLines\":[0,0.5,0.9]"), "not valid", "xLines[2] = 0.9");

        [Test]
        public void RejectsTrailingGarbage() => Rejects(Good + "x", "after the end");
    }
}
