using System;
using UnityEngine;

namespace GregoryTerrain
{
    // The renderer's triangle estimate for a camera (the inspector's "Triangles in view").
    public sealed partial class GregoryTerrainRenderer
    {
        TerrainInputs _estimateInputs;   // the uploaded grid packed for Core, made on the first estimate after an upload
        PatchGrid _estimateGrid;

        /// <summary>
        /// Triangles drawn for <paramref name="cam"/> now: each tile's factors from Core's mirror of the
        /// hull stage (or the cache kernel's), counted as the tessellator does (<see cref="TerrainTriangleEstimate"/>;
        /// the rig checks it against the GPU). At most <paramref name="maxTiles"/> tiles evaluated, an even
        /// sample beyond. Null without an uploaded grid, with invalid settings, the fallback, Horizon levels
        /// (their seams are not mirrored) or a camera without pixels. GT_SNOW's culling allowance is left out.
        /// </summary>
        public TriangleEstimate? EstimateTrianglesInView(Camera cam, int maxTiles = 256)
        {
            if (cam == null) throw new ArgumentNullException(nameof(cam));
            if (_uploadedPatchGrid == null || _settingsError != null || _drawFallback || LevelsOn(_drawFallback)) return null;
            int w = cam.pixelWidth, h = cam.pixelHeight;
            if (w <= 0 || h <= 0) return null;
            if (_estimateGrid != _uploadedPatchGrid)
            {
                _estimateInputs = TerrainInputs.Create(_uploadedPatchGrid, _params);
                _estimateGrid = _uploadedPatchGrid;
            }
            else _estimateInputs = _estimateInputs.WithParams(_params);
            Matrix4x4 m = ObjectToClip(cam);
            TerrainKeywords keywords = NoiseKeywords();
            var partitioning = _usesCache ? TessellationPartitioning.Integer : TessellationPartitioning.FractionalOdd;
            return TerrainTriangleEstimate.InView(_estimateInputs, ToFloat4x4(m), new Float2(w, h), keywords, partitioning, maxTiles);
        }

        static Float4x4 ToFloat4x4(Matrix4x4 m) => Float4x4.FromRows(
            m.m00, m.m01, m.m02, m.m03, m.m10, m.m11, m.m12, m.m13,
            m.m20, m.m21, m.m22, m.m23, m.m30, m.m31, m.m32, m.m33);
    }
}
