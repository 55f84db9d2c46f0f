using System;
using System.Globalization;

namespace GregoryTerrain
{
    /// <summary>Joins grids fitted to neighbouring tiles into one grid over the unit square.</summary>
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
