using System;
using System.Globalization;
using UnityEngine;

namespace GregoryTerrain
{
    /// <summary>
    /// A patch grid saved as a Unity asset: the serializable form of Core's <see cref="PatchGrid"/>
    /// (internals.md, "The tile layout"). The control points live in <see cref="PatchGridBlock"/>
    /// sub-assets of 64 patches (Core's <see cref="PatchGridBlocks"/>), so Undo records only the
    /// blocks an edit changes; the asset is binary (<see cref="PreferBinarySerialization"/>, as
    /// TerrainData). The single <c>controlPoints</c> array layout still loads; the first edit moves it
    /// into blocks. Every change goes through <see cref="SetGrid(PatchGrid)"/>, <see cref="ImportJson"/>
    /// or <see cref="SetControlPoint"/>, which check the new data before touching the old, and stamps
    /// a new <see cref="Version"/>.
    /// </summary>
    [CreateAssetMenu(menuName = "Gregory Terrain/Patch Grid", fileName = "PatchGrid", order = 200)]
    [PreferBinarySerialization]
    public sealed class PatchGridAsset : ScriptableObject
    {
        /// <summary>Doubles per patch: 20 points of (x, y, z).</summary>
        public const int DoublesPerPatch = PatchGridBlocks.DoublesPerPatch;

        [Tooltip("Number of patch columns n (along x, the patch index i).")]
        [SerializeField, Min(1)] int columns = 1;

        [Tooltip("Number of patch rows m (along y, the patch index j).")]
        [SerializeField, Min(1)] int rows = 1;

        [Tooltip("Positions of the vertical grid lines, strictly increasing from 0 to 1. Each patch column lies between two neighbouring lines.")]
        [SerializeField] double[] xLines = { 0.0, 1.0 };

        [Tooltip("Positions of the horizontal grid lines, strictly increasing from 0 to 1. Each patch row lies between two neighbouring lines.")]
        [SerializeField] double[] yLines = { 0.0, 1.0 };

        [Tooltip("The control point blocks (sub-assets of this grid), 64 patches each. Edit with the Patch Grid window or the Scene-view handles.")]
        [SerializeField] PatchGridBlock[] blocks = Array.Empty<PatchGridBlock>();

        // The single-array layout: read when blocks is empty, emptied when moved into blocks.
        [SerializeField, HideInInspector] double[] controlPoints = FlatPatch();

        // Stamps come from one process-wide counter, never reused: an undo gets a fresh one too.
        static int s_NextVersion = 1;
        [NonSerialized] int _version;
        [NonSerialized] string _error;
        [NonSerialized] double[][] _legacyBlocks;   // controlPoints cut into blocks, read-only view
        [NonSerialized] bool _changedSinceCheck;    // MarkChangedOnNextRead was called: check on the next read
        [NonSerialized] ulong _fingerprint;         // of the data last checked (MarkChanged): an undo that restores nothing of ours keeps the version
        [NonSerialized] ulong[] _blockHashes;       // per block, for _fingerprint: an edit hashes again only the blocks it wrote
        [NonSerialized] PatchChangeLog _changes = new PatchChangeLog();   // the patches each edit changed, for readers to catch up

        /// <summary>Changes whenever the grid data may have changed (edit, undo, import, load).</summary>
        public int Version { get { CheckIfChanged(); return _version; } }

        /// <summary>Patch columns n.</summary>
        public int Columns => columns;

        /// <summary>Patch rows m.</summary>
        public int Rows => rows;

        /// <summary>Number of patches n * m.</summary>
        public int PatchCount => columns * rows;

        /// <summary>Why the serialized data is not a valid grid (names the field and value), or null.</summary>
        public string ValidationError { get { CheckIfChanged(); return _error; } }

        /// <summary>True when the serialized data is a valid grid.</summary>
        public bool IsValid { get { CheckIfChanged(); return _error == null; } }

        /// <summary>True while the control points are in the single-array layout.</summary>
        internal bool HasLegacyLayout => (blocks == null || blocks.Length == 0) && controlPoints != null && controlPoints.Length > 0;

        /// <summary>The grid lines as serialized, for readers that need no grid; never write into them.</summary>
        internal double[] XLinesData => xLines;
        internal double[] YLinesData => yLines;

