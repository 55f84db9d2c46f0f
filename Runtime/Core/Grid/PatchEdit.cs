using System;
using System.Globalization;

namespace GregoryTerrain
{
    /// <summary>
    /// The result of an edit (the authoring assembly's <c>PatchBrush</c>, <c>PatchRegionFit</c>) not yet written:
    /// the indices of the patches it changes and their new control points. Nothing else of the grid
    /// changes, so the editor records for Undo only the blocks holding these patches, then applies it.
    /// </summary>
    internal sealed class PatchEdit
    {
        /// <summary>Columns and rows of the grid the edit was computed on.</summary>
        public int Columns { get; }
        public int Rows { get; }
        /// <summary>Changed patch indices <c>j * n + i</c>, ascending.</summary>
        public int[] Patches { get; }
        /// <summary>The new patches, one per entry of <see cref="Patches"/>.</summary>
        public GregoryPatch[] Values { get; }

        public PatchEdit(int columns, int rows, int[] patches, GregoryPatch[] values)
        {
            if (patches == null) throw new ArgumentNullException(nameof(patches));
            if (values == null) throw new ArgumentNullException(nameof(values));
            if (patches.Length != values.Length)
                throw new ArgumentException($"values.Length = {values.Length}, need patches.Length = {patches.Length}.", nameof(values));
            Columns = columns;
            Rows = rows;
            Patches = patches;
            Values = values;
        }

        /// <summary>True when the edit changes nothing (e.g. a brush outside the terrain).</summary>
        public bool IsEmpty => Patches.Length == 0;

        /// <summary>
        /// Writes the new control points into <paramref name="grid"/>'s patches in place. Throws,
        /// changing nothing, unless the grid has the shape the edit was computed on.
        /// </summary>
        public void ApplyTo(PatchGrid grid)
        {
            if (grid == null) throw new ArgumentNullException(nameof(grid));
            if (grid.Columns != Columns || grid.Rows != Rows)
                throw new ArgumentException(string.Format(CultureInfo.InvariantCulture,
                    "grid is {0} x {1} patches, the edit was made on {2} x {3}.", grid.Columns, grid.Rows, Columns, Rows), nameof(grid));
            for (int k = 0; k < Patches.Length; k++)
                Values[k].Points.CopyTo(grid.Patches[Patches[k]].Points, 0);
        }
    }
}
