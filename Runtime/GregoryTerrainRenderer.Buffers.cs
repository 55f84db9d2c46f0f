using System;
using UnityEngine;

namespace GregoryTerrain
{
    // When the GPU buffers (TerrainGpuBuffers) are made, bound and released, as FrameResources decides.
    public sealed partial class GregoryTerrainRenderer
    {
        readonly TerrainGpuBuffers _gpu = new TerrainGpuBuffers();

        // What the GPU objects, the draw material and the surface's query were made from (Core).
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
            UploadAction action = _keys.Upload(key, _gpu.ControlPoints != null);
            if (action != UploadAction.Upload) return action == UploadAction.Keep;   // Skip: logged once; retried on the next version
            if (TryUploadEditedPatches(key)) return true;
            ReleaseGpuResources();
            string error = null;
            PatchGrid g = null;
            try { g = grid.ToPatchGrid(); }
            catch (ArgumentException e) { error = e.Message; }
            error ??= _gpu.Upload(g);
            if (error != null)
            {
                Debug.LogError($"{name}: patch grid '{grid.name}' cannot be drawn: {error}", this);
                _keys.UploadFailed(key);   // do not retry every frame
                return false;
            }

            _props ??= new MaterialPropertyBlock();
            SetBuffer(ShaderIds.ControlPoints, _gpu.ControlPoints);
            SetBuffer(ShaderIds.Regions, _gpu.Regions);
            SetBuffer(ShaderIds.GridLines, _gpu.GridLines);
            // _GridSize is part of TerrainParams: the block was cleared above, so the next plan sends it.
            grid.GetHeightRange(out float minZ, out float maxZ);

            _keys.Uploaded(key, minZ, maxZ);
            _gridStamp++;
            UploadCount++;
            _state.ResetOrigins();
            return true;
        }

        /// <summary>The fallback's index grid, built when F changes; its use logged once a run.</summary>
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
            if (_keys.RebuildFallbackIndices(f, _gpu.FallbackIndices != null)) _gpu.BuildFallbackIndices(f);
            return true;
        }

        /// <summary>
        /// True when the material's noise is tiled: GT_NOISE_TABLE with GT_NOISE or GT_HEIGHT_COLOR
        /// (the table alone changes nothing: no noise reads it).
        /// </summary>
        bool NoiseTableOn() =>
            material != null && material.IsKeywordEnabled(ShaderIds.NoiseTableKeyword)
            && (material.IsKeywordEnabled(ShaderIds.NoiseKeyword) || material.IsKeywordEnabled(ShaderIds.HeightColorKeyword));

        /// <summary>The table while the noise is tiled, else released and null: the default (hashed) noise holds none.</summary>
        GraphicsBuffer EnsureNoiseTable()
        {
            if (NoiseTableOn()) return _gpu.EnsureNoiseTable();
            _gpu.ReleaseNoiseTable();
            return null;
        }

        /// <summary>The table on the property block when new or the block was cleared.</summary>
        void UpdateNoiseTableBinding()
        {
            GraphicsBuffer table = EnsureNoiseTable();
            if (_state.BindNoiseCells(table)) SetBuffer(ShaderIds.NoiseCells, table);
        }

        /// <summary>True while the tiled noise's table is held (the Unity-side tests).</summary>
        internal bool HasNoiseTable => _gpu.NoiseCells != null;

        /// <summary>Releases every GPU buffer this renderer holds. Safe to call twice.</summary>
        public void ReleaseGpuResources()
        {
            _gpu.Release();
            _cache.Release();
            _keys.Released();   // uploaded again, the estimate's CPU copy dropped, the SubShader's tag read again
            ClearPropertyBlock();
        }

        /// <summary>Whole grid uploads (the Unity-side tests).</summary>
        internal int UploadCount { get; private set; }

        /// <summary>
        /// Uploads only the patches edited (PatchGridAsset.ApplyEdit: a sculpt stroke's dabs) since the version in
        /// the buffers; false when that cannot be told (another grid, a whole-grid change, an undo): then the whole grid.
        /// </summary>
        bool TryUploadEditedPatches(GridVersionKey key)
        {
            GridVersionKey held = _keys.HeldGrid;
            if (held.grid != key.grid || _gpu.ControlPoints == null) return false;
            PatchGrid g = grid.UpdatedPatchGrid(_gpu.Grid, held.version, out int[] changed);
            if (g == null) return false;
            _gpu.UploadPatches(g, changed);
            _keys.PatchesUploaded(key, g, changed);   // the height range widens by the edited patches
            _gridStamp++;   // the vertex cache evaluates its tiles again; the settings block holds only the grid's size
            return true;
        }
    }
}