        /// <summary>The control point blocks (empty while <see cref="HasLegacyLayout"/>). A copy of the array.</summary>
        internal PatchGridBlock[] Blocks => blocks == null ? Array.Empty<PatchGridBlock>() : (PatchGridBlock[])blocks.Clone();

        // Loading only marks the grid: the whole-grid check runs at its first read.
        void OnEnable() => MarkChangedOnNextRead();

        void OnValidate() => MarkChangedOnNextRead();

        /// <summary>Re-validates and stamps a new version; for editor code that changed the serialized data directly.</summary>
        public void MarkChanged()
        {
            _changedSinceCheck = false;
            _version = s_NextVersion++;
            _legacyBlocks = null;
            _blockHashes = PatchGridBlocks.BlockHashes(HashedData());
            _fingerprint = Fingerprint();
            _changes.Restart(_version, Math.Max(1, PatchCount));
            _error = CheckSerializedData();
            if (_error != null)
                Debug.LogError($"Patch grid '{name}' is invalid: {_error}", this);
        }

        /// <summary>
        /// Like <see cref="MarkChanged"/>, but the whole-grid check runs once, at the next read of
        /// <see cref="Version"/>, <see cref="IsValid"/> or <see cref="ValidationError"/>: OnValidate
        /// comes once per block on load and undo.
        /// </summary>
        internal void MarkChangedOnNextRead()
        {
            _changedSinceCheck = true;
            _legacyBlocks = null;   // Data() may be read before the check: never from the old array
        }

        void CheckIfChanged()
        {
            if (!_changedSinceCheck) return;
            // Any undo marks every loaded grid (Unity does not say which it restored): when the data hash
            // matches what was last checked, keep the verdict and version, so renderers do not re-upload.
            if (_version != 0 && PatchGridBlocks.Combine(HeaderHash(), PatchGridBlocks.BlockHashes(HashedData())) == _fingerprint)
            {
                _changedSinceCheck = false;
                return;
            }
            MarkChanged();
        }

        /// <summary>Fingerprint of everything the grid is made of: shape, lines and control points (the blocks' hashes as last computed).</summary>
        ulong Fingerprint() => PatchGridBlocks.Combine(HeaderHash(), _blockHashes);

        ulong HeaderHash()
        {
            ulong h = PatchGridBlocks.Mix((ulong)(uint)columns, (ulong)(uint)rows);
            if (xLines != null) foreach (double v in xLines) h = PatchGridBlocks.Mix(h, (ulong)BitConverter.DoubleToInt64Bits(v));
            h = PatchGridBlocks.Mix(h, 0x5E9UL);
            if (yLines != null) foreach (double v in yLines) h = PatchGridBlocks.Mix(h, (ulong)BitConverter.DoubleToInt64Bits(v));
            return PatchGridBlocks.Mix(h, HasLegacyLayout ? 1UL : 2UL);
        }

        /// <summary>The arrays the fingerprint hashes (null for a missing block).</summary>
        double[][] HashedData()
        {
            if (HasLegacyLayout) return new[] { controlPoints };
            var data = new double[blocks?.Length ?? 0][];
            for (int b = 0; b < data.Length; b++) data[b] = blocks[b] != null ? blocks[b].Points : null;
            return data;
        }

        /// <summary>
        /// The grid as Core's <see cref="PatchGrid"/>, new patches each call, using the kept verdict
        /// (<see cref="IsValid"/>). Throws ArgumentException when invalid.
        /// </summary>
        internal PatchGrid ToPatchGrid()
        {
            if (!IsValid) throw new ArgumentException(_error);
            return new PatchGrid(columns, rows, (double[])xLines.Clone(), (double[])yLines.Clone(), PatchGridBlocks.ToPatches(Data(), PatchCount));
        }

        /// <summary>
        /// <paramref name="previous"/> (this grid at <paramref name="previousVersion"/>) brought to this
        /// version by the patches edited since (<see cref="ApplyEdit"/>), sharing unchanged patches. Null,
        /// with <paramref name="changed"/> null, when only a whole rebuild (<see cref="ToPatchGrid"/>) can tell.
        /// </summary>
        internal PatchGrid UpdatedPatchGrid(PatchGrid previous, int previousVersion, out int[] changed)
        {
            changed = null;
            if (!IsValid || HasLegacyLayout) return null;
            return _changes.Update(previous, previousVersion, Data(), out changed);
        }

