using System;
using System.Globalization;

namespace GregoryTerrain
{
    /// <summary>
    /// An n x m grid of Gregory patches tiling the terrain's unit square. Column i (along x, u) spans
    /// <c>[XLines[i], XLines[i+1]]</c>, row j (along y, v) spans <c>[YLines[j], YLines[j+1]]</c>;
    /// patch (i, j) is <c>Patches[j * n + i]</c>. The constructor checks the shape only (counts, no
    /// nulls); <see cref="Validate"/> checks the contents (PatchGridValidation.cs). Mirrors
    /// <c>Shaders/Grid/PatchGrid.hlsl</c> for <see cref="FindPatch"/> and <see cref="FindInterval(ReadOnlySpan{float}, float)"/>.
    /// </summary>
    internal sealed partial class PatchGrid
    {
        /// <summary>n: patches along x.</summary>
        public int Columns { get; }
        /// <summary>m: patches along y.</summary>
        public int Rows { get; }
        /// <summary>n + 1 grid lines along x, strictly increasing from exactly 0 to exactly 1.</summary>
        public double[] XLines { get; }
        /// <summary>m + 1 grid lines along y, strictly increasing from exactly 0 to exactly 1.</summary>
        public double[] YLines { get; }
        /// <summary>n * m patches, patch (i, j) at index j * n + i.</summary>
        public GregoryPatch[] Patches { get; }

        public int PatchCount => Columns * Rows;

        /// <summary>Takes the arrays as they are (no copy). Throws on wrong counts or null entries.</summary>
        public PatchGrid(int columns, int rows, double[] xLines, double[] yLines, GregoryPatch[] patches)
        {
            CheckShape(columns, rows);
            if (xLines == null) throw new ArgumentNullException(nameof(xLines));
            if (yLines == null) throw new ArgumentNullException(nameof(yLines));
            if (patches == null) throw new ArgumentNullException(nameof(patches));
            if (xLines.Length != columns + 1)
                throw new ArgumentException($"xLines.Length = {xLines.Length}, need columns + 1 = {columns + 1}.", nameof(xLines));
            if (yLines.Length != rows + 1)
                throw new ArgumentException($"yLines.Length = {yLines.Length}, need rows + 1 = {rows + 1}.", nameof(yLines));
            if (patches.Length != columns * rows)
                throw new ArgumentException($"patches.Length = {patches.Length}, need columns * rows = {columns * rows}.", nameof(patches));
            for (int p = 0; p < patches.Length; p++)
                if (patches[p] == null)
                    throw new ArgumentException($"patches[{p}] (patch ({p % columns}, {p / columns})) is null.", nameof(patches));
            Columns = columns;
            Rows = rows;
            XLines = xLines;
            YLines = yLines;
            Patches = patches;
        }

        /// <summary>Throws unless columns, rows >= 1 and columns * rows fits an int.</summary>
        public static void CheckShape(int columns, int rows)
        {
            if (columns < 1) throw new ArgumentException($"columns = {columns}, need at least 1.", nameof(columns));
            if (rows < 1) throw new ArgumentException($"rows = {rows}, need at least 1.", nameof(rows));
            if ((long)columns * rows > int.MaxValue)
                throw new ArgumentException($"columns * rows = {(long)columns * rows} patches is more than {int.MaxValue}.", nameof(columns));
        }

        /// <summary>Uniform grid lines <c>k / count</c>, k = 0..count (exactly 0 and 1 at the ends).</summary>
        public static double[] UniformLines(int count)
        {
            if (count < 1) throw new ArgumentException($"count = {count}, need at least 1.", nameof(count));
            var lines = new double[count + 1];
            for (int k = 0; k <= count; k++) lines[k] = (double)k / count;
            return lines;
        }

        /// <summary>
        /// Point k (0..3) of the four equally spaced points from a to b, with the ends exactly a and b,
        /// so that neighbours computing a shared line's points get identical bits.
        /// </summary>
        public static double Third(double a, double b, int k) => k == 0 ? a : k == 3 ? b : a + (b - a) * k / 3.0;

        /// <summary>A flat (z = 0) grid on uniform lines whose patches are bilinear in x, y.</summary>
        public static PatchGrid CreateFlat(int columns, int rows)
        {
            CheckShape(columns, rows);
            return CreateFlat(columns, rows, UniformLines(columns), UniformLines(rows));
        }

        /// <summary>A flat (z = 0) grid on the given lines; each patch's x, y are linear in u, v.</summary>
        public static PatchGrid CreateFlat(int columns, int rows, double[] xLines, double[] yLines)
        {
            CheckShape(columns, rows);
            var patches = new GregoryPatch[columns * rows];
            var grid = new PatchGrid(columns, rows, xLines, yLines, FillPlaceholders(patches));
            for (int j = 0; j < rows; j++)
                for (int i = 0; i < columns; i++)
                {
                    GregoryPatch p = grid.Patch(i, j);
                    for (int a = 0; a < 4; a++)
                        for (int b = 0; b < 4; b++)
                            p[4 * a + b] = new Double3(Third(xLines[i], xLines[i + 1], a), Third(yLines[j], yLines[j + 1], b), 0.0);
                    SetSecondPointsToFirst(p);
                }
            return grid;
        }

