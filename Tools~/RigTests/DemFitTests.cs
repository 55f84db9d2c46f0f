using System;
using System.IO;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>
    /// The fitter on real elevation data: two adjacent SRTM3 crops (Tools~/RigTests/Data/dem/README.md), 241 x 241
    /// samples each, sharing their seam column: no NaN, G1 after enforcement, voids filled rather
    /// than fitted into spikes, the two tiles fitted one after the other join G1, and the error
    /// against the bilinear baseline. Half of issue 27's goal is met and asserted: the max error is at
    /// most the baseline's at every patch count (the fit's reweighting rounds, FitObjective.BoundedMax)
    /// with the RMS at most the baseline's. The other half (RMS at most half the baseline's) is NOT
    /// met and not claimed: the G1 Gregory nets have about 7 unknowns a patch against the baseline
    /// lattice's 9, and on this rough terrain the fit's RMS is 0.93 to 0.97 of the baseline's
    /// (manual, Fitting). The RMS must also stay below the previous C1 spline's.
    /// </summary>
    [TestFixture]
    public class DemFitTests
    {
        public const int Side = 241;
        // 3 arc-seconds at 48.7 N: 92.6 m north-south, 61.2 m east-west. The crops' width in metres
        // scales z into the unit square's units for the angle checks (G1 is kept by any z scale).
        const double CropWidthMetres = 240 * 61.2;
        /// <summary>Normals across shared edges may differ by rounding only: the spline is C1.</summary>
        const double G1BoundDegrees = 1e-6;
        /// <summary>Issue 27's max goal (no worse than the baseline) and the RMS the reweighting keeps (at most the baseline's).</summary>
        const double RmsRatioBound = 1.0, MaxRatioBound = 1.0;

        // The crops live with the rig, not in Tests/ (232 KB the package would ship for one test class).
        static string DataPath(string name) => PackageRoot.Combine("Tools~", "RigTests", "Data", "dem", name);

        /// <summary>A crop's heights in metres, voids as NaN (not yet filled).</summary>
        public static double[] LoadRaw(string name)
        {
            string path = DataPath(name);
            byte[] bytes = File.ReadAllBytes(path);
            int w = 0, h = 0;
            RawHeightmap.InferSize(name, bytes.Length, RawSampleFormat.Int16BigEndian, ref w, ref h);
            Assert.That((w, h), Is.EqualTo((Side, Side)));
            return RawHeightmap.Decode(name, bytes, w, h, RawSampleFormat.Int16BigEndian, RawHeightmap.SrtmVoid);
        }

        public static double[] Load(string name)
        {
            double[] a = LoadRaw(name);
            HeightmapVoids.Fill(a, Side, Side);
            return a;
        }

        public static readonly string West = "N48E009_east.hgt", East = "N48E010_west.hgt";

        /// <summary>
        /// The baseline the goals compare with: a (3P+1) x (3Q+1) lattice as dense as the control net,
        /// each node the mean of the samples nearest it (a box of one lattice spacing), interpolated
        /// bilinearly at every sample.
        /// </summary>
        public static void BilinearBaseline(double[] z, int w, int h, int columns, int rows, out double max, out double rms)
        {
            int lx = 3 * columns + 1, ly = 3 * rows + 1;
            var sum = new double[lx * ly];
            var count = new int[lx * ly];
            for (int r = 0; r < h; r++)
                for (int c = 0; c < w; c++)
                {
                    int a = (int)Math.Round((double)c * (lx - 1) / (w - 1)), b = (int)Math.Round((double)r * (ly - 1) / (h - 1));
                    sum[b * lx + a] += z[r * w + c];
                    count[b * lx + a]++;
                }
            for (int k = 0; k < sum.Length; k++)
                Assert.That(count[k], Is.GreaterThan(0), "baseline lattice node without samples: lattice denser than the samples");
            max = 0;
            double s2 = 0;
            for (int r = 0; r < h; r++)
                for (int c = 0; c < w; c++)
                {
                    double X = (double)c * (lx - 1) / (w - 1), Y = (double)r * (ly - 1) / (h - 1);
                    int a = Math.Min((int)X, lx - 2), b = Math.Min((int)Y, ly - 2);
                    double tx = X - a, ty = Y - b;
                    double m(int i, int j) => sum[j * lx + i] / count[j * lx + i];
                    double f = (1 - ty) * ((1 - tx) * m(a, b) + tx * m(a + 1, b)) + ty * ((1 - tx) * m(a, b + 1) + tx * m(a + 1, b + 1));
                    double e = Math.Abs(f - z[r * w + c]);
                    max = Math.Max(max, e);
                    s2 += e * e;
                }
            rms = Math.Sqrt(s2 / ((double)w * h));
        }

        /// <summary>Max |grid - sample| by evaluating the Gregory patches themselves, and whether any z is NaN.</summary>
        internal static double GridMaxError(PatchGrid g, double[] z, int w, int h)
        {
            double max = 0;
            for (int r = 0; r < h; r++)
                for (int c = 0; c < w; c++)
                {
                    double x = (double)c / (w - 1), y = (double)r / (h - 1);
                    int p = g.FindPatch(x, y);
                    Region reg = g.RegionOf(p);
                    double e = Math.Abs(GregoryEval.Position(g.Patches[p].Points, (x - reg.a) / reg.Width, (y - reg.b) / reg.Height).z - z[r * w + c]);
                    Assert.That(double.IsNaN(e), Is.False, $"NaN at sample ({c}, {r})");
                    max = Math.Max(max, e);
                }
            return max;
        }

        /// <summary>Per sample column, the largest |grid - sample| over its rows, evaluating the Gregory patches themselves.</summary>
        internal static double[] ColumnMaxErrors(PatchGrid g, double[] z, int w, int h)
        {
            var max = new double[w];
            for (int r = 0; r < h; r++)
                for (int c = 0; c < w; c++)
                {
                    double x = (double)c / (w - 1), y = (double)r / (h - 1);
                    int p = g.FindPatch(x, y);
                    Region reg = g.RegionOf(p);
                    double e = Math.Abs(GregoryEval.Position(g.Patches[p].Points, (x - reg.a) / reg.Width, (y - reg.b) / reg.Height).z - z[r * w + c]);
                    Assert.That(double.IsNaN(e), Is.False, $"NaN at sample ({c}, {r})");
                    max[c] = Math.Max(max[c], e);
                }
            return max;
        }

        /// <summary>RMS of a C1 spline over the samples, evaluated on its own Bezier grid.</summary>
        internal static double SplineRms(SplineSurface s, double[] z, int w, int h)
        {
            PatchGrid g = s.ToPatchGrid();
            double s2 = 0;
            for (int r = 0; r < h; r++)
                for (int c = 0; c < w; c++)
                {
                    double x = (double)c / (w - 1), y = (double)r / (h - 1);
                    int p = g.FindPatch(x, y);
                    Region reg = g.RegionOf(p);
                    double e = GregoryEval.Position(g.Patches[p].Points, (x - reg.a) / reg.Width, (y - reg.b) / reg.Height).z - z[r * w + c];
                    s2 += e * e;
                }
            return Math.Sqrt(s2 / ((double)w * h));
        }

        /// <summary>The grid with z divided by the crop's width in metres, so x, y, z share units for angles.</summary>
        internal static PatchGrid InUnitSquareUnits(PatchGrid g, double widthMetres)
        {
            PatchGrid s = g.Clone();
            foreach (GregoryPatch p in s.Patches)
                for (int k = 0; k < GregoryPatch.SlotCount; k++) p[k] = new Double3(p[k].x, p[k].y, p[k].z / widthMetres);
            return s;
        }

        [TestCase("N48E009_east.hgt", 8)]
        [TestCase("N48E009_east.hgt", 16)]
        [TestCase("N48E009_east.hgt", 32)]
        [TestCase("N48E010_west.hgt", 8)]
        [TestCase("N48E010_west.hgt", 16)]
        [TestCase("N48E010_west.hgt", 32)]
        public void BelowTheBilinearBaselineRmsAndG1(string tile, int patches)
        {
            double[] z = Load(tile);
            HeightmapFit fit = HeightmapFitter.Fit(z, Side, Side, patches, patches);
            BilinearBaseline(z, Side, Side, patches, patches, out double bMax, out double bRms);
            double gridMax = GridMaxError(fit.Grid, z, Side, Side);
            // Enforcement as the window runs it: MakeG1 on the grid in terrain units.
            PatchGrid enforced = InUnitSquareUnits(fit.Grid, CropWidthMetres);
            double before = ContinuityMeasure.MaxNormalAngleDegrees(enforced);
            G1Builder.MakeG1(enforced);
            double angle = ContinuityMeasure.MaxNormalAngleDegrees(enforced);
            double moved = 0;
            for (int p = 0; p < enforced.PatchCount; p++)
                for (int k = 0; k < GregoryPatch.SlotCount; k++)
                    moved = Math.Max(moved, Math.Abs(enforced.Patches[p][k].z * CropWidthMetres - fit.Grid.Patches[p][k].z));
            // The previous fitter's surface: the C1 spline the fit starts from.
            double splineRms = SplineRms(fit.Surface, z, Side, Side);
            TestContext.Out.WriteLine($"{tile} {patches}x{patches}: fit max {fit.MaxError:F2} m RMS {fit.RmsError:F3} m; bilinear baseline max {bMax:F2} m RMS {bRms:F3} m (ratios {fit.MaxError / bMax:F2}, {fit.RmsError / bRms:F2}); C1 spline RMS {splineRms:F3} m; least squares alone max {fit.LeastSquaresMax:F2} m RMS {fit.LeastSquaresRms:F3} m, {fit.ReweightRounds} reweighting rounds; Gregory evaluation max {gridMax:F2} m; G1 angle {before:E2} deg, after MakeG1 {angle:E2} deg, which moved points by {moved:E1} m; {fit.Iterations} CG iterations");
            Assert.That(fit.RmsError, Is.LessThanOrEqualTo(RmsRatioBound * bRms), "RMS against the bilinear baseline's");
            Assert.That(fit.RmsError, Is.LessThan(0.99 * splineRms), "RMS against the C1 spline's (the previous fit)");
            Assert.That(fit.MaxError, Is.LessThanOrEqualTo(MaxRatioBound * bMax), "max against the bilinear baseline's");
            Assert.That(fit.BaselineMax, Is.EqualTo(bMax), "the fitter's own baseline (what it holds the max to) is this one");
            Assert.That(fit.BaselineRms, Is.EqualTo(bRms).Within(1e-12 * bRms));
            Assert.That(before, Is.LessThan(G1BoundDegrees), "the fitted grid itself is G1");
            Assert.That(moved, Is.LessThan(1e-6), "MakeG1 should find the fitted grid G1 already");
            Assert.That(gridMax, Is.EqualTo(fit.MaxError).Within(1e-6 * fit.MaxError + 1e-9), "the grid's patches disagree with the reported error");
            Assert.That(angle, Is.LessThan(G1BoundDegrees));
            Assert.That(ContinuityMeasure.MaxPositionGap(fit.Grid), Is.EqualTo(0.0));
            foreach (float e in fit.ErrorMap.Cells) Assert.That(e, Is.GreaterThanOrEqualTo(0f).And.LessThanOrEqualTo((float)fit.MaxError));
        }

        [Test]
        public void VoidsAreFilledWithinTheirNeighboursRange()
        {
            double[] raw = LoadRaw(East);
            int voids = 0;
            foreach (double v in raw) if (double.IsNaN(v)) voids++;
            Assert.That(voids, Is.EqualTo(6), "the east crop has 6 SRTM voids (README)");
            var ex = Assert.Throws<ArgumentException>(() => HeightmapFitter.Fit(raw, Side, Side, 8, 8));
            Assert.That(ex.Message, Does.Contain("not finite").And.Contain("void"));

            double[] filled = (double[])raw.Clone();
            Assert.That(HeightmapVoids.Fill(filled, Side, Side), Is.EqualTo(6));
            for (int k = 0; k < raw.Length; k++)
            {
                if (!double.IsNaN(raw[k])) { Assert.That(filled[k], Is.EqualTo(raw[k])); continue; }
                // Within the range of the known samples up to 3 away: no spike.
                int c = k % Side, r = k / Side;
                double lo = double.MaxValue, hi = double.MinValue;
                for (int dr = -3; dr <= 3; dr++)
                    for (int dc = -3; dc <= 3; dc++)
                    {
                        int cc = c + dc, rr = r + dr;
                        if (cc < 0 || rr < 0 || cc >= Side || rr >= Side || double.IsNaN(raw[rr * Side + cc])) continue;
                        lo = Math.Min(lo, raw[rr * Side + cc]);
                        hi = Math.Max(hi, raw[rr * Side + cc]);
                    }
                Assert.That(filled[k], Is.InRange(lo, hi), $"void at ({c}, {r})");
            }
        }

        [TestCase(8)]
        [TestCase(32)]
        public void TilesFittedOneAfterTheOtherJoinG1(int patches)
        {
            double[] zw = Load(West), ze = Load(East);
            HeightmapFit west = HeightmapFitter.Fit(zw, Side, Side, patches, patches);
            HeightmapFit east = HeightmapFitter.FitEastOf(west, ze, Side, Side, patches);
            PatchGrid joined = InUnitSquareUnits(PatchGridJoin.WestEast(west.Grid, east.Grid, 0.5), 2 * CropWidthMetres);
            double angle = ContinuityMeasure.MaxNormalAngleDegrees(joined);
            BilinearBaseline(ze, Side, Side, patches, patches, out double bMax, out double bRms);
            // Fitted on their own, the tiles meet with a step and a kink: what the join prevents.
            HeightmapFit alone = HeightmapFitter.Fit(ze, Side, Side, patches, patches);
            PatchGrid naive = InUnitSquareUnits(PatchGridJoin.WestEast(west.Grid, alone.Grid, 0.5), 2 * CropWidthMetres);
            double naiveAngle = ContinuityMeasure.MaxNormalAngleDegrees(naive);
            TestContext.Out.WriteLine($"{patches}x{patches}: joined angle {angle:E2} deg, gap {ContinuityMeasure.MaxPositionGap(joined):E2}; east fit max {east.MaxError:F2} m RMS {east.RmsError:F3} m (alone {alone.MaxError:F2} / {alone.RmsError:F3}; baseline {bMax:F2} / {bRms:F3}); fitted apart: angle {naiveAngle:F3} deg, gap {ContinuityMeasure.MaxPositionGap(naive) * 2 * CropWidthMetres:F2} m");
            Assert.That(angle, Is.LessThan(G1BoundDegrees));
            Assert.That(ContinuityMeasure.MaxPositionGap(joined), Is.EqualTo(0.0));
            Assert.That(naiveAngle, Is.GreaterThan(100 * G1BoundDegrees), "the check could not fail: tiles fitted apart already join G1");
            // Holding the seam costs the east tile a little accuracy near it (measured: 7% RMS at 8 x 8).
            Assert.That(east.RmsError, Is.LessThanOrEqualTo(1.1 * alone.RmsError));
            Assert.That(east.RmsError, Is.GreaterThanOrEqualTo(alone.RmsError), "a constrained fit cannot beat the free least-squares one");
        }

        /// <summary>
        /// Why the east tile fitted against a held seam is worse than fitted alone: the excess is the
        /// west fit's edge, fitted from one side. For a height field G1 means the same slope across the
        /// seam too, so the east fit cannot leave the held line: its error on the seam column is the
        /// west fit's on its last column, and the excess sits in the first patch column. Fitted as one
        /// heightmap (the seam seen from both sides), the east samples fit as well as the tile alone.
        /// </summary>
        [Test]
        public void HeldSeamCostIsTheWestEdgesOneSidedFit()
        {
            const int patches = 32;
            double[] zw = Load(West), ze = Load(East);
            HeightmapFit west = HeightmapFitter.Fit(zw, Side, Side, patches, patches);
            HeightmapFit east = HeightmapFitter.FitEastOf(west, ze, Side, Side, patches);
            HeightmapFit alone = HeightmapFitter.Fit(ze, Side, Side, patches, patches);
            double[] eastColumns = ColumnMaxErrors(east.Grid, ze, Side, Side), westColumns = ColumnMaxErrors(west.Grid, zw, Side, Side);
            int patchWidth = (Side - 1) / patches;
            double near = 0, beyond = 0;
            for (int c = 0; c < Side; c++)
                if (c <= patchWidth) near = Math.Max(near, eastColumns[c]); else beyond = Math.Max(beyond, eastColumns[c]);

            int joinedWidth = 2 * Side - 1;
            var zj = new double[joinedWidth * Side];
            for (int r = 0; r < Side; r++)
                for (int c = 0; c < joinedWidth; c++) zj[r * joinedWidth + c] = c < Side ? zw[r * Side + c] : ze[r * Side + c - (Side - 1)];
            HeightmapFit whole = HeightmapFitter.Fit(zj, joinedWidth, Side, 2 * patches, patches);
            double[] wholeColumns = ColumnMaxErrors(whole.Grid, zj, joinedWidth, Side);
            double wholeEast = 0;
            for (int c = Side - 1; c < joinedWidth; c++) wholeEast = Math.Max(wholeEast, wholeColumns[c]);

            TestContext.Out.WriteLine($"{patches}x{patches}: east held max {east.MaxError:F2} m (first patch column {near:F2}, beyond {beyond:F2}; seam column {eastColumns[0]:F2}, " +
                                      $"west's last column {westColumns[Side - 1]:F2}); alone {alone.MaxError:F2}; fitted as one {2 * patches} x {patches} heightmap, over the east samples {wholeEast:F2}");
            Assert.That(eastColumns[0], Is.EqualTo(westColumns[Side - 1]).Within(1e-6), "the seam column's error is the west fit's");
            Assert.That(near, Is.EqualTo(east.MaxError).Within(1e-6), "the max is in the first patch column");
            Assert.That(beyond, Is.LessThanOrEqualTo(1.01 * alone.MaxError), "beyond the first patch column the held seam costs nothing");
            Assert.That(wholeEast, Is.LessThanOrEqualTo(1.01 * alone.MaxError), "two-sided, the seam costs nothing");
            Assert.That(east.MaxError, Is.GreaterThan(1.2 * alone.MaxError), "the held seam's excess, what this test explains");
        }
    }
}
