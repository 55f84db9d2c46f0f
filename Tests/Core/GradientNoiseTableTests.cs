using System;
using NUnit.Framework;

namespace GregoryTerrain.Tests
{
    /// <summary>The tiled noise (GT_NOISE_TABLE): the hashed noise on a lattice wrapped modulo 256.</summary>
    [TestFixture]
    public class GradientNoiseTableTests
    {
        static readonly NoiseSettings Settings = new NoiseSettings(0.02f, 8f, 2f, 2f, 12);
        const TerrainKeywords Tiled = TerrainKeywords.NoiseTable;

        [Test]
        public void InsideTheTableItIsTheHashedNoise()
        {
            // Cells whose four corners lie in [0, 255]: the same gradients, so the same function;
            // float values differ only by the table's one rounding of each coefficient.
            var rng = new Random(31);
            double worst = 0, worstGradient = 0;
            for (int k = 0; k < 20000; k++)
            {
                int ix = rng.Next(0, 255), iy = rng.Next(0, 255);
                float fx = (float)rng.NextDouble(), fy = (float)rng.NextDouble();
                float t = GradientNoise.Cell(ix, iy, fx, fy, out Float2 gt, Tiled);
                float h = GradientNoise.Cell(ix, iy, fx, fy, out Float2 gh);
                worst = Math.Max(worst, Math.Abs(t - h));
                worstGradient = Math.Max(worstGradient, Math.Max(Math.Abs(gt.x - gh.x), Math.Abs(gt.y - gh.y)));
                Assert.That(GradientNoise.Evaluate(ix + (double)fx, iy + (double)fy, out _, Tiled),
                            Is.EqualTo(GradientNoise.Evaluate(ix + (double)fx, iy + (double)fy, out _)), "double reference inside the table");
            }
            TestContext.Out.WriteLine($"tiled against hashed inside [0, 255]^2: value {worst:E2}, gradient {worstGradient:E2}");
            Assert.That(worst, Is.LessThan(2e-6));
            Assert.That(worstGradient, Is.LessThan(2e-5));
        }

        [Test]
        public void RepeatsEvery256CellsAndDiffersFromTheHashedNoiseBeyond()
        {
            var rng = new Random(32);
            int differ = 0;
            for (int k = 0; k < 5000; k++)
            {
                double x = rng.NextDouble() * 256, y = rng.NextDouble() * 256;
                int sx = rng.Next(-40, 40) * 256, sy = rng.Next(-40, 40) * 256;
                double a = GradientNoise.Evaluate(x, y, out Double2 ga, Tiled);
                double b = GradientNoise.Evaluate(x + sx, y + sy, out Double2 gb, Tiled);
                Assert.That(b, Is.EqualTo(a).Within(1e-9), $"period at ({x:R}, {y:R}) + ({sx}, {sy})");
                Assert.That(gb.x, Is.EqualTo(ga.x).Within(1e-9));
                float fa = GradientNoise.Cell((int)Math.Floor(x), (int)Math.Floor(y), (float)(x - Math.Floor(x)), (float)(y - Math.Floor(y)), out _, Tiled);
                float fb = GradientNoise.Cell((int)Math.Floor(x) + sx, (int)Math.Floor(y) + sy, (float)(x - Math.Floor(x)), (float)(y - Math.Floor(y)), out _, Tiled);
                Assert.That(fb, Is.EqualTo(fa), "float: the same table row");
                if (Math.Abs(GradientNoise.Evaluate(x + sx, y + sy, out _) - b) > 1e-3) differ++;
            }
            Assert.That(differ, Is.GreaterThan(4000), "beyond the table the hashed noise is another function");
        }

