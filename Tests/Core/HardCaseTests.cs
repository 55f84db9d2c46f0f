using System;
using NUnit.Framework;

namespace GregoryTerrain.Tests
{
    /// <summary>
    /// The named hard cases of the Core evaluation, each in float (the shaders' arithmetic) and double
    /// (the reference), each with its own stated bound. None may produce NaN or infinity. Every case
    /// prints one summary line: name, bound, measured error.
    /// </summary>
    [TestFixture]
    public class HardCaseTests
    {
        const float FloatMinSubnormal = 1.401298464e-45f;
        const double DoubleMinSubnormal = 4.9406564584124654e-324;
        static readonly (int du, int dv)[] Directions = { (1, 0), (0, 1), (1, 1), (1, 3), (3, 1) };

        static void Report(string name, double bound, double error)
        {
            TestContext.Out.WriteLine(FormattableString.Invariant($"hard case {name,-44} bound {bound,-9:G3} error {error:G3}"));
            Assert.That(error, Is.LessThanOrEqualTo(bound), name);
        }

        static void EvalBoth(GregoryPatch p, double u, double v, out Float3 f, out Double3 d, out Float3 fdu, out Float3 fdv)
        {
            GregoryEval.Evaluate(TestPatches.ToFloat(p), (float)u, (float)v, out f, out fdu, out fdv);
            GregoryEval.Evaluate(p.Points, u, v, out d, out Double3 ddu, out Double3 ddv);
            Assert.That(f.IsFinite && fdu.IsFinite && fdv.IsFinite, Is.True, $"float NaN/inf at ({u:R}, {v:R})");
            Assert.That(d.IsFinite && ddu.IsFinite && ddv.IsFinite, Is.True, $"double NaN/inf at ({u:R}, {v:R})");
        }

        static double MaxFloatVsDouble(GregoryPatch p, int samples = 17)
        {
            double worst = 0;
            for (int i = 0; i <= samples; i++)
                for (int j = 0; j <= samples; j++)
                {
                    EvalBoth(p, (double)i / samples, (double)j / samples, out Float3 f, out Double3 d, out _, out _);
                    worst = Math.Max(worst, HardCaseGrids.Dist(f, d));
                }
            return worst;
        }

        // ------------------------------------------------------------------ corners

        [Test]
        public void CornersExactInFloatAndDouble()
        {
            GregoryPatch p = TestPatches.Random(3);
            double worst = 0;
            foreach (var (u, v, slot) in new[] { (0.0, 0.0, 0), (0.0, 1.0, 3), (1.0, 0.0, 12), (1.0, 1.0, 15) })
            {
                EvalBoth(p, u, v, out Float3 f, out Double3 d, out _, out _);
                worst = Math.Max(worst, TestPatches.Dist(d, p[slot]));
                worst = Math.Max(worst, HardCaseGrids.Dist(f, (Double3)new Double3((float)p[slot].x, (float)p[slot].y, (float)p[slot].z)));
            }
            Report("corners exact (float, double)", 0.0, worst);
        }

        [TestCase(1e-7, TestName = "NearCorner_1e-7")]
        [TestCase(1e-20, TestName = "NearCorner_1e-20")]
        [TestCase(0.0, TestName = "NearCorner_SmallestSubnormal")]
        public void NearCornerAlongSeveralDirections(double distance)
        {
            GregoryPatch p = TestPatches.Random(4);
            double worstD = 0, worstF = 0;
            foreach (var (cu, cv, slot) in new[] { (0, 0, 0), (0, 1, 3), (1, 0, 12), (1, 1, 15) })
                foreach (var (du, dv) in Directions)
                {
                    double ed = distance > 0 ? distance : DoubleMinSubnormal;
                    float ef = distance > 0 ? (float)distance : FloatMinSubnormal;
                    // step into the square from the corner
                    double ud = cu == 0 ? du * ed : 1 - du * ed, vd = cv == 0 ? dv * ed : 1 - dv * ed;
                    GregoryEval.Evaluate(p.Points, ud, vd, out Double3 d, out Double3 ddu, out Double3 ddv);
                    Assert.That(d.IsFinite && ddu.IsFinite && ddv.IsFinite, Is.True);
                    worstD = Math.Max(worstD, TestPatches.Dist(d, p[slot]));
                    float uf = cu == 0 ? du * ef : 1f - du * ef, vf = cv == 0 ? dv * ef : 1f - dv * ef;
                    GregoryEval.Evaluate(TestPatches.ToFloat(p), uf, vf, out Float3 f, out Float3 fdu, out Float3 fdv);
                    Assert.That(f.IsFinite && fdu.IsFinite && fdv.IsFinite, Is.True);
                    worstF = Math.Max(worstF, HardCaseGrids.Dist(f, p[slot]));
                }
            // |S(corner + e d) - P| <= |S'| e |d| (|S'| <= 3 * 2 * 3 for points in [-1,1]^3) plus rounding:
            // double 1e-15, float 1e-6 (1 - 1e-7 itself is 1 - 1.19e-7 in float, and the control
            // points are rounded to float: half an ulp of 1, 6e-8).
            string label = distance > 0 ? distance.ToString("G3") : "smallest subnormal";
            Report($"near corner {label} double", 20 * Math.Max(distance, 1e-300) * 3 + 1e-15, worstD);
            Report($"near corner {label} float", 20 * Math.Max(distance, 1e-300) * 3 + 1e-6, worstF);
        }

