using System;
using UnityEngine;

namespace GregoryTerrain
{
    // A grid edited patch by patch (a sculpt stroke's dabs: PatchGridAsset.ApplyEdit) reaches the GPU
    // buffers and the CPU query at the cost of the patches changed, not of the grid: no whole-grid
    // conversion, validation, upload or query rebuild per dab (PatchGridAsset.UpdatedPatchGrid).
    public sealed partial class GregoryTerrainRenderer
    {
        /// <summary>
        /// Uploads only the patches edited since the grid version in the buffers; false when that
        /// cannot be told (another grid, a whole-grid change, an undo): then the whole grid is uploaded.
        /// </summary>
        bool TryUploadEditedPatches()
        {
            if (_uploadedGrid != grid || _controlPoints == null) return false;
            PatchGrid g = grid.UpdatedPatchGrid(_uploadedPatchGrid, _uploadedVersion, out int[] changed);
            if (g == null) return false;
            var records = new GregoryPatchRecord[changed.Length];
            for (int k = 0; k < changed.Length; k++)
            {
                GregoryPatch p = g.Patches[changed[k]];
                records[k] = GpuLayout.PackPatchRecord(p);
                // The height range only widens (the draw bounds stay bounds); a whole upload tightens it.
                foreach (Double3 c in p.Points)
                {
                    _gridMinZ = Mathf.Min(_gridMinZ, (float)c.z);
                    _gridMaxZ = Mathf.Max(_gridMaxZ, (float)c.z);
                }
            }
            for (int start = 0, end; start < changed.Length; start = end)   // one SetData per run of consecutive patches
            {
                for (end = start + 1; end < changed.Length && changed[end] == changed[end - 1] + 1; end++) { }
                _controlPoints.SetData(records, start, changed[start], end - start);
            }
            _uploadedPatchGrid = g;
            _uploadedVersion = grid.Version;
            _gridStamp++;   // the vertex cache evaluates its tiles again; the settings block holds only the grid's size
            PatchUploadCount++;
            return true;
        }

        /// <summary>Uploads of edited patches only, since this renderer was created (the Unity-side tests check a dab makes one, not a whole upload).</summary>
        internal int PatchUploadCount { get; private set; }

        /// <summary>The query brought to the grid's version at the cost of the patches edited since; null when only a rebuild can tell.</summary>
        TerrainSurfaceQuery EditedQuery(NoiseSettings? noise, bool tiled)
        {
            if (_query == null || _queryAsset != grid || !Nullable.Equals(_queryNoise, noise) || _queryTiledNoise != tiled) return null;
            PatchGrid g = grid.UpdatedPatchGrid(_query.Grid, _queryVersion, out int[] changed);
            return g == null ? null : _query.WithPatches(g, changed);
        }
    }
}
