using System;
using System.Globalization;
using UnityEngine;

namespace GregoryTerrain
{
    /// <summary>
    /// A patch grid saved as a Unity asset: the serializable form of Core's <see cref="PatchGrid"/>
    /// (internals.md: n columns, m rows, grid lines, 20 control points per patch in GregoryPatch slot
    /// order, patch <c>p = j * n + i</c>). Every change goes through <see cref="SetGrid"/> or
    /// <see cref="ImportJson"/>, which check the new data completely before touching the old, and
    /// stamps a new <see cref="Version"/> so renderers upload again only when the grid changed.
    /// </summary>
    [CreateAssetMenu(menuName = "Gregory Terrain/Patch Grid", fileName = "PatchGrid", order = 200)]
    public sealed class PatchGridAsset : ScriptableObject
    {
        /// <summary>Doubles per patch in <see cref="controlPoints"/>: 20 points of (x, y, z).</summary>
        public const int DoublesPerPatch = 3 * 20;

        [Tooltip("Number of patch columns n (along x, the patch index i).")]
        [SerializeField, Min(1)] int columns = 1;

        [Tooltip("Number of patch rows m (along y, the patch index j).")]
        [SerializeField, Min(1)] int rows = 1;

        [Tooltip("Vertical grid lines x[0..n], strictly increasing from 0 to 1: patch (i, j) spans x[i]..x[i+1].")]
        [SerializeField] double[] xLines = { 0.0, 1.0 };

        [Tooltip("Horizontal grid lines y[0..m], strictly increasing from 0 to 1: patch (i, j) spans y[j]..y[j+1].")]
        [SerializeField] double[] yLines = { 0.0, 1.0 };

        [Tooltip("20 control points (x, y, z) per patch, GregoryPatch slot order, patch p = j * n + i. " +
                 "Edit with the Patch Grid window or the Scene-view handles, not by hand.")]
        [SerializeField] double[] controlPoints = FlatPatch();

        // Version stamps come from one process-wide counter, so a stamp is never reused: after an undo
        // the asset gets a fresh stamp too, and a renderer never mistakes old data for uploaded data.
        static int s_NextVersion = 1;
        [NonSerialized] int _version;
        [NonSerialized] string _error;

        /// <summary>Changes whenever the grid data may have changed (edit, undo, import, load).</summary>
        public int Version => _version;

        /// <summary>Patch columns n.</summary>
        public int Columns => columns;

        /// <summary>Patch rows m.</summary>
        public int Rows => rows;

        /// <summary>Number of patches n * m.</summary>
        public int PatchCount => columns * rows;

        /// <summary>Why the serialized data is not a valid grid (names the field and value), or null.</summary>
        public string ValidationError => _error;

        /// <summary>True when the serialized data is a valid grid.</summary>
        public bool IsValid => _error == null;

        void OnEnable() => MarkChanged();

        void OnValidate() => MarkChanged();

        /// <summary>
        /// Re-validates and stamps a new version. Editor code calls it after changing the serialized
        /// data directly (handles, undo/redo); <see cref="SetGrid"/> calls it itself.
        /// </summary>
        public void MarkChanged()
        {
            _version = s_NextVersion++;
            _error = CheckSerializedData();
            if (_error != null)
                Debug.LogError($"Patch grid '{name}' is invalid: {_error}", this);
        }

        /// <summary>The grid as Core's <see cref="PatchGrid"/>. Throws ArgumentException when invalid.</summary>
        internal PatchGrid ToPatchGrid()
        {
            string error = CheckSerializedData();
            if (error != null) throw new ArgumentException(error);
            var patches = new GregoryPatch[columns * rows];
            for (int p = 0; p < patches.Length; p++)
            {
                var patch = new GregoryPatch();
                int k0 = p * DoublesPerPatch;
                for (int s = 0; s < GregoryPatch.SlotCount; s++)
                    patch[s] = new Double3(controlPoints[k0 + 3 * s], controlPoints[k0 + 3 * s + 1], controlPoints[k0 + 3 * s + 2]);
                patches[p] = patch;
            }
            return new PatchGrid(columns, rows, (double[])xLines.Clone(), (double[])yLines.Clone(), patches);
        }