        // ------------------------------------------------------------------ degenerate patches

        [Test]
        public void CollapsedEdge()
        {
            GregoryPatch p = TestPatches.Random(5);
            for (int j = 0; j < 4; j++) p[GregoryPatch.Slot(0, j)] = p[0];   // edge u = 0 collapsed to a point: corners 0 and 3 equal
            double err = MaxFloatVsDouble(p);
            Float3 n = GregoryEval.Normal(TestPatches.ToFloat(p), 0f, 0.5f);
            Assert.That(n.IsFinite, Is.True, "normal on the collapsed edge");
            Report("collapsed edge (float vs double)", 1e-6, err);
        }

        [Test]
        public void InteriorPairsFarApart()
        {
            GregoryPatch p = TestPatches.Random(6);
            foreach (int s in new[] { GregoryPatch.P111, GregoryPatch.P121, GregoryPatch.P211, GregoryPatch.P221 })
                p[s] = p[s] + new Double3(1e3, -1e3, 1e3);
            double err = MaxFloatVsDouble(p);
            Report("interior pairs 1e3 apart (float vs double)", 1e3 * 1e-6, err);
        }

        [TestCase(1e-9, TestName = "NearlyFlat")]
        [TestCase(1e6, TestName = "NearlyVertical")]
        public void FlatOrVertical(double heightScale)
        {
            GregoryPatch p = TestPatches.Random(7);
            for (int k = 0; k < 20; k++) p[k] = new Double3(p[k].x, p[k].y, p[k].z * heightScale);
            double err = MaxFloatVsDouble(p);
            Float3 n = GregoryEval.Normal(TestPatches.ToFloat(p), 0.3f, 0.6f);
            Assert.That(n.IsFinite, Is.True);
            Report($"height scale {heightScale:G3} (float vs double)", 1e-6 * Math.Max(1, heightScale), err);
        }

        // ------------------------------------------------------------------ regions

        /// <summary>Float surface via the shader path vs double surface at points of a range; max error.</summary>
        static double RangeError(PatchGrid g, TerrainRange range, int tiles, int factor)
        {
            var fg = TerrainInputs.ForGrid(g);
            RangeMapping.EncodeRange(range, RangeOrigin.For(range), out Float4 rf, out Float4 of);
            double worst = 0;
            for (int tj = 0; tj < tiles; tj++)
                for (int ti = 0; ti < tiles; ti++)
                    for (int y = 0; y <= factor; y++)
                        for (int x = 0; x <= factor; x++)
                        {
                            TerrainPoint q = RangeMapping.ToTerrainPoint(rf, of, tiles, ti, tj, (float)x / factor, (float)y / factor);
                            Assert.That(q.local.IsFinite, Is.True);
                            Float3 f = HardCaseGrids.FloatSurface(fg, q);
                            Assert.That(f.IsFinite, Is.True, $"NaN/inf at {q}");
                            Double3 d = RelativeSurface.SurfaceAt(g, q.ToDouble());
                            worst = Math.Max(worst, Math.Abs(f.z - d.z));
                        }
            return worst;
        }

        [Test]
        public void ExtremeAspectRatioRegion()
        {
            PatchGrid g = HardCaseGrids.WithLines(new[] { 0.0, 0.4, 0.401, 1.0 }, new[] { 0.0, 1.0 });   // 0.001 x 1
            double err = RangeError(g, new TerrainRange(0.399, 0.0, 0.402, 1.0), 4, 16);
            // float u in a 1e-3 wide patch: q resolves 3e-8, u 3e-5; the slope is 0.7, so 3e-8 in height, plus float rounding
            Report("region 1:1000 (height, float vs double)", 1e-7, err);
        }

        [Test]
        public void TinyRegion()
        {
            PatchGrid g = HardCaseGrids.WithLines(new[] { 0.0, 0.5, 0.5 + 1e-6, 1.0 }, new[] { 0.0, 0.5, 0.5 + 1e-6, 1.0 });
            double err = RangeError(g, new TerrainRange(0.5 - 1e-6, 0.5 - 1e-6, 0.5 + 2e-6, 0.5 + 2e-6), 3, 8);
            // the GPU's float lines 0.5 + 1e-6 differ from the double ones by up to 3e-8 (slope 0.7)
            Report("region 1e-6 of the terrain (height)", 1e-7, err);
        }

