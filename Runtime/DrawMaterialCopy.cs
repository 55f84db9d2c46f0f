using UnityEngine;

namespace GregoryTerrain
{
    // A renderer's runtime copy of its material (HideAndDontSave) for the keywords it chooses: one on the
    // asset would be shared by every renderer and saved with the .mat. FrameResources says when to sync.
    internal sealed class DrawMaterialCopy
    {
        Material _drawMaterial;

        /// <summary>The copy, or null while the asset itself is drawn.</summary>
        internal Material Current => _drawMaterial;

        /// <summary>
        /// The keywords the material switches (Core's ShaderKeywords). Their state on the asset is
        /// compared bit by bit as well as the CRC, so a keyword toggled on the asset reaches the copy
        /// whether or not Unity's CRC covers keywords; reading them allocates nothing (shaderKeywords would).
        /// </summary>
        static readonly (string name, FrameKeywords flag)[] AssetKeywords = ShaderKeywords.SwitchedBy(KeywordSwitch.Material);

        static int AssetKeywordBits(Material material)
        {
            int bits = 0;
            for (int k = 0; k < AssetKeywords.Length; k++)
                if (material.IsKeywordEnabled(AssetKeywords[k].name)) bits |= 1 << k;
            return bits;
        }

        /// <summary>
        /// Picks <paramref name="material"/> or the copy for the wanted <c>GT_VERTEX_CACHE</c>, <c>GT_SNOW</c>,
        /// <c>GT_LOD</c> and <c>GT_RANGE_ORIGIN</c> states. The copy is made once and synced
        /// (properties, keywords, shader) only when the asset changed, so a steady frame costs one CRC
        /// of the asset (for its first camera; the others reuse that frame's comparison) and sets nothing.
        /// </summary>
        internal Material Update(Material material, FrameKeywords keywords, FrameResources keys)
        {
            if (material == null) { Release(keys); return null; }
            if (HasKeywords(material, keywords))
            {
                Release(keys);
                return material;
            }
            // Edit mode: every call compares (frameCount does not advance between the editor's repaints).
            int frame = Application.isPlaying ? Time.frameCount : -1;
            if (_drawMaterial != null && keys.MaterialComparedThisFrame(material.GetInstanceID(), frame) && HasKeywords(_drawMaterial, keywords))
                return _drawMaterial;
            var asset = new MaterialSourceKey(material.GetInstanceID(), material.ComputeCRC(), AssetKeywordBits(material));
            bool stale = keys.CopyStale(asset, frame);
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
            keys.Copied(asset);
            foreach (var (name, flag) in RendererKeywords)
                if ((keywords & flag) != 0) _drawMaterial.EnableKeyword(name);
                else _drawMaterial.DisableKeyword(name);
            return _drawMaterial;
        }

        /// <summary>The keywords a renderer chooses, each with its <see cref="FrameKeywords"/> flag.</summary>
        static readonly (string name, FrameKeywords flag)[] RendererKeywords = ShaderKeywords.SwitchedBy(KeywordSwitch.Renderer);

        static bool HasKeywords(Material m, FrameKeywords keywords)
        {
            foreach (var (name, flag) in RendererKeywords)
                if (m.IsKeywordEnabled(name) != ((keywords & flag) != 0)) return false;
            return true;
        }

        /// <summary>On the main thread (OnDisable, before a domain reload). Safe to call twice.</summary>
        internal void Release(FrameResources keys)
        {
            if (_drawMaterial == null) return;
            if (Application.isPlaying) Object.Destroy(_drawMaterial); else Object.DestroyImmediate(_drawMaterial);
            _drawMaterial = null;
            keys.CopyReleased();
        }
    }
}
