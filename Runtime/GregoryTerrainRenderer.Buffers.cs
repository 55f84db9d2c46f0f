using System;
using UnityEngine;

namespace GregoryTerrain
{
    // The renderer's GPU buffers: the grid uploaded once per asset version, the fallback's index grid.
    public sealed partial class GregoryTerrainRenderer
    {
        // The tiled noise's cell table (GT_NOISE_TABLE), while the material's noise is tiled.
        GraphicsBuffer _noiseCells;

        /// <summary>What the GPU objects, the draw material and the surface's query were made from (Core).</summary>
        internal FrameResources Resources => _state.resources;
        FrameResources _keys => _state.resources;

        /// <summary>Empties the property block and forgets what it held: the one place the block is cleared.</summary>
        void ClearPropertyBlock()
        {
            _props?.Clear();
            _state.Forget();   // the bindings set only on change too
        }

        static bool s_DeviceChecked;
        static string s_DeviceError;

        /// <summary>
        /// False where Unity cannot make structured buffers (GraphicsBuffer throws for Target.Structured
        /// unless SystemInfo.supportsComputeShaders), which every pass reads. Logged once a run.
        /// </summary>
        bool DeviceCanDraw()
        {
            if (!s_DeviceChecked)
            {
                s_DeviceChecked = true;
                if (!SystemInfo.supportsComputeShaders)
                {
                    s_DeviceError = "no compute support on this device (SystemInfo.supportsComputeShaders = false), so no structured buffers, which every pass reads: not drawn";
                    Debug.LogError($"Gregory Terrain: {s_DeviceError}.", this);
                }
            }
            return s_DeviceError == null;
        }

        /// <summary>Uploads the grid when it is new or changed; false when it cannot be drawn.</summary>
        bool EnsureUploaded()
        {
            var key = new GridVersionKey(grid.GetInstanceID(), grid.Version);
            UploadAction action = _keys.Upload(key, _controlPoints != null);
            if (action != UploadAction.Upload) return action == UploadAction.Keep;   // Skip: logged once; retried on the next version
            if (TryUploadEditedPatches(key)) return true;
            ReleaseGpuResources();
            PatchGrid g;
            try { g = grid.ToPatchGrid(); }
            catch (ArgumentException e)
            {
                Debug.LogError($"{name}: patch grid '{grid.name}' cannot be drawn: {e.Message}", this);
                _keys.UploadFailed(key);   // do not retry every frame
                return false;
            }
            GregoryPatchRecord[] records;
            float[] regions, lines;
            try
            {
                // GpuLayout validates (bit-identical shared edges, float-representable lines) and packs.
                records = GpuLayout.PackPatchRecords(g);
                regions = GpuLayout.PackRegions(g);
                lines = GpuLayout.PackGridLines(g);
            }
            catch (ArgumentException e)
            {
                Debug.LogError($"{name}: patch grid '{grid.name}' cannot be drawn: {e.Message}", this);
                _keys.UploadFailed(key);
                return false;
            }

            // One 320-byte record a patch (StructuredBuffer<GregoryPatchRecord>); the regions a float array
            // of float4 elements: count = floats / 4, stride 16 (GpuLayout.Float4Stride).
            _controlPoints = new GraphicsBuffer(GraphicsBuffer.Target.Structured, records.Length, GpuLayout.PatchRecordStride);
            _controlPoints.SetData(records);
            _regions = new GraphicsBuffer(GraphicsBuffer.Target.Structured, regions.Length / GpuLayout.Float4Size, GpuLayout.Float4Stride);
            _regions.SetData(regions);
            _gridLines = new GraphicsBuffer(GraphicsBuffer.Target.Structured, lines.Length, GpuLayout.GridLineStride);
            _gridLines.SetData(lines);

            _props ??= new MaterialPropertyBlock();
            SetBuffer(ShaderIds.ControlPoints, _controlPoints);
            SetBuffer(ShaderIds.Regions, _regions);
            SetBuffer(ShaderIds.GridLines, _gridLines);
            // _GridSize is part of TerrainParams: the block was cleared above, so the next plan sends it.
            grid.GetHeightRange(out _gridMinZ, out _gridMaxZ);

            _keys.Uploaded(key);
            _uploadedPatchGrid = g;
            _gridStamp++;
            UploadCount++;
            _state.ResetOrigins();
            return true;
        }