        [Test]
        public void RangeTouchingTheTerrainEdge()
        {
            PatchGrid g = HardCaseGrids.Fitted();
            double err = Math.Max(RangeError(g, new TerrainRange(0.9, 0.0, 1.0, 0.1), 4, 8), RangeError(g, TerrainRange.full, 4, 8));
            // the far corner q = 1 exactly lands on the last patch's corner: the control point, as
            // the reference point plus its float difference from it (one rounding each)
            var fg = TerrainInputs.ForGrid(g);
            RangeMapping.EncodeRange(TerrainRange.full, RangeOrigin.zero, out Float4 rf, out Float4 of);
            Float3 corner = HardCaseGrids.FloatSurface(fg, RangeMapping.ToTerrainPoint(rf, of, 4, 3, 3, 1f, 1f));
            Assert.That(corner.z, Is.EqualTo((float)g.Patches[g.PatchCount - 1][15].z).Within(1e-8f));   // half an ulp of P - R_p plus half of the sum
            Report("range touching the terrain edge (height)", 1e-6, err);
        }

        [Test]
        public void RangeOfOnePatch()
        {
            PatchGrid g = HardCaseGrids.Fitted();
            Region r = g.RegionOf(2, 1);
            double err = RangeError(g, new TerrainRange(r.a, r.b, r.e, r.f), 2, 16);
            Report("range = one patch (height)", 1e-6, err);
        }

        [Test]
        public void RangeSmallerThanOneVertexSpacing()
        {
            PatchGrid g = HardCaseGrids.Fitted();
            double w = 1e-9;   // far below a vertex spacing of a whole-terrain view (1/512)
            var range = new TerrainRange(0.3, 0.7, 0.3 + w, 0.7 + w);
            RangeMapping.EncodeRange(range, RangeOrigin.For(range), out Float4 rf, out Float4 of);
            double prev = double.NegativeInfinity, worst = 0;
            for (int x = 0; x <= 16; x++)
            {
                Double2 q = RangeMapping.ToTerrainPoint(rf, of, 1, 0, 0, x / 16f, 0f).ToDouble();
                Assert.That(q.x, Is.GreaterThan(prev), "vertices stay ordered");
                prev = q.x;
                worst = Math.Max(worst, Math.Abs(q.x - (0.3 + w * x / 16)));
            }
            double err = RangeError(g, range, 1, 16);
            Report("range 1e-9 wide: q error", 1e-15, worst);
            Report("range 1e-9 wide: height (float vs double)", 1e-7, err);
        }

        // ------------------------------------------------------------------ large coordinates

        [TestCase(1e5, TestName = "TerrainOf1e5Metres")]
        [TestCase(1e6, TestName = "TerrainOf1e6Metres")]
        public void LargeTerrainCoordinates(double metres)
        {
            GregoryPatch p = TestPatches.Random(8);
            for (int k = 0; k < 20; k++) p[k] = p[k] * metres;
            double err = MaxFloatVsDouble(p);
            // float keeps ~1e-7 relative: bound 1e-6 of the scale (0.1 m at 1e5 m, 1 m at 1e6 m)
            Report($"terrain of {metres:G3} m (float vs double, m)", 1e-6 * metres, err);
        }

        // ------------------------------------------------------------------ noise

        [Test]
        public void NoiseAtCoordinate1e6()
        {
            var s = new NoiseSettings(1f, 1e6f, 2f, 2f, 1);   // lattice coordinate ~1e6 at q ~ 1
            double worst = 0;
            for (int k = 0; k < 200; k++)
            {
                double x = 0.5 + k * 1.37e-7, y = 0.75 - k * 0.91e-7;
                var q = new TerrainPoint(new Float2((float)x, (float)y), new Float2((float)(x - (float)x), (float)(y - (float)y)));
                float f = OctaveNoise.Evaluate(q, s, 1f, out Float2 g);
                Assert.That(GMath.isfinite(f) && g.IsFinite, Is.True);
                Double2 qd = q.ToDouble();
                double d = OctaveNoise.Evaluate(qd.x, qd.y, s, 1.0, out _);
                worst = Math.Max(worst, Math.Abs(f - d));
            }
            // lattice fraction from the exact TwoProduct split: ~1e-7 of a cell, gradient <= ~2 per cell
            Report("noise at lattice coordinate 1e6", 1e-5, worst);
        }

