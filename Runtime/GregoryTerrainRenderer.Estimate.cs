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
        /// Triangles this renderer draws as <paramref name="cam"/> sees the terrain now, at the current
        /// settings and range: each tile's factors from Core's mirror of the hull stage (or, drawing
        /// from the vertex cache, of its kernel's integer factors), counted as the tessellator
        /// triangulates (<see cref="TerrainTriangleEstimate"/>; the rig checks it against the GPU's
        /// count). It shows what the target pixel error costs in a view. At most
        /// <paramref name="maxTiles"/> tiles are evaluated (51 surface points each, on the CPU), an
        /// even sample of them beyond that. Null when there is nothing to estimate: no grid uploaded
        /// yet, invalid settings, the fallback (fixed grids: <see cref="EstimatedTriangleCount"/>),
        /// Horizon levels (each camera's L levels and their seams are not mirrored here: the count
        /// would be one range's), or a camera without pixels. With GT_SNOW the snow's culling allowance is left out.
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
