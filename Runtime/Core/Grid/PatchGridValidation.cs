using System;
using System.Collections.Generic;
using System.Globalization;

namespace GregoryTerrain
{
    internal sealed partial class PatchGrid
    {
        /// <summary>
        /// Throws ArgumentException unless the grid is well formed and drawable: no more patches
        /// than the GPU buffers hold (<see cref="GpuLayout.CheckSize"/>); grid lines finite, strictly
        /// increasing, from exactly 0 to exactly 1 (so the regions tile the unit square with no gap
        /// or overlap) and still strictly increasing once rounded to float (else a patch is empty
        /// on the GPU); every control point finite and within float32's range; and each pair of
        /// neighbours uses identical (bit for bit) control points on their shared edge (so the
        /// surface is watertight whatever the arithmetic). The message names the field, the patch
        /// (i, j), the slot, the value and the limit.
        /// </summary>
        public void Validate()
        {
            GpuLayout.CheckSize(Columns, Rows);
            ValidateLines(XLines, "xLines");
            ValidateLines(YLines, "yLines");
            for (int j = 0; j < Rows; j++)
                for (int i = 0; i < Columns; i++)
                    ValidatePoints(i, j);
            for (int j = 0; j < Rows; j++)
                for (int i = 0; i < Columns; i++)
                    ValidateEdgesAfter(i, j);
        }

        /// <summary>
        /// <see cref="Validate"/>'s rules for <paramref name="patches"/> only: their control points and
        /// the edges they share with their four neighbours. For a grid that was valid before those
        /// patches changed (an edit): it is valid again exactly when this passes, at the cost of the
        /// patches changed, not of the grid.
        /// </summary>
        public void ValidatePatches(IReadOnlyList<int> patches)
        {
            foreach (int p in patches)
            {
                if (p < 0 || p >= PatchCount)
                    throw new ArgumentOutOfRangeException(nameof(patches), p, F("patch {0} is outside the grid's {1} patches.", p, PatchCount));
                int i = p % Columns, j = p / Columns;
                ValidatePoints(i, j);
                ValidateEdgesAfter(i, j);
                if (i > 0) ValidateEdgesAfter(i - 1, j, up: false);
                if (j > 0) ValidateEdgesAfter(i, j - 1, right: false);
            }
        }

        void ValidatePoints(int i, int j)
        {
            GregoryPatch p = Patch(i, j);
            p.Validate(Name(i, j));
            for (int k = 0; k < GregoryPatch.SlotCount; k++)
                CheckFloatRange(p[k], i, j, k);
        }

        /// <summary>The edges patch (i, j) shares with its right and upper neighbours.</summary>
        void ValidateEdgesAfter(int i, int j, bool right = true, bool up = true)
        {
            // Right neighbour: our u = 1 column (slots 12..15) is its u = 0 column (slots 0..3).
            if (right && i + 1 < Columns)
                for (int k = 0; k < 4; k++)
                    CheckShared(i, j, GregoryPatch.Slot(3, k), i + 1, j, GregoryPatch.Slot(0, k), "x", XLines[i + 1]);
            // Upper neighbour: our v = 1 row (slots 3, 7, 11, 15) is its v = 0 row (0, 4, 8, 12).
            if (up && j + 1 < Rows)
                for (int k = 0; k < 4; k++)
                    CheckShared(i, j, GregoryPatch.Slot(k, 3), i, j + 1, GregoryPatch.Slot(k, 0), "y", YLines[j + 1]);
        }

        /// <summary>
        /// Why flat serialized data (a PatchGridAsset's fields: 60 doubles per patch, x y z of the 20
        /// slots) is not a valid grid, or null: the rules of <see cref="Validate"/>, with the GPU's
        /// patch limit checked before anything is allocated. The message names the field and value.
        /// </summary>
        public static string SerializedDataError(int columns, int rows, double[] xLines, double[] yLines, double[] controlPoints)
        {
            try
            {
                GpuLayout.CheckSize(columns, rows);
                long expected = (long)columns * rows * 3 * GregoryPatch.SlotCount;
                if (controlPoints == null || controlPoints.Length != expected)
                    return F("controlPoints.Length = {0}, expected {1} (= 60 x {2} x {3})", controlPoints?.Length ?? 0, expected, columns, rows);
                var patches = new GregoryPatch[columns * rows];
                for (int p = 0; p < patches.Length; p++)
                {
                    var patch = new GregoryPatch();
                    for (int k = 0; k < GregoryPatch.SlotCount; k++)
                    {
                        long o = ((long)p * GregoryPatch.SlotCount + k) * 3;
                        patch[k] = new Double3(controlPoints[o], controlPoints[o + 1], controlPoints[o + 2]);
                    }
                    patches[p] = patch;
                }
                new PatchGrid(columns, rows, xLines, yLines, patches).Validate();
                return null;
            }
            catch (ArgumentException e)
            {
                return e.Message;
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
            for (int k = 1; k <= last; k++)
                if (!((float)lines[k] > (float)lines[k - 1]))
                    throw new ArgumentException(F("{0}[{1}] = {2:R} and {0}[{3}] = {4:R} round to the same float {5:R}: the patch between them would be empty on the GPU.",
                        field, k, lines[k], k - 1, lines[k - 1], (float)lines[k]), field);
        }

        static void CheckFloatRange(Double3 c, int i, int j, int slot)
        {
            if (!InputLimits.FitsFloat(c.x) || !InputLimits.FitsFloat(c.y) || !InputLimits.FitsFloat(c.z))
                throw new ArgumentException(F("patches: {0} slot {1} = {2} is outside float32's range (|x|, |y|, |z| <= {3:R}); the GPU cannot hold it.",
                    Name(i, j), slot, c, InputLimits.MaxFloat), "patches");
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