        [Test]
        public void NoiseWith12Octaves()
        {
            var s = new NoiseSettings(0.01f, 8f, 2f, 2f, 12);
            double worst = 0;
            for (int k = 0; k < 200; k++)
            {
                double x = 0.123 + k * 0.00391, y = 0.877 - k * 0.00277;
                float f = OctaveNoise.Evaluate(TerrainPoint.FromFloat(new Float2((float)x, (float)y)), s, 12f, out Float2 g);
                Assert.That(GMath.isfinite(f) && g.IsFinite, Is.True);
                Double2 qd = new Double2((float)x, (float)y);
                worst = Math.Max(worst, Math.Abs(f - OctaveNoise.Evaluate(qd.x, qd.y, s, 12.0, out _)));
            }
            // top octave 8 * 2^11 = 16384 cells: float q (6e-8) is 1e-3 of a cell there, weight 2^-11
            Report("noise with 12 octaves (float vs double)", 1e-6, worst);
        }

        // ------------------------------------------------------------------ tessellation

        [TestCase(1f, TestName = "Factor1")]
        [TestCase(64f, TestName = "Factor64")]
        [TestCase(63.5f, TestName = "Factor63.5Fractional")]
        public void FactorsAndTileLayout(float factor)
        {
            // the factor functions hit their clamps exactly and never NaN
            Assert.That(TessellationPolicy.EdgeFactor(factor * 8f, 8f, 64f), Is.EqualTo(factor));
            Assert.That(TessellationPolicy.EdgeFactor(1e-30f, 8f, 64f), Is.EqualTo(1f));
            Assert.That(TessellationPolicy.EdgeFactor(float.PositiveInfinity, 8f, 64f), Is.EqualTo(64f));
            // tile layout at this factor: shared edges bit-identical, vertices ordered (integer
            // partitioning: k / F; fractional: the odd-partition points, here k / factor clipped at 1)
            int tiles = 8, count = (int)Math.Ceiling(factor);
            double worst = 0;
            for (int ti = 0; ti < tiles - 1; ti++)
            {
                Float2 end = RangeMapping.RangeCoordinate(ti, 0, 1f, 0f, tiles);
                Float2 start = RangeMapping.RangeCoordinate(ti + 1, 0, 0f, 0f, tiles);
                Assert.That(end.x, Is.EqualTo(start.x), "shared tile edge bit-identical");
                float prev = -1f;
                for (int k = 0; k <= count; k++)
                {
                    float s = Math.Min(k / factor, 1f);
                    Float2 o = RangeMapping.RangeCoordinate(ti, 0, s, 0f, tiles);
                    Assert.That(o.x, Is.GreaterThanOrEqualTo(prev));
                    prev = o.x;
                    worst = Math.Max(worst, Math.Abs(o.x - (ti + (double)s) / tiles));
                }
            }
            Report($"tile layout at factor {factor}", 6e-8, worst);
        }

        [Test]
        public void CameraInsideTheBoxAndOnAPatchEdge()
        {
            var screen = new Float2(800f, 600f);
            // endpoints at, behind and on the eye plane: w <= 0
            var cases = new[]
            {
                (new Float4(0.1f, 0.2f, 0.5f, 0f), new Float4(0.3f, -0.2f, 0.5f, 0f)),     // both on the eye plane (camera on the edge)
                (new Float4(0.1f, 0.2f, 0.5f, -1f), new Float4(0.3f, -0.2f, 0.5f, 2f)),    // one behind (camera inside the box)
                (new Float4(0f, 0f, 0f, 0f), new Float4(0f, 0f, 0f, 0f)),                  // degenerate: the camera at both endpoints
                (new Float4(1e-30f, 0f, 0f, 1e-38f), new Float4(0f, 1e-30f, 0f, 1e-38f)),   // nearly on the plane: huge NDC
            };
            foreach (var (a, b) in cases)
            {
                float f1 = TessellationPolicy.EdgeTessFactor(a, b, screen, 8f, 64f);
                float f2 = TessellationPolicy.EdgeTessFactor(b, a, screen, 8f, 64f);
                Assert.That(GMath.isfinite(f1), Is.True, $"{a} {b}");
                Assert.That(f1, Is.EqualTo(f2), "symmetric");
                Assert.That(f1, Is.InRange(1f, 64f));
            }
            // a box around the camera (corners on both sides of the eye plane) is never culled
            var box = new Float4[8];
            for (int i = 0; i < 8; i++) box[i] = new Float4((i & 1) == 0 ? -1f : 1f, (i & 2) == 0 ? -1f : 1f, 0.5f, (i & 4) == 0 ? -0.5f : 0.5f);
            Assert.That(TessellationPolicy.BoxOutsideFrustum(box, 0f), Is.False);
            for (int i = 0; i < 8; i++) box[i] = new Float4(0f, 0f, 0f, 0f);   // camera exactly at a flat tile
            Assert.That(TessellationPolicy.BoxOutsideFrustum(box, 0f), Is.False);
            Report("camera inside the box / on a patch edge (NaN count)", 0, 0);
        }
    }
}
