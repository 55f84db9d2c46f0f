using System;
using NUnit.Framework;

namespace GregoryTerrain.Tests
{
    /// <summary>
    /// Four tiles of one heightmap fitted one by one (south-west alone, south-east against its west
    /// edge, north-west against its south edge, north-east against both) and joined into one grid:
    /// G1 across every shared edge and at the corner where the four meet, seams bit-identical, no NaN.
    /// The tiles differ in size and patch count so the held slopes are rescaled on every seam.
    /// </summary>
    [TestFixture]
    public class HeightmapTileJoinTests
    {
        // The whole heightmap and where it is cut: the seam column and row are shared by both sides.
        const int W = 113, H = 121, SeamColumn = 64, SeamRow = 64;
        const int WestWidth = SeamColumn + 1, EastWidth = W - SeamColumn, SouthHeight = SeamRow + 1, NorthHeight = H - SeamRow;
        const double WestShare = (double)SeamColumn / (W - 1), SouthShare = (double)SeamRow / (H - 1);
        // Rounding only: the held unknowns are copied, so the seams' cross derivatives agree to a few ulps.
        const double G1BoundDegrees = 1e-7;

        static double[] Tile(int c0, int r0, int w, int h)
        {
            var a = new double[w * h];
            for (int r = 0; r < h; r++)
                for (int c = 0; c < w; c++)
                    a[r * w + c] = HeightmapFitterTests.Terrain((double)(c0 + c) / (W - 1), (double)(r0 + r) / (H - 1));
            return a;
        }

        static double[] Sw() => Tile(0, 0, WestWidth, SouthHeight);
        static double[] Se() => Tile(SeamColumn, 0, EastWidth, SouthHeight);
        static double[] Nw() => Tile(0, SeamRow, WestWidth, NorthHeight);
        static double[] Ne() => Tile(SeamColumn, SeamRow, EastWidth, NorthHeight);

        static PatchGrid Join(PatchGrid sw, PatchGrid se, PatchGrid nw, PatchGrid ne) =>
            PatchGridJoin.SouthNorth(PatchGridJoin.WestEast(sw, se, WestShare), PatchGridJoin.WestEast(nw, ne, WestShare), SouthShare);

        /// <summary>The largest angle between the unit normals of the four patches around grid vertex (i, j), in degrees.</summary>
        static double CornerAngleDegrees(PatchGrid g, int i, int j)
        {
            var n = new[]
            {
                GregoryEval.Normal(g.Patch(i - 1, j - 1).Points, 1, 1), GregoryEval.Normal(g.Patch(i, j - 1).Points, 0, 1),
                GregoryEval.Normal(g.Patch(i - 1, j).Points, 1, 0), GregoryEval.Normal(g.Patch(i, j).Points, 0, 0),
            };
            double worst = 0;
            for (int a = 0; a < 4; a++)
                for (int b = a + 1; b < 4; b++)
                {
                    Double3 p = GMath.normalize(n[a]), q = GMath.normalize(n[b]);
                    worst = Math.Max(worst, Math.Atan2(GMath.length(GMath.cross(p, q)), GMath.dot(p, q)) * (180.0 / Math.PI));
                }
            return worst;
        }

        static bool AllFinite(PatchGrid g)
        {
            foreach (GregoryPatch p in g.Patches)
                for (int k = 0; k < GregoryPatch.SlotCount; k++)
                    if (!GMath.isfinite(p[k].x) || !GMath.isfinite(p[k].y) || !GMath.isfinite(p[k].z)) return false;
            return true;
        }

