using System;
using System.Diagnostics;
using NUnit.Framework;

namespace GregoryTerrain.Tests
{
    /// <summary>
    /// Property tests with a fixed seed: random grids fitted to random smooth heightmaps, random
    /// ranges (widths from the whole terrain down to 1e-6): no NaN, G1 within tolerance, the float
    /// path (the shaders' arithmetic, absolute and deep-zoom relative) within tolerance of double.
    /// </summary>
    [TestFixture]
    public class PropertyTests
    {
        public const int Grids = 50, RangesPerGrid = 100;

        [Test]
        public void RandomGridsAndRangesStayFiniteG1AndCloseToDouble()
        {
            var rng = new Random(20240607);
            var clock = Stopwatch.StartNew();
            int iterations = 0;
            double worstAngle = 0, worstAbs = 0, worstRel = 0;
            for (int gi = 0; gi < Grids; gi++)
            {
                int cols = rng.Next(1, 5), rows = rng.Next(1, 5), samples = 9 + 4 * rng.Next(1, 4);
                PatchGrid g = HeightmapFitter.Fit(HardCaseGrids.Heightmap(samples, rng.Next()), samples, samples, cols, rows).Grid;
                double angle = ContinuityMeasure.MaxNormalAngleDegrees(g, 9);
                worstAngle = Math.Max(worstAngle, angle);
                Assert.That(angle, Is.LessThan(1e-6), $"grid {gi} is G1 (normal angle in degrees)");
                var fg = TerrainInputs.ForGrid(g);
                for (int ri = 0; ri < RangesPerGrid; ri++, iterations++)
                {
                    double w = Math.Pow(10, -6 * rng.NextDouble());
                    double c = rng.NextDouble() * (1 - w), d = rng.NextDouble() * (1 - w);
                    var range = new TerrainRange(c, d, Math.Min(c + w, 1), Math.Min(d + w, 1));
                    RangeOrigin o = RangeOrigin.For(range);
                    RangeMapping.EncodeRange(range, o, out Float4 rf, out Float4 of);
                    bool relative = RelativeSurface.IsActive(of);
                    Double3 reference = relative ? RelativeSurface.ReferencePoint(g, o) : default;
                    for (int k = 0; k < 9; k++)
                    {
                        float s = (float)rng.NextDouble(), t = (float)rng.NextDouble();
                        int ti = rng.Next(4), tj = rng.Next(4);
                        TerrainPoint q = RangeMapping.ToTerrainPoint(rf, of, 4, ti, tj, s, t);
                        Double3 exact = RelativeSurface.SurfaceAt(g, q.ToDouble());
                        Float3 abs = HardCaseGrids.FloatSurface(fg, q);
                        Assert.That(abs.IsFinite, Is.True, $"NaN/inf at {q}");
                        worstAbs = Math.Max(worstAbs, HardCaseGrids.Dist(abs, exact));
                        if (relative)
                        {
                            Float3 rel = RelativeSurface.FromOrigin(fg, q, of);
                            Assert.That(rel.IsFinite, Is.True);
                            worstRel = Math.Max(worstRel, TestPatches.MaxAbs(new Double3(rel.x, rel.y, rel.z) + reference - exact) / range.Width);
                        }
                    }
                }
            }
            // absolute float: q and heights ~1 rounded to float plus the float grid lines: 1e-6;
            // relative (deep zoom): 1e-5 of the range width (the GPU's float grid lines move the
            // surface by ~1e-8 * slope; the arithmetic itself keeps ~1e-7 of the width).
            TestContext.Out.WriteLine($"property iterations (grid, range): {iterations} over {Grids} grids, {clock.Elapsed.TotalSeconds:F1} s; " +
                $"max G1 angle {worstAngle:G3} deg, max |float - double| {worstAbs:G3}, max relative-path error {worstRel:G3} widths");
            Assert.That(worstAbs, Is.LessThan(1e-6));
            Assert.That(worstRel, Is.LessThan(1e-5));
            Assert.That(iterations, Is.EqualTo(Grids * RangesPerGrid));
        }
    }
}
