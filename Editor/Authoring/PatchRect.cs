using System;
using System.Globalization;

namespace GregoryTerrain
{
    /// <summary>
    /// A selection of patches: columns <c>I0..I1</c> and rows <c>J0..J1</c> of a grid, both ends
    /// included (one patch when I0 = I1 and J0 = J1). What the editor's region selection holds and
    /// what <see cref="PatchBrush"/> and <see cref="PatchRegionFit"/> confine an edit to.
    /// </summary>
    [Serializable]
    internal struct PatchRect : IEquatable<PatchRect>
    {
        public int I0, J0, I1, J1;

        public PatchRect(int i0, int j0, int i1, int j1) { I0 = i0; J0 = j0; I1 = i1; J1 = j1; }

        /// <summary>The whole grid.</summary>
        public static PatchRect All(PatchGrid grid) => new PatchRect(0, 0, grid.Columns - 1, grid.Rows - 1);

        /// <summary>The rectangle spanned by two patches given in any order (a drag from one corner to the other).</summary>
        public static PatchRect Spanning(int ia, int ja, int ib, int jb) =>
            new PatchRect(Math.Min(ia, ib), Math.Min(ja, jb), Math.Max(ia, ib), Math.Max(ja, jb));

        public int Columns => I1 - I0 + 1;
        public int Rows => J1 - J0 + 1;
        public int PatchCount => Columns * Rows;

        public bool Contains(int i, int j) => i >= I0 && i <= I1 && j >= J0 && j <= J1;

        /// <summary>
        /// Throws ArgumentOutOfRangeException, naming the field (<c>field.I0</c> ...) and its value,
        /// unless 0 &lt;= I0 &lt;= I1 &lt; columns and 0 &lt;= J0 &lt;= J1 &lt; rows.
        /// </summary>
        public void Check(int columns, int rows, string field)
        {
            Bound(I0, 0, columns - 1, field + ".I0", "column");
            Bound(I1, I0, columns - 1, field + ".I1", "column");
            Bound(J0, 0, rows - 1, field + ".J0", "row");
            Bound(J1, J0, rows - 1, field + ".J1", "row");
        }

        static void Bound(int v, int lo, int hi, string field, string what)
        {
            if (v < lo || v > hi)
                throw new ArgumentOutOfRangeException(field, v, string.Format(CultureInfo.InvariantCulture,
                    "{0} = {1}: the {2} must lie in {3}..{4}.", field, v, what, lo, hi));
        }

        public bool Equals(PatchRect o) => I0 == o.I0 && J0 == o.J0 && I1 == o.I1 && J1 == o.J1;
        public override bool Equals(object obj) => obj is PatchRect o && Equals(o);
        public override int GetHashCode() => HashCode.Combine(I0, J0, I1, J1);
        public override string ToString() => FormattableString.Invariant($"patches ({I0}, {J0}) to ({I1}, {J1})");
    }
}