        [Test]
        public void SmoothAcrossTheWrapSeam()
        {
            // Across x = 256 (cell 255 -> cell 0 of the next tile) value and gradient are continuous:
            // cell 255's far corners are the next tile's cell 0's near corners.
            var rng = new Random(33);
            for (int k = 0; k < 2000; k++)
            {
                double y = rng.NextDouble() * 1024 - 512;
                const double e = 1e-9;
                double left = GradientNoise.Evaluate(256 - e, y, out Double2 gl, Tiled);
                double right = GradientNoise.Evaluate(256 + e, y, out Double2 gr, Tiled);
                Assert.That(right, Is.EqualTo(left).Within(1e-7), $"value across x = 256 at y {y:R}");
                Assert.That(gr.x, Is.EqualTo(gl.x).Within(1e-6), $"d/dx across x = 256 at y {y:R}");
                Assert.That(gr.y, Is.EqualTo(gl.y).Within(1e-6), $"d/dy across x = 256 at y {y:R}");
                double below = GradientNoise.Evaluate(y, -e, out _, Tiled), above = GradientNoise.Evaluate(y, e, out _, Tiled);
                Assert.That(above, Is.EqualTo(below).Within(1e-7), $"value across y = 0 at x {y:R}");
            }
        }

        [Test]
        public void FloatMatchesTheDoubleReferenceWithGradient()
        {
            var rng = new Random(34);
            double worst = 0;
            for (int k = 0; k < 2000; k++)
            {
                double x = rng.NextDouble(), y = rng.NextDouble();
                var q = new Float2((float)x, (float)y);
                float count = (float)(rng.NextDouble() * Settings.octaves);
                float f = OctaveNoise.Evaluate(TerrainPoint.FromFloat(q), Settings, count, out Float2 gf, Tiled);
                double d = OctaveNoise.Evaluate(q.x, q.y, Settings, count, out Double2 gd, Tiled);
                worst = Math.Max(worst, Math.Abs(f - d));
                Assert.That(gf.x, Is.EqualTo(gd.x).Within(2e-3 * (1 + Math.Abs(gd.x))), $"d/dx at {q}");
                Assert.That(gf.y, Is.EqualTo(gd.y).Within(2e-3 * (1 + Math.Abs(gd.y))), $"d/dy at {q}");
                const double h = 1e-7;
                double gx = (OctaveNoise.Evaluate(x + h, y, Settings, count, out _, Tiled) - OctaveNoise.Evaluate(x - h, y, Settings, count, out _, Tiled)) / (2 * h);
                Assert.That(OctaveNoise.Evaluate(x, y, Settings, count, out Double2 g, Tiled), Is.Not.NaN);
                Assert.That(g.x, Is.EqualTo(gx).Within(1e-4 * (1 + Math.Abs(gx))), "double gradient against finite differences");
            }
            TestContext.Out.WriteLine($"tiled octave noise: max |float - double| = {worst:E3}");
            Assert.That(worst, Is.LessThan(1e-5 * Settings.amplitude * 10));
        }

        [Test]
        public void TheTableHoldsEachCellsPolynomial()
        {
            // A broken row (here: the table read one cell over) must show: the tiled value at a cell
            // centre is the wrapped corners' noise, which a neighbour's row does not give.
            float[] t = GradientNoiseTable.Floats;
            Assert.That(t.Length, Is.EqualTo(256 * 256 * GradientNoiseTable.RowsPerCell * 4));
            int mismatched = 0;
            for (int y = 0; y < 256; y += 5)
                for (int x = 0; x < 256; x += 3)
                {
                    double reference = GradientNoise.Evaluate(x + 0.375, y + 0.625, out _, Tiled);
                    Assert.That(GradientNoise.Cell(x, y, 0.375f, 0.625f, out _, Tiled), Is.EqualTo(reference).Within(2e-6), $"cell ({x}, {y})");
                    if (Math.Abs(GradientNoise.Cell(x + 1, y, 0.375f, 0.625f, out _, Tiled) - reference) > 1e-4) mismatched++;
                }
            Assert.That(mismatched, Is.GreaterThan(1000), "a neighbouring cell's row is told apart");
        }
    }
}
