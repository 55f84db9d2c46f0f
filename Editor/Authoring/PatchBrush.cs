using System;
using System.Globalization;

namespace GregoryTerrain
{
    /// <summary>What a brush dab does to the heights under it.</summary>
    internal enum BrushMode
    {
        /// <summary>Adds <see cref="BrushDab.Strength"/> (terrain units; negative lowers) times the falloff.</summary>
        Raise,
        /// <summary>Moves each height toward the mean of its 3 x 3 net neighbours by Strength (0..1) times the falloff.</summary>
        Smooth,
        /// <summary>Moves each height toward <see cref="BrushDab.Target"/> by Strength (0..1) times the falloff.</summary>
        Flatten,
    }

    /// <summary>
    /// One application of a brush in terrain space: a disc of <see cref="Radius"/> around
    /// (<see cref="X"/>, <see cref="Y"/>) in the unit square's units, falling off smoothly to 0 at its
    /// rim (<see cref="PatchBrush.Falloff"/>). A stroke is many dabs along the mouse's path.
    /// </summary>
    internal readonly struct BrushDab
    {
        public readonly BrushMode Mode;
        /// <summary>Centre in terrain space (the unit square's x, y).</summary>
        public readonly double X, Y;
        /// <summary>Radius in the same units as x; must be positive and finite.</summary>
        public readonly double Radius;
        /// <summary>Raise: height added at the centre, terrain units (negative lowers). Smooth, Flatten: fraction 0..1 of the way at the centre.</summary>
        public readonly double Strength;
        /// <summary>Flatten's height, terrain units (ignored by the other modes).</summary>
        public readonly double Target;

        public BrushDab(BrushMode mode, double x, double y, double radius, double strength, double target = 0)
        {
            Mode = mode; X = x; Y = y; Radius = radius; Strength = strength; Target = target;
        }

        /// <summary>Throws ArgumentException naming the field (<c>dab.Radius</c> ...) and its value unless the dab is usable.</summary>
        public void Check()
        {
            if (Mode != BrushMode.Raise && Mode != BrushMode.Smooth && Mode != BrushMode.Flatten)
                throw new ArgumentException(F("dab.Mode = {0} is not a brush mode.", (int)Mode), "dab.Mode");
            Finite(X, "dab.X");
            Finite(Y, "dab.Y");
            if (!(Radius > 0) || double.IsInfinity(Radius))
                throw new ArgumentException(F("dab.Radius = {0}, need a positive finite radius (terrain units).", Radius), "dab.Radius");
            Finite(Strength, "dab.Strength");
            if (Mode != BrushMode.Raise && !(Strength >= 0 && Strength <= 1))
                throw new ArgumentException(F("dab.Strength = {0}: {1} moves heights a fraction of the way, need 0..1.", Strength, Mode), "dab.Strength");
            if (Mode == BrushMode.Flatten) Finite(Target, "dab.Target");
        }

        static void Finite(double v, string field)
        {
            if (!GMath.isfinite(v)) throw new ArgumentException(F("{0} = {1} is not finite.", field, v), field);
        }

        static string F(string format, params object[] args) => string.Format(CultureInfo.InvariantCulture, format, args);
    }

    /// <summary>
    /// Brush edits on a patch grid's control points that keep it G1 (NetEdit: heights of the net
    /// nodes under the disc change, then the corner lines and shared edges around them are made G1
    /// again; patches beyond those and their neighbours keep every bit). The grid is not written: the
    /// caller applies the returned <see cref="PatchEdit"/> (after recording it for Undo).
    /// </summary>
    internal static class PatchBrush
    {
        /// <summary>The brush profile at <c>t = distance / radius</c>: <c>(1 - t^2)^2</c> inside, 0 outside; 1 at the centre, smooth (C1) at the rim.</summary>
        public static double Falloff(double t) => t >= 1 ? 0 : (1 - t * t) * (1 - t * t);