        /// <summary>
        /// Replaces the data with <paramref name="grid"/> (already validated by PatchGrid). Nothing
        /// changes if the copy fails. Record an undo step before calling it from the editor.
        /// </summary>
        internal void SetGrid(PatchGrid grid)
        {
            if (grid == null) throw new ArgumentNullException(nameof(grid));
            int n = grid.Columns, m = grid.Rows;
            var xs = new double[n + 1];
            var ys = new double[m + 1];
            for (int i = 0; i <= n; i++) xs[i] = grid.XLines[i];
            for (int j = 0; j <= m; j++) ys[j] = grid.YLines[j];
            var cps = new double[n * m * DoublesPerPatch];
            for (int p = 0; p < n * m; p++)
            {
                GregoryPatch patch = grid.Patches[p];
                for (int s = 0; s < GregoryPatch.SlotCount; s++)
                {
                    Double3 q = patch[s];
                    int k = p * DoublesPerPatch + 3 * s;
                    cps[k] = q.x; cps[k + 1] = q.y; cps[k + 2] = q.z;
                }
            }
            // Everything is built; only now replace the old data.
            columns = n; rows = m; xLines = xs; yLines = ys; controlPoints = cps;
            MarkChanged();
        }

        /// <summary>The grid as JSON (Core's PatchGridJson format).</summary>
        public string ExportJson() => PatchGridJson.Write(ToPatchGrid());

        /// <summary>
        /// Replaces the grid with the one in <paramref name="json"/>. A FormatException or
        /// ArgumentException from the parser leaves the current data untouched.
        /// </summary>
        public void ImportJson(string json)
        {
            PatchGrid grid = PatchGridJson.Read(json);   // throws before anything changes
            SetGrid(grid);
        }

        /// <summary>Control point <paramref name="slot"/> of patch <paramref name="patch"/>, terrain space.</summary>
        public Vector3 GetControlPoint(int patch, int slot)
        {
            int k = Index(patch, slot);
            return new Vector3((float)controlPoints[k], (float)controlPoints[k + 1], (float)controlPoints[k + 2]);
        }

        /// <summary>
        /// Moves one control point (terrain space). Record an undo step first. A boundary point is
        /// stored once per patch that shares it, bit for bit (PatchGrid.Validate and the GPU's
        /// watertight edges rely on it), so every copy in the neighbouring patches moves with it.
        /// Does not enforce G1: run the Patch Grid window's "Enforce G1" afterwards if the grid must
        /// stay smooth.
        /// </summary>
        public void SetControlPoint(int patch, int slot, Vector3 terrainPosition)
        {
            int k = Index(patch, slot);
            if (!float.IsFinite(terrainPosition.x) || !float.IsFinite(terrainPosition.y) || !float.IsFinite(terrainPosition.z))
                throw new ArgumentException($"control point ({patch}, {slot}) = {terrainPosition} must be finite", nameof(terrainPosition));
            double ox = controlPoints[k], oy = controlPoints[k + 1], oz = controlPoints[k + 2];
            if (IsBoundarySlot(slot))
            {
                // The copies of a shared boundary point sit in the 3 x 3 block of patches around it.
                int pi = patch % columns, pj = patch / columns;
                for (int j = Math.Max(pj - 1, 0); j <= Math.Min(pj + 1, rows - 1); j++)
                for (int i = Math.Max(pi - 1, 0); i <= Math.Min(pi + 1, columns - 1); i++)
                for (int s = 0; s < 16; s++)
                {
                    if (!IsBoundarySlot(s)) continue;
                    int q = (j * columns + i) * DoublesPerPatch + 3 * s;
                    if (q == k) continue;
                    if (SameBits(controlPoints[q], ox) && SameBits(controlPoints[q + 1], oy) && SameBits(controlPoints[q + 2], oz))
                    {
                        controlPoints[q] = terrainPosition.x;
                        controlPoints[q + 1] = terrainPosition.y;
                        controlPoints[q + 2] = terrainPosition.z;
                    }
                }
            }
            controlPoints[k] = terrainPosition.x;
            controlPoints[k + 1] = terrainPosition.y;
            controlPoints[k + 2] = terrainPosition.z;
            MarkChanged();
        }