        /// <summary>
        /// Replaces the data with <paramref name="grid"/> (validated) whose blocks are
        /// <paramref name="data"/>; existing blocks are written in place, <paramref name="created"/> are
        /// new (the editor adds them as sub-assets), <paramref name="dropped"/> unused (the editor destroys
        /// them with Undo). Record the asset and the changed blocks first.
        /// </summary>
        internal void SetGrid(PatchGrid grid, double[][] data, out PatchGridBlock[] created, out PatchGridBlock[] dropped)
        {
            if (grid == null) throw new ArgumentNullException(nameof(grid));
            string shape = PatchGridBlocks.CheckShape(data, grid.PatchCount);
            if (shape != null) throw new ArgumentException(shape, nameof(data));
            int n = grid.Columns, m = grid.Rows;
            var xs = new double[n + 1];
            var ys = new double[m + 1];
            for (int i = 0; i <= n; i++) xs[i] = grid.XLines[i];
            for (int j = 0; j <= m; j++) ys[j] = grid.YLines[j];
            // Everything is built; only now replace the old data.
            PatchGridBlock[] old = blocks ?? Array.Empty<PatchGridBlock>();
            var next = new PatchGridBlock[data.Length];
            var made = new System.Collections.Generic.List<PatchGridBlock>();
            for (int b = 0; b < next.Length; b++)
            {
                if (b < old.Length && old[b] != null) { next[b] = old[b]; next[b].Points = data[b]; }
                else { next[b] = PatchGridBlock.Create(this, b, data[b]); made.Add(next[b]); }
            }
            var unused = new System.Collections.Generic.List<PatchGridBlock>();
            for (int b = next.Length; b < old.Length; b++) if (old[b] != null) unused.Add(old[b]);
            columns = n; rows = m; xLines = xs; yLines = ys; blocks = next; controlPoints = Array.Empty<double>();
            created = made.ToArray();
            dropped = unused.ToArray();
            MarkChanged();
        }

        /// <summary>
        /// Replaces the data with <paramref name="grid"/>, destroying blocks no longer used. For code
        /// outside the editor; the editor goes through PatchGridAssetUndo.SetGrid.
        /// </summary>
        internal void SetGrid(PatchGrid grid)
        {
            if (grid == null) throw new ArgumentNullException(nameof(grid));
            SetGrid(grid, PatchGridBlocks.FromGrid(grid), out PatchGridBlock[] created, out PatchGridBlock[] dropped);
            bool inFile = false;
#if UNITY_EDITOR
            // Blocks of a saved grid are sub-assets: new ones must join the file, old ones leave it.
            inFile = UnityEditor.AssetDatabase.Contains(this);
            if (inFile)
            {
                foreach (PatchGridBlock b in created) UnityEditor.AssetDatabase.AddObjectToAsset(b, this);
                UnityEditor.EditorUtility.SetDirty(this);
            }
#endif
            foreach (PatchGridBlock b in dropped)
            {
                if (inFile) DestroyImmediate(b, true);   // a sub-asset: destroying it removes it from the file
                else if (Application.isPlaying) Destroy(b);
                else DestroyImmediate(b);
            }
        }

        /// <summary>
        /// The existing blocks that <see cref="SetGrid(PatchGrid, double[][], out PatchGridBlock[], out PatchGridBlock[])"/>
        /// with <paramref name="data"/> changes: what a whole-grid replacement records for Undo.
        /// </summary>
        internal PatchGridBlock[] BlocksChangedBy(double[][] data)
        {
            if (HasLegacyLayout || blocks == null) return Array.Empty<PatchGridBlock>();
            var current = new double[Math.Min(blocks.Length, data.Length)][];
            for (int b = 0; b < current.Length; b++) current[b] = blocks[b] != null ? blocks[b].Points : null;
            var changed = new System.Collections.Generic.List<PatchGridBlock>();
            foreach (int b in PatchGridBlocks.ChangedBlocks(current, data))
                if (b < current.Length && blocks[b] != null) changed.Add(blocks[b]);
            return changed.ToArray();
        }