        static GregoryPatch[] FillPlaceholders(GregoryPatch[] patches)
        {
            for (int p = 0; p < patches.Length; p++) patches[p] = new GregoryPatch();
            return patches;
        }

        /// <summary>Makes each interior pair coincide (the patch becomes its Bezier patch).</summary>
        public static void SetSecondPointsToFirst(GregoryPatch p)
        {
            p[GregoryPatch.P111] = p[GregoryPatch.P110];
            p[GregoryPatch.P121] = p[GregoryPatch.P120];
            p[GregoryPatch.P211] = p[GregoryPatch.P210];
            p[GregoryPatch.P221] = p[GregoryPatch.P220];
        }

        /// <summary>A deep copy (lines and control points).</summary>
        public PatchGrid Clone()
        {
            var patches = new GregoryPatch[Patches.Length];
            for (int p = 0; p < patches.Length; p++) patches[p] = Patches[p].Clone();
            return new PatchGrid(Columns, Rows, (double[])XLines.Clone(), (double[])YLines.Clone(), patches);
        }

        /// <summary>Patch index <c>j * n + i</c>.</summary>
        public int Index(int i, int j)
        {
            CheckCell(i, j);
            return j * Columns + i;
        }

        public GregoryPatch Patch(int i, int j) => Patches[Index(i, j)];

        /// <summary>The region <c>(a, b, e, f)</c> = <c>[XLines[i], XLines[i+1]] x [YLines[j], YLines[j+1]]</c>.</summary>
        public Region RegionOf(int i, int j)
        {
            CheckCell(i, j);
            return new Region(XLines[i], YLines[j], XLines[i + 1], YLines[j + 1]);
        }

        public Region RegionOf(int patch)
        {
            if ((uint)patch >= (uint)PatchCount)
                throw new ArgumentOutOfRangeException(nameof(patch), patch, $"patch = {patch} is not in 0..{PatchCount - 1}.");
            return RegionOf(patch % Columns, patch / Columns);
        }

        /// <summary>
        /// Index <c>j * n + i</c> of the patch containing (x, y). A point on a line shared by two
        /// patches goes to the higher-index one (the interval is <c>[line_i, line_{i+1})</c>), except
        /// on the last line (1.0), which belongs to the last column/row. Points outside the unit
        /// square are clamped to the border patches, as the shader does. NaN throws.
        /// </summary>
        public int FindPatch(double x, double y)
        {
            if (double.IsNaN(x)) throw new ArgumentException("x = NaN: cannot locate a patch.", nameof(x));
            if (double.IsNaN(y)) throw new ArgumentException("y = NaN: cannot locate a patch.", nameof(y));
            return FindInterval(YLines, y) * Columns + FindInterval(XLines, x);
        }

        /// <summary>
        /// The largest i in [0, lines.Length - 2] with <c>lines[i] &lt;= x</c> (0 if none): binary
        /// search over the interior lines. Mirrors <c>PatchGridFindInterval</c> in HLSL.
        /// </summary>
        public static int FindInterval(ReadOnlySpan<double> lines, double x)
        {
            int lo = 0, hi = lines.Length - 2;
            while (lo < hi)
            {
                int mid = (lo + hi + 1) >> 1;
                if (lines[mid] <= x) lo = mid; else hi = mid - 1;
            }
            return lo;
        }

        /// <summary>Float version of <see cref="FindInterval(ReadOnlySpan{double}, double)"/>, on the float lines the GPU holds.</summary>
        public static int FindInterval(ReadOnlySpan<float> lines, float x)
        {
            // HLSL PatchGridFindInterval: first the interval a uniform grid would give, kept when its
            // lines bracket x; the same answer as the search (the lines increase).
            int count = lines.Length - 1;
            int g = x > 0f ? Math.Min((int)(Math.Min(x, 1f) * count), count - 1) : 0;
            if (lines[g] <= x && (g == count - 1 || lines[g + 1] > x)) return g;
            int lo = 0, hi = lines.Length - 2;
            while (lo < hi)
            {
                int mid = (lo + hi + 1) >> 1;
                if (lines[mid] <= x) lo = mid; else hi = mid - 1;
            }
            return lo;
        }

        void CheckCell(int i, int j)
        {
            if ((uint)i >= (uint)Columns)
                throw new ArgumentOutOfRangeException(nameof(i), i, string.Format(CultureInfo.InvariantCulture, "column i = {0} is not in 0..{1}.", i, Columns - 1));
            if ((uint)j >= (uint)Rows)
                throw new ArgumentOutOfRangeException(nameof(j), j, string.Format(CultureInfo.InvariantCulture, "row j = {0} is not in 0..{1}.", j, Rows - 1));
        }
    }
}