        [Test]
        public void TwoByTwoFittedTileByTileJoinsG1EverywhereCornerIncluded()
        {
            HeightmapFit sw = HeightmapFitter.Fit(Sw(), WestWidth, SouthHeight, 4, 4);
            HeightmapFit se = HeightmapFitter.FitEastOf(sw, Se(), EastWidth, SouthHeight, 3);
            HeightmapFit nw = HeightmapFitter.FitNorthOf(sw, Nw(), WestWidth, NorthHeight, 5);
            HeightmapFit ne = HeightmapFitter.FitNorthEastOf(nw, se, Ne(), EastWidth, NorthHeight);
            Assert.That((ne.Grid.Columns, ne.Grid.Rows), Is.EqualTo((3, 5)), "columns from the south-east tile, rows from the north-west one");

            PatchGrid joined = Join(sw.Grid, se.Grid, nw.Grid, ne.Grid);
            Assert.That(AllFinite(joined), "no NaN or infinity in the joined grid");
            Assert.DoesNotThrow(joined.Validate, "seams bit-identical");
            double angle = ContinuityMeasure.MaxNormalAngleDegrees(joined);
            double corner = CornerAngleDegrees(joined, 4, 4);
            TestContext.Out.WriteLine($"2 x 2 fitted tile by tile: G1 {angle:E2} deg over every shared edge, {corner:E2} deg between the four normals at the corner; " +
                                      $"max error SW {sw.MaxError:E2} SE {se.MaxError:E2} NW {nw.MaxError:E2} NE {ne.MaxError:E2}");
            Assert.That(ContinuityMeasure.MaxPositionGap(joined), Is.EqualTo(0.0));
            Assert.That(angle, Is.LessThan(G1BoundDegrees));
            Assert.That(corner, Is.LessThan(G1BoundDegrees));
            foreach (HeightmapFit f in new[] { sw, se, nw, ne })
            {
                Assert.That(GMath.isfinite(f.MaxError) && GMath.isfinite(f.RmsError));
                // The held edges cost little on smooth data: the same bound as the free 5 x 5 fit of
                // the whole (HeightmapFitterTests), 1% of the terrain's range.
                Assert.That(f.MaxError, Is.LessThan(2.5e-3));
            }

            // The checks can fail: the north-east tile held at its west edge only (its south seam
            // free) kinks across the south-north seam; fitted alone, it also kinks at the corner.
            // (Held at its west edge only, its corner vertex is still the shared one, and the
            // tangent plane at a vertex is the vertex's own: the corner alone would not show it.)
            HeightmapFit westOnly = HeightmapFitter.FitEastOf(nw, Ne(), EastWidth, NorthHeight, 3);
            double brokenAngle = ContinuityMeasure.MaxNormalAngleDegrees(Join(sw.Grid, se.Grid, nw.Grid, westOnly.Grid));
            HeightmapFit alone = HeightmapFitter.Fit(Ne(), EastWidth, NorthHeight, 3, 5);
            double aloneCorner = CornerAngleDegrees(Join(sw.Grid, se.Grid, nw.Grid, alone.Grid), 4, 4);
            TestContext.Out.WriteLine($"north-east held at its west edge only: G1 {brokenAngle:E2} deg; fitted alone: corner {aloneCorner:E2} deg");
            Assert.That(brokenAngle, Is.GreaterThan(1000 * G1BoundDegrees));
            Assert.That(aloneCorner, Is.GreaterThan(1000 * G1BoundDegrees));
        }

        [Test]
        public void NorthOfJoinsSouthNorthG1()
        {
            HeightmapFit south = HeightmapFitter.Fit(Se(), EastWidth, SouthHeight, 3, 4);
            HeightmapFit north = HeightmapFitter.FitNorthOf(south, Ne(), EastWidth, NorthHeight, 2);
            PatchGrid joined = PatchGridJoin.SouthNorth(south.Grid, north.Grid, SouthShare);
            Assert.That(AllFinite(joined));
            Assert.DoesNotThrow(joined.Validate);
            double angle = ContinuityMeasure.MaxNormalAngleDegrees(joined);
            HeightmapFit alone = HeightmapFitter.Fit(Ne(), EastWidth, NorthHeight, 3, 2);
            double naive = ContinuityMeasure.MaxNormalAngleDegrees(PatchGridJoin.SouthNorth(south.Grid, alone.Grid, SouthShare));
            TestContext.Out.WriteLine($"north of: G1 {angle:E2} deg (fitted apart {naive:E2}); north max {north.MaxError:E2} RMS {north.RmsError:E2} (alone {alone.MaxError:E2} / {alone.RmsError:E2})");
            Assert.That(angle, Is.LessThan(G1BoundDegrees));
            Assert.That(naive, Is.GreaterThan(1000 * G1BoundDegrees), "the check could not fail: tiles fitted apart already join G1");
            Assert.That(north.RmsError, Is.GreaterThanOrEqualTo(alone.RmsError), "a constrained fit cannot beat the free least-squares one");
        }