        /// <summary>
        /// The edit one dab makes. <paramref name="limit"/> (a region selection) confines it to the net
        /// nodes of those patches; the points next to its border may still move to keep G1. Throws
        /// ArgumentException naming the field and value on a bad dab or limit, or on a grid whose
        /// patches under the brush are not finite or do not share their edges bit for bit; the grid is
        /// never changed. An empty edit when the disc misses the grid or the limit.
        /// </summary>
        public static PatchEdit Apply(PatchGrid grid, BrushDab dab, PatchRect? limit = null)
        {
            if (grid == null) throw new ArgumentNullException(nameof(grid));
            dab.Check();
            limit?.Check(grid.Columns, grid.Rows, "limit");
            int n = grid.Columns, m = grid.Rows;
            var empty = new PatchEdit(n, m, Array.Empty<int>(), Array.Empty<GregoryPatch>());
            double x0 = dab.X - dab.Radius, x1 = dab.X + dab.Radius, y0 = dab.Y - dab.Radius, y1 = dab.Y + dab.Radius;
            if (x1 < 0 || x0 > 1 || y1 < 0 || y0 > 1) return empty;
            // Patches under the disc's bounding box, cut to the limit.
            int i0 = PatchGrid.FindInterval(grid.XLines, Math.Max(0, x0)), i1 = PatchGrid.FindInterval(grid.XLines, Math.Min(1, x1));
            int j0 = PatchGrid.FindInterval(grid.YLines, Math.Max(0, y0)), j1 = PatchGrid.FindInterval(grid.YLines, Math.Min(1, y1));
            if (limit is PatchRect l)
            {
                i0 = Math.Max(i0, l.I0); i1 = Math.Min(i1, l.I1); j0 = Math.Max(j0, l.J0); j1 = Math.Min(j1, l.J1);
                if (i0 > i1 || j0 > j1) return empty;
            }
            var edit = new NetEdit(grid, new PatchRect(Math.Max(0, i0 - 1), Math.Max(0, j0 - 1), Math.Min(n - 1, i1 + 1), Math.Min(m - 1, j1 + 1)));
            int a0 = 3 * i0, a1 = 3 * (i1 + 1), b0 = 3 * j0, b1 = 3 * (j1 + 1);
            bool Editable(int a, int b) => a >= a0 && a <= a1 && b >= b0 && b <= b1;

            // New heights from the old ones (all read before any is written), nodes then second points.
            var nodeZ = new double[(a1 - a0 + 1) * (b1 - b0 + 1)];
            var nodeSet = new bool[nodeZ.Length];
            for (int b = b0; b <= b1; b++)
                for (int a = a0; a <= a1; a++)
                {
                    Double3 p = edit.Node(a, b);
                    int k = (b - b0) * (a1 - a0 + 1) + (a - a0);
                    nodeSet[k] = NewHeight(edit, dab, p, a, b, out nodeZ[k]);
                }
            var second = new double[(i1 - i0 + 1) * (j1 - j0 + 1) * 4];
            var secondSet = new bool[second.Length];
            for (int j = j0; j <= j1; j++)
                for (int i = i0; i <= i1; i++)
                    for (int q = 0; q < 4; q++)
                    {
                        int first = FirstSlots[q];
                        int k = ((j - j0) * (i1 - i0 + 1) + (i - i0)) * 4 + q;
                        secondSet[k] = NewHeight(edit, dab, edit.Patch(i, j)[GregoryPatch.SecondOfPair(first)], 3 * i + first / 4, 3 * j + first % 4, out second[k]);
                    }
            for (int b = b0; b <= b1; b++)
                for (int a = a0; a <= a1; a++)
                {
                    int k = (b - b0) * (a1 - a0 + 1) + (a - a0);
                    if (nodeSet[k]) edit.SetNodeZ(a, b, nodeZ[k]);
                }
            for (int j = j0; j <= j1; j++)
                for (int i = i0; i <= i1; i++)
                    for (int q = 0; q < 4; q++)
                    {
                        int k = ((j - j0) * (i1 - i0 + 1) + (i - i0)) * 4 + q;
                        if (secondSet[k]) edit.SetZ(i, j, GregoryPatch.SecondOfPair(FirstSlots[q]), second[k]);
                    }

            edit.RepairCorners(i0, j0, i1 + 1, j1 + 1, Editable);
            edit.JoinEdges((i, j, vertical) => EdgeRule.Symmetric);
            return edit.ToEdit();
        }

        static readonly int[] FirstSlots = { GregoryPatch.P110, GregoryPatch.P120, GregoryPatch.P210, GregoryPatch.P220 };

        /// <summary>The dab's new height for point p at net node (a, b); false where the falloff is 0.</summary>
        static bool NewHeight(NetEdit edit, BrushDab dab, Double3 p, int a, int b, out double z)
        {
            double dx = p.x - dab.X, dy = p.y - dab.Y;
            double w = Falloff(Math.Sqrt(dx * dx + dy * dy) / dab.Radius);
            z = p.z;
            if (!(w > 0)) return false;
            switch (dab.Mode)
            {
                case BrushMode.Raise: z = p.z + dab.Strength * w; break;
                case BrushMode.Smooth: z = p.z + dab.Strength * w * (NeighbourMean(edit, a, b) - p.z); break;
                default: z = p.z + dab.Strength * w * (dab.Target - p.z); break;
            }
            if (!InputLimits.FitsFloat(z))
                throw new ArgumentException(string.Format(CultureInfo.InvariantCulture,
                    "dab.Strength = {0} would put a control point at height {1:R}, outside float32's range (|z| <= {2:R}).", dab.Strength, z, InputLimits.MaxFloat), "dab.Strength");
            return true;
        }

        /// <summary>Mean height of the 3 x 3 net nodes around (a, b) that lie in the grid.</summary>
        static double NeighbourMean(NetEdit edit, int a, int b)
        {
            int na = 3 * edit.Grid.Columns, nb = 3 * edit.Grid.Rows;
            double sum = 0;
            int count = 0;
            for (int db = -1; db <= 1; db++)
                for (int da = -1; da <= 1; da++)
                {
                    int x = a + da, y = b + db;
                    if (x < 0 || x > na || y < 0 || y > nb) continue;
                    sum += edit.Node(x, y).z;
                    count++;
                }
            return sum / count;
        }
    }
}