        /// <summary>Slots 0..15 on the border of the 4 x 4 net (i or j is 0 or 3), slot = 4 i + j.</summary>
        static bool IsBoundarySlot(int slot) => slot < 16 && (slot / 4 == 0 || slot / 4 == 3 || slot % 4 == 0 || slot % 4 == 3);

        static bool SameBits(double a, double b) => BitConverter.DoubleToInt64Bits(a) == BitConverter.DoubleToInt64Bits(b);

        /// <summary>Smallest and largest control point height (z); the surface lies between them.</summary>
        public void GetHeightRange(out float minZ, out float maxZ)
        {
            minZ = float.PositiveInfinity; maxZ = float.NegativeInfinity;
            if (controlPoints == null) { minZ = maxZ = 0f; return; }
            for (int k = 2; k < controlPoints.Length; k += 3)
            {
                float z = (float)controlPoints[k];
                if (z < minZ) minZ = z;
                if (z > maxZ) maxZ = z;
            }
            if (minZ > maxZ) minZ = maxZ = 0f;
        }

        int Index(int patch, int slot)
        {
            if (patch < 0 || patch >= PatchCount)
                throw new ArgumentOutOfRangeException(nameof(patch), patch, $"patch must lie in [0, {PatchCount})");
            if (slot < 0 || slot >= GregoryPatch.SlotCount)
                throw new ArgumentOutOfRangeException(nameof(slot), slot, $"slot must lie in [0, {GregoryPatch.SlotCount})");
            return patch * DoublesPerPatch + 3 * slot;
        }

        /// <summary>Checks the serialized layout; returns a message naming field and value, or null.</summary>
        string CheckSerializedData()
        {
            if (columns < 1) return $"columns = {columns}, must be at least 1";
            if (rows < 1) return $"rows = {rows}, must be at least 1";
            string e = CheckLines("xLines", xLines, columns) ?? CheckLines("yLines", yLines, rows);
            if (e != null) return e;
            int expected = columns * rows * DoublesPerPatch;
            if (controlPoints == null || controlPoints.Length != expected)
                return $"controlPoints.Length = {controlPoints?.Length ?? 0}, expected {expected} (= 60 x {columns} x {rows})";
            for (int k = 0; k < controlPoints.Length; k++)
            {
                if (!double.IsFinite(controlPoints[k]))
                    return $"controlPoints[{k}] (patch {k / DoublesPerPatch}, slot {k % DoublesPerPatch / 3}) = " +
                           controlPoints[k].ToString(CultureInfo.InvariantCulture) + ", must be finite";
            }
            return PatchGrid.SerializedDataError(columns, rows, xLines, yLines, controlPoints);
        }

        static string CheckLines(string field, double[] lines, int cells)
        {
            if (lines == null || lines.Length != cells + 1)
                return $"{field}.Length = {lines?.Length ?? 0}, expected {cells + 1}";
            if (lines[0] != 0.0) return $"{field}[0] = {F(lines[0])}, must be 0";
            if (lines[cells] != 1.0) return $"{field}[{cells}] = {F(lines[cells])}, must be 1";
            for (int i = 1; i <= cells; i++)
                if (!(lines[i] > lines[i - 1]))
                    return $"{field}[{i}] = {F(lines[i])} is not greater than {field}[{i - 1}] = {F(lines[i - 1])}";
            return null;
        }

        static string F(double v) => v.ToString("R", CultureInfo.InvariantCulture);

        /// <summary>The default one-patch grid: a flat Bezier patch at height 0 over the unit square.</summary>
        static double[] FlatPatch()
        {
            var cps = new double[DoublesPerPatch];
            for (int i = 0; i < 4; i++)
            for (int j = 0; j < 4; j++)
            {
                int s = 4 * i + j;
                cps[3 * s] = i / 3.0; cps[3 * s + 1] = j / 3.0;
            }
            // Slots 16..19 repeat the interior slots 5, 6, 9, 10 (a Gregory patch equal to its Bezier patch).
            int[] firsts = { 5, 6, 9, 10 };
            for (int r = 0; r < 4; r++)
                for (int c = 0; c < 3; c++) cps[3 * (16 + r) + c] = cps[3 * firsts[r] + c];
            return cps;
        }
    }
}