        [Test]
        public void BadNeighboursAreRefusedNamingTheField()
        {
            HeightmapFit sw = HeightmapFitter.Fit(Sw(), WestWidth, SouthHeight, 4, 4);
            HeightmapFit se = HeightmapFitter.FitEastOf(sw, Se(), EastWidth, SouthHeight, 3);
            HeightmapFit nw = HeightmapFitter.FitNorthOf(sw, Nw(), WestWidth, NorthHeight, 5);
            double[] ne = Ne();
            double[] kept = (double[])ne.Clone();

            // North of a tile of another width.
            var e = Assert.Throws<ArgumentException>(() => HeightmapFitter.FitNorthOf(sw, ne, EastWidth, NorthHeight, 5));
            Assert.That(e.ParamName, Is.EqualTo("width"));
            Assert.That(e.Message, Does.Contain($"width = {EastWidth} samples").And.Contain($"has {WestWidth}"));
            // North-east with a west neighbour of another height.
            e = Assert.Throws<ArgumentException>(() => HeightmapFitter.FitNorthEastOf(sw, se, ne, EastWidth, NorthHeight));
            Assert.That(e.ParamName, Is.EqualTo("height"));
            Assert.That(e.Message, Does.Contain($"height = {NorthHeight} samples").And.Contain($"has {SouthHeight}"));
            // North-east whose neighbours continue different south-west tiles (another patch
            // count): the corner they both hold disagrees.
            HeightmapFit sw2 = HeightmapFitter.Fit(Sw(), WestWidth, SouthHeight, 2, 2);
            HeightmapFit nw2 = HeightmapFitter.FitNorthOf(sw2, Nw(), WestWidth, NorthHeight, 5);
            e = Assert.Throws<ArgumentException>(() => HeightmapFitter.FitNorthEastOf(nw2, se, ne, EastWidth, NorthHeight));
            Assert.That(e.ParamName, Is.EqualTo("south"));
            Assert.That(e.Message, Does.Contain("corner vertex height"));
            // A neighbour whose net does not match its grid.
            var tampered = new HeightmapFit(nw.Grid, nw.MaxError, nw.RmsError, nw.ErrorMap, nw.Surface, new GregoryNet(4, 4), nw.Unknowns,
                nw.Iterations, nw.SampleWidth, nw.SampleHeight);
            e = Assert.Throws<ArgumentException>(() => HeightmapFitter.FitNorthEastOf(tampered, se, ne, EastWidth, NorthHeight));
            Assert.That(e.ParamName, Is.EqualTo("west"));
            Assert.That(e.Message, Does.Contain("west.Net is 4 x 4 patches, west.Grid is 4 x 5"));
            var noNet = new HeightmapFit(se.Grid, se.MaxError, se.RmsError, se.ErrorMap, se.Surface, se.Net, null, 0, se.SampleWidth, se.SampleHeight);
            e = Assert.Throws<ArgumentException>(() => HeightmapFitter.FitNorthOf(noNet, ne, EastWidth, NorthHeight, 5));
            Assert.That(e.ParamName, Is.EqualTo("south"));
            Assert.That(e.Message, Does.Contain("south.Unknowns = null"));
            Assert.Throws<ArgumentNullException>(() => HeightmapFitter.FitNorthEastOf(nw, null, ne, EastWidth, NorthHeight));
            // Nothing half-changed: the inputs are as they were, and the neighbours still continue.
            Assert.That(ne, Is.EqualTo(kept));
            HeightmapFit fine = HeightmapFitter.FitNorthEastOf(nw, se, ne, EastWidth, NorthHeight);
            Assert.DoesNotThrow(Join(sw.Grid, se.Grid, nw.Grid, fine.Grid).Validate);
        }
    }
}
