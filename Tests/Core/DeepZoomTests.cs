using System;
using NUnit.Framework;

namespace GregoryTerrain.Tests
{
    /// <summary>
    /// Deep zoom (precision.md): the difference evaluation against the double reference. The
    /// vertex jitter table (plain float vs the shipped path) is the rig's: ZoomJitterTests.
    /// </summary>
    [TestFixture]
    public class DeepZoomTests
    {
        static PatchGrid _grid;
        static PatchGrid Grid => _grid ??= HardCaseGrids.Fitted();

        // The renderer's keyword rule (GT_RANGE_ORIGIN): on exactly while the origin it sends
        // is set, so the stages that compile no origin code never see one; under the levels or the vertex
        // cache off (GT_LOD and GT_VERTEX_CACHE compile that code; the three are one keyword set, so a
        // cache or levels variant with the origin's keyword would be compiled and never drawn).
        // A wide range sends 0, a deep one a snapped origin.
        [Test]
        public void TheRangeOriginKeywordIsOnExactlyWhileAnOriginIsSent()
        {
            foreach (double w in new[] { 1.0, 0.1, 2 * RangeOrigin.DeepWidth, RangeOrigin.DeepWidth, 0.5 * RangeOrigin.DeepWidth, 1e-6, 1e-9 })
                foreach (double c in new[] { 0.0, 0.3 * (1.0 - w), 1.0 - w })
                {
                    var range = new TerrainRange(c, c, c + w, c + w);
                    RangeOrigin o = RangeOrigin.For(range);
                    RangeMapping.EncodeRange(range, o, out Float4 rangeF, out Float4 originF);
                    bool deep = w < RangeOrigin.DeepWidth && !(o.Equals(RangeOrigin.zero));
                    Assert.That(RelativeSurface.NeedsRangeOriginKeyword(originF, false, false), Is.EqualTo(RelativeSurface.IsActive(originF)), $"w {w} c {c}");
                    Assert.That(RelativeSurface.NeedsRangeOriginKeyword(originF, false, false), Is.EqualTo(deep), $"w {w} c {c}: keyword on for a deep range only");
                    Assert.That(RelativeSurface.NeedsRangeOriginKeyword(originF, true, false), Is.False, $"w {w} c {c}: the levels' GT_LOD instead");
                    Assert.That(RelativeSurface.NeedsRangeOriginKeyword(originF, false, true), Is.False, $"w {w} c {c}: the cache's GT_VERTEX_CACHE instead");
                }
            Assert.That(RelativeSurface.NeedsRangeOriginKeyword(new Float4(0f, 0f, 1e-30f, 0f), false, false), Is.True, "a lo part alone is an origin");
        }

        [Test]
        public void BernsteinDifferenceMatchesTheDefinitionInDouble()
        {
            Span<double> b = stackalloc double[4], db = stackalloc double[4];
            foreach (double t0 in new[] { 0.0, 0.3, 0.999, 1.0 })
                foreach (double dt in new[] { -0.3, 1e-7, 0.25 })
                {
                    GregoryDifference.BernsteinDifference(t0, dt, b, db);
                    for (int i = 0; i < 4; i++)
                        Assert.That(db[i], Is.EqualTo(TestPatches.B3(i, t0 + dt) - TestPatches.B3(i, t0)).Within(1e-14), $"i {i} t0 {t0} dt {dt}");
                }
        }

        [Test]
        public void DifferenceOfRandomPatchesMatchesTwoDoubleEvaluations()
        {
            var rng = new Random(7);
            double worst = 0;
            for (int n = 0; n < 400; n++)
            {
                GregoryPatch p = TestPatches.Random(n);
                double u0 = rng.NextDouble(), v0 = rng.NextDouble();
                if (n % 4 == 0) { u0 = 0; v0 = rng.NextDouble() < 0.5 ? 0 : 1; }   // corners: the pair guard
                double du = (rng.NextDouble() - 0.5) * Math.Pow(10, -rng.Next(0, 8)), dv = (rng.NextDouble() - 0.5) * Math.Pow(10, -rng.Next(0, 8));
                du = Math.Clamp(u0 + du, 0, 1) - u0; dv = Math.Clamp(v0 + dv, 0, 1) - v0;
                Double3 d = GregoryDifference.Evaluate(p.Points, u0, v0, du, dv);
                Double3 r = GregoryEval.Position(p.Points, u0 + du, v0 + dv) - GregoryEval.Position(p.Points, u0, v0);
                worst = Math.Max(worst, TestPatches.Dist(d, r));
                Float3 f = GregoryDifference.Evaluate(TestPatches.ToFloat(p), (float)u0, (float)v0, (float)du, (float)dv);
                Assert.That(f.IsFinite, Is.True);
                // float: relative to the step (|S'| <= ~10 for points in [-1, 1]) plus the float rounding of u0
                double step = Math.Max(Math.Abs(du), Math.Abs(dv));
                Assert.That(HardCaseGrids.Dist(f, r), Is.LessThanOrEqualTo(40 * step * 1.2e-7 + 1e-6 * step + 1e-12), $"n {n} u0 {u0} du {du}");
            }
            Assert.That(worst, Is.LessThan(1e-13));
            TestContext.Out.WriteLine($"difference vs two double evaluations: max {worst:G3} (double) over 400 random patches and steps");
        }

