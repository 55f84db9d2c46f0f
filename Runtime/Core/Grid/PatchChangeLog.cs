using System;
using System.Collections.Generic;

namespace GregoryTerrain
{
    /// <summary>
    /// Which patches a grid's patch-by-patch edits (brush dabs, region refits) changed, by the version
    /// each edit produced, so that a reader holding the grid at an older version (the renderer's GPU
    /// buffers, its CPU query) catches up on those patches only instead of converting, validating and
    /// uploading the whole grid on every dab. Any other change (a whole-grid replacement, an undo, a
    /// load) restarts the log: a reader from before it rebuilds. Versions are the asset's stamps,
    /// increasing but not consecutive.
    /// </summary>
    internal sealed class PatchChangeLog
    {
        readonly List<(int version, int[] patches)> _edits = new List<(int, int[])>();
        int _start;        // the version the log starts at; 0: none yet
        int _logged;       // patches held in _edits (with repeats)
        int _limit;        // beyond this a rebuild costs less than catching up

        /// <summary>Starts again at <paramref name="version"/> (a whole-grid change): older readers rebuild.</summary>
        public void Restart(int version, int patchCount)
        {
            _edits.Clear();
            _start = version;
            _logged = 0;
            _limit = Math.Max(patchCount, 1024);
        }

        /// <summary>The edit that produced <paramref name="version"/> changed <paramref name="patches"/> (kept, not copied).</summary>
        public void Add(int version, int[] patches)
        {
            if (patches == null) throw new ArgumentNullException(nameof(patches));
            if (_start == 0 || _logged + patches.Length > _limit) { Restart(version, _limit); return; }
            _edits.Add((version, patches));
            _logged += patches.Length;
        }

        /// <summary>
        /// The patches changed after <paramref name="version"/>, ascending and each once; null when the
        /// log cannot tell (the version is from before its start, or not one it produced).
        /// </summary>
        public int[] ChangedSince(int version)
        {
            if (_start == 0) return null;
            int first;
            if (version == _start) first = 0;
            else
            {
                first = _edits.FindIndex(e => e.version == version);
                if (first < 0) return null;
                first++;
            }
            var changed = new SortedSet<int>();
            for (int k = first; k < _edits.Count; k++) changed.UnionWith(_edits[k].patches);
            var result = new int[changed.Count];
            changed.CopyTo(result);
            return result;
        }

        /// <summary>
        /// <paramref name="previous"/> (the grid at <paramref name="previousVersion"/>) with the patches
        /// changed since, read from <paramref name="blocks"/> (the grid now), as a new grid sharing the
        /// unchanged patches and the lines: neither grid is written. Checked on the changed patches and
        /// their shared edges only (<see cref="PatchGrid.ValidatePatches"/>). Null when the log cannot
        /// tell or that check fails: the caller rebuilds the whole grid and reports what is wrong.
        /// </summary>
        public PatchGrid Update(PatchGrid previous, int previousVersion, double[][] blocks, out int[] changed)
        {
            changed = previous == null ? null : ChangedSince(previousVersion);
            if (changed == null) return null;
            var patches = (GregoryPatch[])previous.Patches.Clone();
            foreach (int p in changed) patches[p] = PatchGridBlocks.ReadPatch(blocks, p);
            var grid = new PatchGrid(previous.Columns, previous.Rows, previous.XLines, previous.YLines, patches);
            try { grid.ValidatePatches(changed); }
            catch (ArgumentException) { changed = null; return null; }
            return grid;
        }
    }
}
