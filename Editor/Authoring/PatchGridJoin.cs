using System;
using System.Globalization;

namespace GregoryTerrain
{
    /// <summary>
    /// Joins grids fitted to neighbouring tiles into one grid over the unit square, side by side
    /// (<see cref="WestEast"/>) or one above the other (<see cref="SouthNorth"/>). A 2 x 2 block of
    /// tiles is two west-east joins then one south-north join of the two strips: the strips must
    /// share their columns, i.e. both west tiles have the same column count and x lines (and so do
    /// both east tiles) and the same westShare is used for both rows. G1 across every seam needs
    /// each tile fitted against its neighbours' edges: HeightmapFitter.FitEastOf for a west-east
    /// seam, FitNorthOf for a south-north one, FitNorthEastOf for the tile with both (the corner
    /// where four tiles meet).
    /// </summary>
    internal static class PatchGridJoin
    {
        /// <summary>
        /// West's columns then east's, on the rows they share: west's x is scaled into
        /// [0, westShare], east's into [westShare, 1], z is kept. The seam line is exactly westShare
        /// on both sides, so identical seam heights stay identical. The grids must have the same rows
        /// and y lines. Pass west's share of the joined width (its width over the sum of widths).
        /// </summary>
        public static PatchGrid WestEast(PatchGrid west, PatchGrid east, double westShare)
        {
            if (west == null) throw new ArgumentNullException(nameof(west));
            if (east == null) throw new ArgumentNullException(nameof(east));
            if (!(westShare > 0 && westShare < 1))
                throw new ArgumentException(string.Format(CultureInfo.InvariantCulture, "westShare = {0}, need a value strictly between 0 and 1.", westShare), nameof(westShare));
            if (west.Rows != east.Rows)
                throw new ArgumentException($"east.Rows = {east.Rows}, west.Rows = {west.Rows}: the grids must share their rows.", nameof(east));
            for (int j = 0; j <= west.Rows; j++)
                if (west.YLines[j] != east.YLines[j])
                    throw new ArgumentException(string.Format(CultureInfo.InvariantCulture,
                        "east.YLines[{0}] = {1:R}, west's is {2:R}: the grids must share their rows.", j, east.YLines[j], west.YLines[j]), nameof(east));
            int n = west.Columns + east.Columns, m = west.Rows;
            var xl = new double[n + 1];
            for (int i = 0; i <= west.Columns; i++) xl[i] = i == west.Columns ? westShare : west.XLines[i] * westShare;
            for (int i = 1; i <= east.Columns; i++) xl[west.Columns + i] = i == east.Columns ? 1.0 : westShare + east.XLines[i] * (1 - westShare);
            var patches = new GregoryPatch[n * m];
            for (int j = 0; j < m; j++)
            {
                for (int i = 0; i < west.Columns; i++)
                    patches[j * n + i] = Rescaled(west.Patch(i, j), 0, westShare);
                for (int i = 0; i < east.Columns; i++)
                    patches[j * n + west.Columns + i] = Rescaled(east.Patch(i, j), westShare, 1 - westShare);
            }
            return new PatchGrid(n, m, xl, (double[])west.YLines.Clone(), patches);
        }

        /// <summary>
        /// South's rows then north's, on the columns they share: south's y is scaled into
        /// [0, southShare], north's into [southShare, 1], z is kept. The mirror of <see cref="WestEast"/>
        /// across the diagonal: the seam line is exactly southShare on both sides, so identical seam
        /// heights stay identical. The grids must have the same columns and x lines.
        /// </summary>
        public static PatchGrid SouthNorth(PatchGrid south, PatchGrid north, double southShare)
        {
            if (south == null) throw new ArgumentNullException(nameof(south));
            if (north == null) throw new ArgumentNullException(nameof(north));
            if (!(southShare > 0 && southShare < 1))
                throw new ArgumentException(string.Format(CultureInfo.InvariantCulture, "southShare = {0}, need a value strictly between 0 and 1.", southShare), nameof(southShare));
            if (south.Columns != north.Columns)
                throw new ArgumentException($"north.Columns = {north.Columns}, south.Columns = {south.Columns}: the grids must share their columns.", nameof(north));
            for (int i = 0; i <= south.Columns; i++)
                if (south.XLines[i] != north.XLines[i])
                    throw new ArgumentException(string.Format(CultureInfo.InvariantCulture,
                        "north.XLines[{0}] = {1:R}, south's is {2:R}: the grids must share their columns.", i, north.XLines[i], south.XLines[i]), nameof(north));
            int n = south.Columns, m = south.Rows + north.Rows;
            var yl = new double[m + 1];
            for (int j = 0; j <= south.Rows; j++) yl[j] = j == south.Rows ? southShare : south.YLines[j] * southShare;
            for (int j = 1; j <= north.Rows; j++) yl[south.Rows + j] = j == north.Rows ? 1.0 : southShare + north.YLines[j] * (1 - southShare);
            var patches = new GregoryPatch[n * m];
            for (int i = 0; i < n; i++)
            {
                for (int j = 0; j < south.Rows; j++)
                    patches[j * n + i] = RescaledY(south.Patch(i, j), 0, southShare);
                for (int j = 0; j < north.Rows; j++)
                    patches[(south.Rows + j) * n + i] = RescaledY(north.Patch(i, j), southShare, 1 - southShare);
            }
            return new PatchGrid(n, m, (double[])south.XLines.Clone(), yl, patches);
        }

        /// <summary>y to offset + scale y, keeping y = 0 and y = 1 exactly at offset and offset + scale (the seam).</summary>
        static GregoryPatch RescaledY(GregoryPatch p, double offset, double scale)
        {
            var q = p.Clone();
            for (int k = 0; k < GregoryPatch.SlotCount; k++) q[k] = new Double3(p[k].x, Scale(p[k].y, offset, scale), p[k].z);
            return q;
        }

        static double Scale(double t, double offset, double scale) => t == 0 ? offset : t == 1 ? (offset == 0 ? scale : 1.0) : offset + t * scale;

        /// <summary>x to offset + scale x, keeping x = 0 and x = 1 exactly at offset and offset + scale (the seam).</summary>
        static GregoryPatch Rescaled(GregoryPatch p, double offset, double scale)
        {
            var q = p.Clone();
            for (int k = 0; k < GregoryPatch.SlotCount; k++)
            {
                double x = p[k].x;
                double nx = x == 0 ? offset : x == 1 ? (offset == 0 ? scale : 1.0) : offset + x * scale;
                q[k] = new Double3(nx, p[k].y, p[k].z);
            }
            return q;
        }
    }
}
