using System;
using System.Globalization;

namespace GregoryTerrain
{
    public sealed partial class PatchGrid
    {
        /// <summary>
        /// Throws ArgumentException unless the grid is well formed: grid lines finite, strictly
        /// increasing, from exactly 0 to exactly 1 (so the regions tile the unit square with no gap
        /// or overlap); every control point finite; and each pair of neighbours uses identical
        /// (bit for bit) control points on their shared edge (so the surface is watertight whatever
        /// the arithmetic). The message names the field, the patch (i, j), the slot and the value.
        /// </summary>
        public void Validate()
        {
            ValidateLines(XLines, "xLines");
            ValidateLines(YLines, "yLines");
            for (int j = 0; j < Rows; j++)
                for (int i = 0; i < Columns; i++)
                    Patch(i, j).Validate(Name(i, j));
            for (int j = 0; j < Rows; j++)
                for (int i = 0; i < Columns; i++)
                {
                    // Right neighbour: our u = 1 column (slots 12..15) is its u = 0 column (slots 0..3).
                    if (i + 1 < Columns)
                        for (int k = 0; k < 4; k++)
                            CheckShared(i, j, GregoryPatch.Slot(3, k), i + 1, j, GregoryPatch.Slot(0, k), "x", XLines[i + 1]);
                    // Upper neighbour: our v = 1 row (slots 3, 7, 11, 15) is its v = 0 row (0, 4, 8, 12).
                    if (j + 1 < Rows)
                        for (int k = 0; k < 4; k++)
                            CheckShared(i, j, GregoryPatch.Slot(k, 3), i, j + 1, GregoryPatch.Slot(k, 0), "y", YLines[j + 1]);
                }
        }

        static string Name(int i, int j) => string.Format(CultureInfo.InvariantCulture, "patch ({0}, {1})", i, j);

        static void ValidateLines(double[] lines, string field)
        {
            int last = lines.Length - 1;
            for (int k = 0; k <= last; k++)
                if (!GMath.isfinite(lines[k]))
                    throw new ArgumentException(F("{0}[{1}] = {2} is not finite.", field, k, lines[k]), field);
            if (lines[0] != 0.0)
                throw new ArgumentException(F("{0}[0] = {1} must be exactly 0 (the grid must start at the unit square's edge).", field, lines[0]), field);
            if (lines[last] != 1.0)
                throw new ArgumentException(F("{0}[{1}] = {2} must be exactly 1 (the grid must end at the unit square's edge).", field, last, lines[last]), field);
            for (int k = 1; k <= last; k++)
                if (!(lines[k] > lines[k - 1]))
                    throw new ArgumentException(F("{0}[{1}] = {2} is not greater than {0}[{3}] = {4}: grid lines must increase strictly (patches would overlap or be empty).",
                        field, k, lines[k], k - 1, lines[k - 1]), field);
        }

        void CheckShared(int i0, int j0, int slot0, int i1, int j1, int slot1, string axis, double line)
        {
            Double3 a = Patch(i0, j0)[slot0], b = Patch(i1, j1)[slot1];
            if (!SameBits(a, b))
                throw new ArgumentException(F("patches: {0} and {1} share the edge {2} = {3}, but slot {4} of {0} = {5} differs from slot {6} of {1} = {7}; shared boundary control points must be identical.",
                    Name(i0, j0), Name(i1, j1), axis, line, slot0, a, slot1, b), "patches");
        }

        static bool SameBits(Double3 a, Double3 b) =>
            BitConverter.DoubleToInt64Bits(a.x) == BitConverter.DoubleToInt64Bits(b.x) &&
            BitConverter.DoubleToInt64Bits(a.y) == BitConverter.DoubleToInt64Bits(b.y) &&
            BitConverter.DoubleToInt64Bits(a.z) == BitConverter.DoubleToInt64Bits(b.z);

        static string F(string format, params object[] args) => string.Format(CultureInfo.InvariantCulture, format, args);
    }
}
