using UnityEngine;

namespace GregoryTerrain
{
    // The draw material (DrawMaterialCopy), and the Snow Simulator attached.
    public sealed partial class GregoryTerrainRenderer
    {
        readonly DrawMaterialCopy _drawCopy = new DrawMaterialCopy();

        /// <summary>The material drawn now: the asset, or its runtime copy while the keywords differ.</summary>
        internal Material DrawMaterial => _drawCopy.Current != null ? _drawCopy.Current : material;

        internal Material UpdateDrawMaterial(FrameKeywords keywords) => _drawCopy.Update(material, keywords, _keys);

        /// <summary>True while an enabled Snow Simulator is attached and holds a depth map: the draw has GT_SNOW.</summary>
        bool SnowOn() => _snow != null && _snow.DepthBuffer != null;

        /// <summary>HLSL <c>SnowDepthCap()</c>: the deepest snow drawn, in terrain height units (0 without snow).</summary>
        float SnowDepthCap() => SnowOn() ? _snow.MapSize.z : 0f;

        /// <summary>Called by a Snow Simulator whose Terrain is this renderer, when it is enabled.</summary>
        internal void AttachSnow(SnowSimulator simulator)
        {
            if (_snow != null && _snow != simulator)
                Debug.LogWarning($"{name}: Snow Simulator '{simulator.name}' replaces '{_snow.name}'; one simulator per terrain.", this);
            _snow = simulator;
        }

        /// <summary>Called by the attached Snow Simulator when it is disabled or retargeted.</summary>
        internal void DetachSnow(SnowSimulator simulator)
        {
            if (_snow != simulator) return;
            _snow = null;
        }

        /// <summary>
        /// What a Snow Simulator evaluates its field from: the grid's buffers, the constants last
        /// sent (any range: the simulator replaces it), whether the material has GT_NOISE, and with tiled
        /// noise (GT_NOISE_TABLE) the noise table, else null. False until a grid is uploaded with valid settings.
        /// </summary>
        internal bool TryGetSnowTerrain(out TerrainGpuBuffers buffers, out TerrainParams parameters, out bool noise, out GraphicsBuffer noiseCells, out int gridStamp)
        {
            buffers = _gpu;
            parameters = _params; gridStamp = _gridStamp;
            noise = material != null && material.IsKeywordEnabled(ShaderIds.NoiseKeyword);
            bool ready = _gpu.Grid != null && _settingsError == null;
            // The table the draw binds (made here if the simulator asks before the next draw does).
            noiseCells = ready && noise ? EnsureNoiseTable() : null;
            return ready;
        }

        /// <summary>The snow map on the property block: set when the simulator's buffer or size changes, not per frame.</summary>
        void UpdateSnowBinding()
        {
            if (!SnowOn()) return;   // GT_SNOW off: whatever the block holds is not read
            GraphicsBuffer depth = _snow.DepthBuffer;
            Vector4 size = _snow.MapSize;
            if (!_state.BindSnow(depth, new Float3(size.x, size.y, size.z))) return;
            SetBuffer(ShaderIds.SnowDepth, depth);
            SetVector(ShaderIds.SnowMapSize, size);
        }
    }
}