        [Test]
        public void RelativeSurfaceMatchesTheDoubleReferenceAcrossPatchLines()
        {
            var fg = TerrainInputs.ForGrid(Grid);
            foreach (var c in new[] { new Double2(0.5137, 0.6262), new Double2(0.4, 0.6), new Double2(0.2, 0.2 + 3e-8) })
                foreach (double w in new[] { 1e-3, 1e-6 })
                {
                    var range = new TerrainRange(c.x - w / 2, c.y - w / 2, c.x + w / 2, c.y + w / 2);
                    RangeOrigin o = RangeOrigin.For(range);
                    RangeMapping.EncodeRange(range, o, out Float4 rf, out Float4 of);
                    double worst = 0;
                    for (int k = 0; k <= 16; k++)
                        for (int l = 0; l <= 16; l++)
                        {
                            float s = k / 16f, t = l / 16f;
                            TerrainPoint q = RangeMapping.ToTerrainPoint(rf, of, 1, 0, 0, s, t);
                            Float3 d = RelativeSurface.FromOrigin(fg, q, of);
                            Double3 r = RelativeSurface.FromOrigin(Grid, q.ToDouble(), o.Value);
                            worst = Math.Max(worst, HardCaseGrids.Dist(d, r));
                        }
                    // Bound: the GPU's float grid lines and control points move the surface by ~1e-8 * slope
                    // (systematic, the same in every frame), far below it the difference arithmetic.
                    Assert.That(worst / w, Is.LessThan(1e-5), $"centre {c} width {w}");
                    TestContext.Out.WriteLine($"relative surface centre {c} width {w:G3}: max |float - double| = {worst:G3} = {worst / w:G3} widths");
                }
        }

        [TestCase(false)]
        [TestCase(true)]   // the tiled noise: octaves 4 on span the table's 256 cells, x = 0.5 is on its seams
        public void RelativeNoiseMatchesTheDoubleDifference(bool tiled)
        {
            TerrainKeywords keywords = tiled ? TerrainKeywords.NoiseTable : TerrainKeywords.None;
            // p(q) - p(O) in float against two double evaluations, at deep zoom, with O in the middle
            // and q across lattice lines of the coarse octaves (range straddling x = 0.5 = cell 8 of 16).
            var noise = new NoiseSettings(0.004f, 16f, 2f, 2f, 12);
            double worst = 0, w = 1e-6;
            foreach (var c in new[] { new Double2(0.5, 0.5 + 1e-7), new Double2(0.5137, 0.6262), new Double2(0.3, 0.7) })
            {
                var range = new TerrainRange(c.x - w / 2, c.y - w / 2, c.x + w / 2, c.y + w / 2);
                RangeOrigin o = RangeOrigin.For(range);
                RangeMapping.EncodeRange(range, o, out Float4 rf, out Float4 of);
                TerrainPoint origin = RelativeSurface.OriginPoint(of);
                for (int k = 0; k <= 16; k++)
                    for (int l = 0; l <= 16; l++)
                    {
                        TerrainPoint q = RangeMapping.ToTerrainPoint(rf, of, 1, 0, 0, k / 16f, l / 16f);
                        float f = OctaveNoise.Relative(q, origin, RelativeSurface.Difference(q, origin), noise, 12f, out Float2 g, keywords);
                        Assert.That(GMath.isfinite(f) && g.IsFinite, Is.True);
                        Double2 qd = q.ToDouble(), od = o.Value;
                        double d = OctaveNoise.Evaluate(qd.x, qd.y, noise, 12.0, out _, keywords) - OctaveNoise.Evaluate(od.x, od.y, noise, 12.0, out _, keywords);
                        worst = Math.Max(worst, Math.Abs(f - d));
                    }
            }
            // 1e-5 of the width (0.008 px of an 800-px view); the absolute float noise errs by ~2e-10 (0.2 px)
            TestContext.Out.WriteLine($"relative noise (12 octaves, width 1e-6, tiled {tiled}): max |float - double difference| = {worst:G3} = {worst / w:G3} widths");
            Assert.That(worst / w, Is.LessThan(1e-5));
        }
    }
}