        /// <summary>Moves the single-array layout into new blocks, bit for bit (returned; the editor adds them as sub-assets); none when already in blocks.</summary>
        internal PatchGridBlock[] MoveLegacyDataToBlocks()
        {
            if (!HasLegacyLayout) return Array.Empty<PatchGridBlock>();
            string error = CheckSerializedData();
            if (error != null) throw new InvalidOperationException($"Patch grid '{name}' cannot be upgraded: {error}");
            double[][] data = PatchGridBlocks.Split(controlPoints, PatchCount);
            var made = new PatchGridBlock[data.Length];
            for (int b = 0; b < data.Length; b++) made[b] = PatchGridBlock.Create(this, b, data[b]);
            blocks = made;
            controlPoints = Array.Empty<double>();
            MarkChanged();
            return made;
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
            CheckIndex(patch, slot);
            // One block, not Data() (allocates the list): handles read every point each repaint.
            int b = PatchGridBlocks.BlockOf(patch);
            Double3 q = PatchGridBlocks.Get(HasLegacyLayout ? Data()[b] : blocks[b].Points, patch, slot);
            return new Vector3((float)q.x, (float)q.y, (float)q.z);
        }

        /// <summary>
        /// The blocks <see cref="SetControlPoint"/> may change for this point (its neighbours' too, for a
        /// shared point): record them for Undo first. Empty in the single-array layout.
        /// </summary>
        internal PatchGridBlock[] BlocksTouchedByMove(int patch, int slot)
        {
            CheckIndex(patch, slot);
            if (HasLegacyLayout) return Array.Empty<PatchGridBlock>();
            int[] touched = PatchGridBlocks.BlocksTouchedByMove(columns, rows, patch, slot);
            var result = new PatchGridBlock[touched.Length];
            for (int k = 0; k < touched.Length; k++) result[k] = blocks[touched[k]];
            return result;
        }

        /// <summary>
        /// Moves one control point (terrain space) and every bit-identical copy of it in neighbouring
        /// patches. Record <see cref="BlocksTouchedByMove"/> first. Does not enforce G1.
        /// </summary>
        public void SetControlPoint(int patch, int slot, Vector3 terrainPosition)
        {
            CheckIndex(patch, slot);
            if (HasLegacyLayout)
                throw new InvalidOperationException($"Patch grid '{name}' still has the older single-array layout: move its data to blocks first (MoveLegacyDataToBlocks)");
            // The kept verdict: a handle drag calls this every mouse move.
            if (!IsValid) throw new InvalidOperationException($"Patch grid '{name}' is invalid: {ValidationError}");
            PatchGridBlocks.MoveControlPoint(Data(), columns, rows, patch, slot,
                new Double3(terrainPosition.x, terrainPosition.y, terrainPosition.z));
            MarkChanged();
        }

        /// <summary>Index of the patch holding terrain point (x, y); outside points go to the border patches.</summary>
        internal int FindPatch(double x, double y)
        {
            if (double.IsNaN(x) || double.IsNaN(y)) throw new ArgumentException($"({x}, {y}) is not a point: cannot locate a patch.");
            return PatchGrid.FindInterval(yLines, y) * columns + PatchGrid.FindInterval(xLines, x);
        }

        /// <summary>The blocks holding the patches an edit changes (record these for Undo before <see cref="ApplyEdit"/>). Empty while the grid has the older layout.</summary>
        internal PatchGridBlock[] BlocksOf(PatchEdit edit)
        {
            if (edit == null) throw new ArgumentNullException(nameof(edit));
            if (HasLegacyLayout) return Array.Empty<PatchGridBlock>();
            var touched = new System.Collections.Generic.SortedSet<int>();
            foreach (int p in edit.Patches) touched.Add(PatchGridBlocks.BlockOf(p));
            var result = new PatchGridBlock[touched.Count];
            int k = 0;
            foreach (int b in touched) result[k++] = blocks[b];
            return result;
        }

