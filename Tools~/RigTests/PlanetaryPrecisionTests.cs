// Planetary precision (issue 28, "World units"): a 1,000 km terrain seen at the feet, ranges 1e-7,
// 1e-8 and 1e-9 of it wide (10 cm, 1 cm, 1 mm) on a 1920-pixel-wide view, patches 1e-6 (1 m) wide
// and a grid line at 0.13 (4.8e-9 off as one float) inside the view. Core's float path (the GPU's
// arithmetic, GpuPropertyTests keep the two equal) against an independent double evaluation of the
// same Gregory surface (PatchGrid in double, GregoryEval in double): the largest position error and
// the jitter of a panned view in pixels, and the largest normal error in radians. "before": the
// layout up to this change (absolute float control points, one float per grid line, FindPatch on the
// float point for the normal); "after": GpuLayout's relative points and hi/lo lines. Both printed;
// the test asserts the after (goal: < 0.5 px). Run: Tools~/gt test --filter PlanetaryPrecision.
using System;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    [TestFixture]
    public class PlanetaryPrecisionTests
    {
        const double Pixels = 1920, PanPixels = 0.25;
        const int Tiles = 4, Factor = 8, Frames = 8;
        const double PatchWidth = 1e-6;   // 1 m on a 1,000 km terrain
        const double LineX = 0.13, LineY = 0.62;

        /// <summary>Lines every 1e-6 around (0.13, 0.62), coarse elsewhere; heights with 1 m features and a km-scale offset.</summary>
        static PatchGrid PlanetaryGrid()
        {
            double[] xs = Lines(LineX), ys = Lines(LineY);
            PatchGrid g = PatchGrid.CreateFlat(xs.Length - 1, ys.Length - 1, xs, ys);
            foreach (GregoryPatch p in g.Patches)
                for (int k = 0; k < 20; k++)
                {
                    double x = p[k].x, y = p[k].y;
                    // 5 km above sea level (0.005), a regional slope, and 0.3 m bumps 3 m and 4 m long.
                    double z = 0.005 + 0.01 * x + 0.003 * y
                        + 0.3e-6 * Math.Sin(2 * Math.PI * x / 3e-6) * Math.Cos(2 * Math.PI * y / 4e-6);
                    p[k] = new Double3(x, y, z);
                }
            g.Validate();
            return g;
        }

        static double[] Lines(double at)
        {
            var l = new System.Collections.Generic.List<double> { 0.0, 0.5 * at };
            for (int k = -4; k <= 4; k++) l.Add(at + k * PatchWidth);
            l.Add(0.5 + 0.5 * at);
            l.Add(1.0);
            return l.ToArray();
        }

        /// <summary>The layout before: absolute float points (w = 0: no reference point), one float per line (lo = 0).</summary>
        static TerrainInputs BeforeLayout(PatchGrid g)
        {
            TerrainInputs after = TerrainInputs.ForGrid(g);
            var cps = new float[after.ControlPoints.Length];
            for (int p = 0; p < g.PatchCount; p++)
                for (int k = 0; k < 20; k++)
                {
                    long o = GpuLayout.ControlPointOffset(p, k);
                    cps[o] = (float)g.Patches[p][k].x;
                    cps[o + 1] = (float)g.Patches[p][k].y;
                    cps[o + 2] = (float)g.Patches[p][k].z;
                }
            var lines = (float[])after.GridLines.Clone();
            Array.Clear(lines, GpuLayout.GridLinesLoOffset(g.Columns, g.Rows), lines.Length / 2);
            return new TerrainInputs(cps, after.Regions, lines, after.Params);
        }

        /// <summary>The normal as the tile path computed it before: FindPatch on the rounded point, one-float region.</summary>
        static Float3 BeforeNormal(TerrainInputs before, TerrainPoint q)
        {
            int patch = before.FindPatch(RangeMapping.Approximate(q));
            Float4 region = before.PatchRegion(patch);
            Float2 uv = RangeMapping.PatchLocalUV(q, region);
            Span<Float3> cp = stackalloc Float3[GregoryPatch.SlotCount];
            before.LoadGregoryPatch(patch, cp);
            GregoryEval.Evaluate(cp, uv.x, uv.y, out _, out Float3 du, out Float3 dv);
            return GregoryEval.NormalFromDerivatives(du, dv);
        }

        static Float3 AfterNormal(TerrainInputs after, TerrainPoint q)
        {
            TerrainSurfacePoint s = TerrainVertex.EvaluateSurfaceAt(after, q);
            return GregoryEval.NormalFromDerivatives(s.dPdu, s.dPdv);
        }

        static TerrainRange Square(Double2 c, double w, double dx, double dy) =>
            new TerrainRange(c.x + dx - 0.5 * w, c.y + dy - 0.5 * w, c.x + dx + 0.5 * w, c.y + dy + 0.5 * w);

        struct Figures { public double error, jitter, normal; }

        /// <summary>Largest |float - double| position (px), jitter over panned frames (px), largest normal angle (rad).</summary>
        static Figures Measure(PatchGrid g, TerrainInputs inputs, bool before, Double2 centre, double width)
        {
            RangeOrigin origin = RangeOrigin.For(Square(centre, width, 0, 0));
            Assert.That(RelativeSurface.IsActive(origin.ToFloat4()), "a planetary range must use the relative output");
            Double3 reference = RelativeSurface.ReferencePoint(g, origin);
            double scale = Pixels / width, pan = PanPixels * width / Pixels;
            int across = Factor + 1;
            var first = new Double3[Tiles * Tiles * across * across];
            var f = new Figures();
            for (int frame = 0; frame <= Frames; frame++)
            {
                TerrainRange range = Square(centre, width, frame * pan, 0.5 * frame * pan);
                RangeMapping.EncodeRange(range, origin, out Float4 rangeF, out Float4 originF);
                int n = 0;
                for (int tj = 0; tj < Tiles; tj++)
                    for (int ti = 0; ti < Tiles; ti++)
                        for (int y = 0; y < across; y++)
                            for (int x = 0; x < across; x++, n++)
                            {
                                float s = (float)x / Factor, t = (float)y / Factor;
                                TerrainPoint q = RangeMapping.ToTerrainPoint(rangeF, originF, Tiles, ti, tj, s, t);
                                Float3 d = RelativeSurface.FromOrigin(inputs, q, originF);
                                Double3 p = reference + new Double3(d.x, d.y, d.z);
                                // The double evaluator at the exact point the float path formed.
                                TerrainVertex.Reference(g, q.ToDouble(), null, 0, out Double3 truth, out Double3 normal);
                                Double3 e = (p - truth) * scale;
                                f.error = Math.Max(f.error, Length(e));
                                if (frame == 0) first[n] = e;
                                else f.jitter = Math.Max(f.jitter, Length(e - first[n]));
                                if (frame > 0) continue;
                                Float3 nf = before ? BeforeNormal(inputs, q) : AfterNormal(inputs, q);
                                double dot = nf.x * normal.x + nf.y * normal.y + nf.z * normal.z;
                                double cross = Length(new Double3(nf.y * normal.z - nf.z * normal.y, nf.z * normal.x - nf.x * normal.z, nf.x * normal.y - nf.y * normal.x));
                                f.normal = Math.Max(f.normal, Math.Atan2(cross, dot));
                            }
            }
            return f;
        }

        static double Length(Double3 v) => Math.Sqrt(v.x * v.x + v.y * v.y + v.z * v.z);

        [TestCase(1e-7)]
        [TestCase(1e-8)]
        [TestCase(1e-9)]
        public void AThousandKilometreTerrainStaysStableAtTheFeet(double width)
        {
            PatchGrid g = PlanetaryGrid();
            TerrainInputs after = TerrainInputs.ForGrid(g), before = BeforeLayout(g);
            // On the float-rounded line 0.13 (4.8e-9 from the true one), on the line 0.62, inside a patch.
            foreach (Double2 c in new[] { new Double2((float)LineX, LineY + 0.3 * PatchWidth), new Double2(LineX + 0.37 * width, (float)LineY),
                                          new Double2(LineX + 0.5 * PatchWidth, LineY + 0.5 * PatchWidth) })
            {
                Figures b = Measure(g, before, true, c, width), a = Measure(g, after, false, c, width);
                TestContext.Out.WriteLine(FormattableString.Invariant(
                    $"planetary width {width:G1} centre ({c.x:R}, {c.y:R}): before error {b.error:G3} px jitter {b.jitter:G3} px normal {b.normal:G3} rad; after error {a.error:G3} px jitter {a.jitter:G3} px normal {a.normal:G3} rad"));
                Assert.That(a.jitter, Is.LessThan(0.5), "jitter after");
                Assert.That(a.error, Is.LessThan(0.5), "position error after");
                Assert.That(a.normal, Is.LessThan(1e-3), "normal error after");
            }
        }
    }
}
