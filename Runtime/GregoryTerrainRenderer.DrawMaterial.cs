using UnityEngine;

namespace GregoryTerrain
{
    // Per-renderer shader state: the keywords a renderer chooses (FrameKeywords) go on a runtime copy
    // of the material, buffers and constants on its MaterialPropertyBlock, which carries no keywords; a
    // keyword on the asset would be shared by every renderer and saved with the .mat. The copy
    // (HideAndDontSave) is synced when the asset's content (CRC) changes and destroyed on disable and
    // before a domain reload; a renderer whose keywords equal the asset's draws the asset.
    public sealed partial class GregoryTerrainRenderer
    {
        Material _drawMaterial;        // the runtime copy, or null while the asset itself is drawn

        /// <summary>
        /// The package's own material keywords. Their state on the asset is compared bit by bit as
        /// well as the CRC, so a keyword toggled on the asset reaches the copy whether or not
        /// Unity's CRC covers keywords; reading them allocates nothing (shaderKeywords would).
        /// </summary>
        static readonly string[] AssetKeywords =
        {
            ShaderIds.NoiseKeyword, ShaderIds.HeightColorKeyword, ShaderIds.NoiseTableKeyword,
            ShaderIds.DebugNormalsKeyword, ShaderIds.DebugPatchIdKeyword, ShaderIds.DebugTessFactorKeyword,
        };

        int AssetKeywordBits()
        {
            int bits = 0;
            for (int k = 0; k < AssetKeywords.Length; k++)
                if (material.IsKeywordEnabled(AssetKeywords[k])) bits |= 1 << k;
            return bits;
        }

        /// <summary>
        /// The material this renderer draws with now: the asset, or its runtime copy when the
        /// renderer's keywords differ from the asset's. Null before the first draw.
        /// </summary>
        internal Material DrawMaterial => _drawMaterial != null ? _drawMaterial : material;

        /// <summary>
        /// Picks the asset or the copy for the wanted <c>GT_VERTEX_CACHE</c>, <c>GT_SNOW</c>,
        /// <c>GT_LOD</c> and <c>GT_RANGE_ORIGIN</c> states. The copy is made once and synced
        /// (properties, keywords, shader) only when the asset changed, so a steady frame costs one CRC
        /// of the asset (for its first camera; the others reuse that frame's comparison) and sets nothing.
        /// </summary>
        internal Material UpdateDrawMaterial(FrameKeywords keywords)
        {
            if (material == null) { ReleaseDrawMaterial(); return null; }
            if (HasKeywords(material, keywords))
            {
                ReleaseDrawMaterial();
                return material;
            }
            // Edit mode: every call compares (frameCount does not advance between the editor's repaints).
            int frame = Application.isPlaying ? Time.frameCount : -1;
            if (_drawMaterial != null && _keys.MaterialComparedThisFrame(material.GetInstanceID(), frame) && HasKeywords(_drawMaterial, keywords))
                return _drawMaterial;
            var asset = new MaterialSourceKey(material.GetInstanceID(), material.ComputeCRC(), AssetKeywordBits());
            bool stale = _keys.CopyStale(asset, frame);
            if (_drawMaterial == null)
            {
                _drawMaterial = new Material(material) { name = material.name + " (Gregory Terrain runtime copy)", hideFlags = HideFlags.HideAndDontSave };
            }
            else if (stale)
            {
                _drawMaterial.shader = material.shader;
                _drawMaterial.CopyPropertiesFromMaterial(material);
                _drawMaterial.shaderKeywords = material.shaderKeywords;   // the asset's keywords, whatever the copy above took
            }
            else if (HasKeywords(_drawMaterial, keywords))
                return _drawMaterial;   // steady state: nothing set
            _keys.Copied(asset);
            for (int k = 0; k < RendererKeywords.Length; k++)
                if ((keywords & (FrameKeywords)(1 << k)) != 0) _drawMaterial.EnableKeyword(RendererKeywords[k]);
                else _drawMaterial.DisableKeyword(RendererKeywords[k]);
            return _drawMaterial;
        }

        /// <summary>The keywords a renderer chooses, in <see cref="FrameKeywords"/>' bit order.</summary>
        static readonly string[] RendererKeywords =
            { ShaderIds.VertexCacheKeyword, ShaderIds.SnowKeyword, ShaderIds.LevelsKeyword, ShaderIds.RangeOriginKeyword };

        static bool HasKeywords(Material m, FrameKeywords keywords)
        {
            for (int k = 0; k < RendererKeywords.Length; k++)
                if (m.IsKeywordEnabled(RendererKeywords[k]) != ((keywords & (FrameKeywords)(1 << k)) != 0)) return false;
            return true;
        }

        void ReleaseDrawMaterial()
        {
            if (_drawMaterial == null) return;
            if (Application.isPlaying) Destroy(_drawMaterial); else DestroyImmediate(_drawMaterial);
            _drawMaterial = null;
            _keys.CopyReleased();
        }

        // ---- snow -----------------------------------------------------------------------------------

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
        /// What a Snow Simulator evaluates its field from: the uploaded grid's buffers (as GpuLayout
        /// packs them), the constants last sent (any range: the simulator replaces it), whether the
        /// material has GT_NOISE, and with tiled noise (GT_NOISE_TABLE) the noise table, else null.
        /// False until a grid is uploaded with valid settings.
        /// </summary>
        internal bool TryGetSnowTerrain(out GraphicsBuffer controlPoints, out GraphicsBuffer regions, out GraphicsBuffer gridLines,
            out TerrainParams parameters, out bool noise, out GraphicsBuffer noiseCells, out int gridStamp)
        {
            controlPoints = _controlPoints; regions = _regions; gridLines = _gridLines;
            parameters = _params; gridStamp = _gridStamp;
            noise = material != null && material.IsKeywordEnabled(ShaderIds.NoiseKeyword);
            bool ready = _controlPoints != null && _settingsError == null && _uploadedPatchGrid != null;
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