        /// <summary>The fallback's (F+1)^2-vertex grid as triangles, built when F changes.</summary>
        bool EnsureFallbackIndices()
        {
            if (!s_FallbackLogged)
            {
                s_FallbackLogged = true;
                Debug.Log("Gregory Terrain: the shader's tessellated SubShader is not used on this device " +
                          $"(SystemInfo.supportsTessellationShaders = {SystemInfo.supportsTessellationShaders}); " +
                          "drawing the vertex-shader fallback (a fixed grid per tile).", this);
            }
            int f = fallbackGridFactor;
            if (!_keys.RebuildFallbackIndices(f, _fallbackIndices != null)) return true;
            _fallbackIndices?.Release();
            var indices = new int[6 * f * f];
            int k = 0, row = f + 1;
            for (int t = 0; t < f; t++)
            for (int s = 0; s < f; s++)
            {
                int v = t * row + s;
                indices[k++] = v; indices[k++] = v + row; indices[k++] = v + 1;
                indices[k++] = v + 1; indices[k++] = v + row; indices[k++] = v + row + 1;
            }
            _fallbackIndices = new GraphicsBuffer(GraphicsBuffer.Target.Index, indices.Length, sizeof(int));
            _fallbackIndices.SetData(indices);
            return true;
        }

        /// <summary>
        /// True when the material's noise is tiled: GT_NOISE_TABLE with GT_NOISE or GT_HEIGHT_COLOR
        /// (the table alone changes nothing: no noise reads it).
        /// </summary>
        bool NoiseTableOn() =>
            material != null && material.IsKeywordEnabled(ShaderIds.NoiseTableKeyword)
            && (material.IsKeywordEnabled(ShaderIds.NoiseKeyword) || material.IsKeywordEnabled(ShaderIds.HeightColorKeyword));

        /// <summary>
        /// The tiled noise's table (<c>_NoiseCells</c>: 256 x 256 cells, 2 float4 each, 2 MiB), made
        /// from Core's <see cref="GradientNoiseTable"/> the first time the noise is tiled; released
        /// and null while it is not, so the default (hashed) noise holds no table at all.
        /// </summary>
        GraphicsBuffer EnsureNoiseTable()
        {
            if (!NoiseTableOn())
            {
                ReleaseNoiseTable();
                return null;
            }
            if (_noiseCells != null) return _noiseCells;
            float[] floats = GradientNoiseTable.Floats;   // shared with Core: read, never written
            _noiseCells = new GraphicsBuffer(GraphicsBuffer.Target.Structured,
                GradientNoiseTable.Size * GradientNoiseTable.Size * GradientNoiseTable.RowsPerCell, GpuLayout.Float4Stride);
            _noiseCells.SetData(floats);
            return _noiseCells;
        }

        /// <summary>The table on the property block when new or the block was cleared.</summary>
        void UpdateNoiseTableBinding()
        {
            GraphicsBuffer table = EnsureNoiseTable();
            if (_state.BindNoiseCells(table)) SetBuffer(ShaderIds.NoiseCells, table);
        }

        /// <summary>True while the tiled noise's table is held (the Unity-side tests).</summary>
        internal bool HasNoiseTable => _noiseCells != null;

        void ReleaseNoiseTable()
        {
            _noiseCells?.Release(); _noiseCells = null;
        }

        /// <summary>Releases every GPU buffer this renderer holds. Safe to call twice.</summary>
        public void ReleaseGpuResources()
        {
            _controlPoints?.Release(); _controlPoints = null;
            _regions?.Release(); _regions = null;
            _gridLines?.Release(); _gridLines = null;
            _fallbackIndices?.Release(); _fallbackIndices = null;
            ReleaseNoiseTable();
            _cache.Release();
            _uploadedPatchGrid = null;
            _keys.Released();   // uploaded again, the estimate's CPU copy dropped, the SubShader's tag read again
            ClearPropertyBlock();
        }

        /// <summary>Whole grid uploads (the Unity-side tests).</summary>
        internal int UploadCount { get; private set; }

        // ---- a grid edited patch by patch (a sculpt stroke's dabs: PatchGridAsset.ApplyEdit) reaches the
        // buffers and the query at the cost of the patches changed (PatchGridAsset.UpdatedPatchGrid)

        /// <summary>
        /// Uploads only the patches edited since the grid version in the buffers; false when that
        /// cannot be told (another grid, a whole-grid change, an undo): then the whole grid is uploaded.
        /// </summary>
        bool TryUploadEditedPatches(GridVersionKey key)
        {
            GridVersionKey held = _keys.HeldGrid;
            if (held.grid != key.grid || _controlPoints == null) return false;
            PatchGrid g = grid.UpdatedPatchGrid(_uploadedPatchGrid, held.version, out int[] changed);
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
            _keys.Uploaded(key);
            _gridStamp++;   // the vertex cache evaluates its tiles again; the settings block holds only the grid's size
            PatchUploadCount++;
            return true;
        }

        /// <summary>Uploads of edited patches only (the Unity-side tests).</summary>
        internal int PatchUploadCount { get; private set; }
    }
}
