using System;

namespace GregoryTerrain.Tests
{
    /// <summary>Grids and checks shared by the authoring tests (brush, region refit, joins).</summary>
    static class AuthoringGrids
    {
        /// <summary>A smooth test surface, heights in the unit square's units (about 0.2 of relief).</summary>
        public static double F(double x, double y) => 0.15 * Math.Sin(3 * x + 1) * Math.Cos(2 * y) + 0.05 * x * y;
        static double Fx(double x, double y) => 0.45 * Math.Cos(3 * x + 1) * Math.Cos(2 * y) + 0.05 * y;
        static double Fy(double x, double y) => -0.3 * Math.Sin(3 * x + 1) * Math.Sin(2 * y) + 0.05 * x;

        /// <summary>
        /// A G1 grid on the given lines (uneven ones too, so cross-edge ratios k are not -1): each net
        /// node takes F and its slopes at the nearest grid vertex (a twist-free Hermite net, so corner
        /// lines are straight), then G1Builder.MakeG1.
        /// </summary>
        public static PatchGrid Curved(double[] xl, double[] yl)
        {
            int n = xl.Length - 1, m = yl.Length - 1;
            PatchGrid grid = PatchGrid.CreateFlat(n, m, xl, yl);
            for (int j = 0; j < m; j++)
                for (int i = 0; i < n; i++)
                {
                    GregoryPatch p = grid.Patch(i, j);
                    for (int ka = 0; ka < 4; ka++)
                        for (int kb = 0; kb < 4; kb++)
                        {
                            int a = 3 * i + ka, b = 3 * j + kb;
                            int I = (a + 1) / 3, J = (b + 1) / 3, da = a - 3 * I, db = b - 3 * J;
                            double w = da < 0 ? xl[I] - xl[I - 1] : da > 0 ? xl[I + 1] - xl[I] : 0;
                            double h = db < 0 ? yl[J] - yl[J - 1] : db > 0 ? yl[J + 1] - yl[J] : 0;
                            double z = F(xl[I], yl[J]) + da * Fx(xl[I], yl[J]) * w / 3 + db * Fy(xl[I], yl[J]) * h / 3;
                            int s = GregoryPatch.Slot(ka, kb);
                            p[s] = new Double3(p[s].x, p[s].y, z);
                        }
                    PatchGrid.SetSecondPointsToFirst(p);
                }
            G1Builder.MakeG1(grid);
            return grid;
        }

        public static readonly double[] Uneven = { 0, 0.1, 0.25, 0.45, 0.55, 0.8, 1.0 };

        /// <summary>W x H samples of <paramref name="f"/> over the unit square (the fitter's convention).</summary>
        public static double[] Samples(Func<double, double, double> f, int w, int h)
        {
            var z = new double[w * h];
            for (int r = 0; r < h; r++)
                for (int c = 0; c < w; c++) z[r * w + c] = f((double)c / (w - 1), (double)r / (h - 1));
            return z;
        }

        public static bool SameBits(GregoryPatch a, GregoryPatch b)
        {
            for (int k = 0; k < GregoryPatch.SlotCount; k++)
                if (BitConverter.DoubleToInt64Bits(a[k].x) != BitConverter.DoubleToInt64Bits(b[k].x) ||
                    BitConverter.DoubleToInt64Bits(a[k].y) != BitConverter.DoubleToInt64Bits(b[k].y) ||
                    BitConverter.DoubleToInt64Bits(a[k].z) != BitConverter.DoubleToInt64Bits(b[k].z)) return false;
            return true;
        }

        /// <summary>The first patch of <paramref name="after"/> that differs from <paramref name="before"/> outside <paramref name="allowed"/>, or null.</summary>
        public static string ChangedOutside(PatchGrid before, PatchGrid after, PatchRect allowed)
        {
            for (int j = 0; j < before.Rows; j++)
                for (int i = 0; i < before.Columns; i++)
                    if (!allowed.Contains(i, j) && !SameBits(before.Patch(i, j), after.Patch(i, j))) return $"patch ({i}, {j})";
            return null;
        }

        /// <summary>True when every point of every patch has the same bits in both grids.</summary>
        public static bool SameBits(PatchGrid a, PatchGrid b)
        {
            for (int p = 0; p < a.PatchCount; p++) if (!SameBits(a.Patches[p], b.Patches[p])) return false;
            return true;
        }

        /// <summary>Surface height at (x, y), for grids whose x, y are linear in u, v within a patch.</summary>
        public static double Height(PatchGrid g, double x, double y)
        {
            int p = g.FindPatch(x, y);
            Region r = g.RegionOf(p);
            return GregoryEval.Position(g.Patches[p].Points, (x - r.a) / r.Width, (y - r.b) / r.Height).z;
        }

        /// <summary>The part of a grid in <paramref name="rect"/> as a grid of its own over the unit square (lines and x, y rescaled, ends exact).</summary>
        public static PatchGrid Cut(PatchGrid g, PatchRect rect)
        {
            double x0 = g.XLines[rect.I0], x1 = g.XLines[rect.I1 + 1], y0 = g.YLines[rect.J0], y1 = g.YLines[rect.J1 + 1];
            double S(double t, double lo, double hi) => t == lo ? 0 : t == hi ? 1 : (t - lo) / (hi - lo);
            var xl = new double[rect.Columns + 1];
            var yl = new double[rect.Rows + 1];
            for (int i = 0; i <= rect.Columns; i++) xl[i] = S(g.XLines[rect.I0 + i], x0, x1);
            for (int j = 0; j <= rect.Rows; j++) yl[j] = S(g.YLines[rect.J0 + j], y0, y1);
            var patches = new GregoryPatch[rect.PatchCount];
            for (int j = 0; j < rect.Rows; j++)
                for (int i = 0; i < rect.Columns; i++)
                {
                    GregoryPatch p = g.Patch(rect.I0 + i, rect.J0 + j).Clone();
                    for (int k = 0; k < GregoryPatch.SlotCount; k++) p[k] = new Double3(S(p[k].x, x0, x1), S(p[k].y, y0, y1), p[k].z);
                    patches[j * rect.Columns + i] = p;
                }
            return new PatchGrid(rect.Columns, rect.Rows, xl, yl, patches);
        }
    }
}