        /// <summary>
        /// Writes an edit's patches (Core's PatchEdit, built and checked against this grid) into the
        /// blocks: a valid grid stays valid, so no whole-grid check a dab. Throws, changing nothing, when
        /// the grid is invalid, in the single-array layout, or of another shape.
        /// </summary>
        internal void ApplyEdit(PatchEdit edit)
        {
            if (edit == null) throw new ArgumentNullException(nameof(edit));
            if (HasLegacyLayout)
                throw new InvalidOperationException($"Patch grid '{name}' still has the older single-array layout: move its data to blocks first (MoveLegacyDataToBlocks)");
            if (!IsValid) throw new InvalidOperationException($"Patch grid '{name}' is invalid: {ValidationError}");
            if (edit.Columns != columns || edit.Rows != rows)
                throw new ArgumentException($"edit is for {edit.Columns} x {edit.Rows} patches, the grid has {columns} x {rows}", nameof(edit));
            double[][] data = Data();
            for (int k = 0; k < edit.Patches.Length; k++) PatchGridBlocks.SetPatch(data, edit.Patches[k], edit.Values[k]);
            _changedSinceCheck = false;
            _version = s_NextVersion++;
            PatchGridBlocks.Rehash(_blockHashes, data, edit.Patches);
            _fingerprint = Fingerprint();
            _changes.Add(_version, edit.Patches);
        }

        /// <summary>Smallest and largest control point height (z); the surface lies between them.</summary>
        public void GetHeightRange(out float minZ, out float maxZ)
        {
            minZ = float.PositiveInfinity; maxZ = float.NegativeInfinity;
            if (IsValid)
                foreach (double[] a in Data())
                    for (int k = 2; k < a.Length; k += 3)
                    {
                        float z = (float)a[k];
                        if (z < minZ) minZ = z;
                        if (z > maxZ) maxZ = z;
                    }
            if (minZ > maxZ) minZ = maxZ = 0f;
        }

        /// <summary>The control points as Core blocks: the block objects' arrays, or the older array cut into blocks.</summary>
        double[][] Data()
        {
            if (HasLegacyLayout) return _legacyBlocks ??= PatchGridBlocks.Split(controlPoints, PatchCount);
            var data = new double[blocks.Length][];
            for (int b = 0; b < blocks.Length; b++) data[b] = blocks[b] != null ? blocks[b].Points : null;
            return data;
        }

        void CheckIndex(int patch, int slot)
        {
            if (patch < 0 || patch >= PatchCount)
                throw new ArgumentOutOfRangeException(nameof(patch), patch, $"patch must lie in [0, {PatchCount})");
            if (slot < 0 || slot >= GregoryPatch.SlotCount)
                throw new ArgumentOutOfRangeException(nameof(slot), slot, $"slot must lie in [0, {GregoryPatch.SlotCount})");
        }

        /// <summary>Checks the serialized layout; returns a message naming field and value, or null.</summary>
        string CheckSerializedData()
        {
            if (columns < 1) return $"columns = {columns}, must be at least 1";
            if (rows < 1) return $"rows = {rows}, must be at least 1";
            string e = CheckLines("xLines", xLines, columns) ?? CheckLines("yLines", yLines, rows);
            if (e != null) return e;
            if (HasLegacyLayout)
            {
                int expected = columns * rows * DoublesPerPatch;
                if (controlPoints.Length != expected)
                    return $"controlPoints.Length = {controlPoints.Length}, expected {expected} (= 60 x {columns} x {rows})";
            }
            else
            {
                if (blocks == null || blocks.Length == 0) return "blocks is empty and there is no controlPoints array";
                for (int b = 0; b < blocks.Length; b++)
                    if (blocks[b] == null) return $"blocks[{b}] is missing (a deleted sub-asset?)";
                e = PatchGridBlocks.CheckShape(Data(), PatchCount);
                if (e != null) return e;
            }
            if (HasLegacyLayout) return PatchGrid.SerializedDataError(columns, rows, xLines, yLines, controlPoints);
            // The same rules as the flat layout (Core's PatchGrid.Validate), on the blocks' patches.
            try
            {
                GpuLayout.CheckSize(columns, rows);
                new PatchGrid(columns, rows, xLines, yLines, PatchGridBlocks.ToPatches(Data(), PatchCount)).Validate();
                return null;
            }
            catch (ArgumentException ex)
            {
                return ex.Message;
            }
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
