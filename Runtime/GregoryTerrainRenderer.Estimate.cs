using System;
using UnityEngine;

namespace GregoryTerrain
{
    // The renderer's triangle estimate for a camera (the inspector's "Triangles in view").
    public sealed partial class GregoryTerrainRenderer
    {
        TerrainInputs _estimateInputs;   // the uploaded grid packed for Core, made on the first estimate after an upload
        PatchGrid _estimateGrid;
        readonly TerrainRange[] _estimateLevels = new TerrainRange[LodTiles.MaxLevels];

        /// <summary>
        /// Triangles drawn for <paramref name="cam"/> now (<see cref="TerrainTriangleEstimate"/>), with Horizon
        /// levels every level around it. At most <paramref name="maxTiles"/> tiles evaluated, an even sample
        /// beyond. Null without an uploaded grid, with invalid settings, the fallback or a camera without pixels.
        /// </summary>
        public TriangleEstimate? EstimateTrianglesInView(Camera cam, int maxTiles = 256)
        {
            if (cam == null) throw new ArgumentNullException(nameof(cam));
            if (_uploadedPatchGrid == null || _settingsError != null || _keys.LastDrawFallback) return null;
            int w = cam.pixelWidth, h = cam.pixelHeight;
            if (w <= 0 || h <= 0) return null;
            if (_estimateGrid != _uploadedPatchGrid)
            {
                _estimateInputs = TerrainInputs.Create(_uploadedPatchGrid, _params);
                _estimateGrid = _uploadedPatchGrid;
            }
            else _estimateInputs = _estimateInputs.WithParams(_params);
            Float4x4 m = ToFloat4x4(ObjectToClip(cam));
            var screen = new Float2(w, h);
            if (LevelsOn(false))
            {
                // The camera's levels, against the origin the draw matrix (ObjectToClip) cancels.
                Double3 local = WorldToTerrainObject(cam.transform.position);
                // The uploaded tile count, not the field: an inspector edit is not drawn (or checked) yet.
                int uploadedTiles = _estimateInputs.TileCountInt();
                if (uploadedTiles % 2 != 0 || uploadedTiles < LodLevels.MinTiles) return null;
                int count = LodLevels.Layout(new Double2(local.x, local.z), FinestExponent(), uploadedTiles, _estimateLevels);
                ReadOnlySpan<TerrainRange> levels = new ReadOnlySpan<TerrainRange>(_estimateLevels, 0, count);
                return TerrainTriangleEstimate.InLevels(_estimateInputs, levels, _state.origin, m, screen, NoiseKeywords(), maxTiles);
            }
            var partitioning = _usesCache ? TessellationPartitioning.Integer : TessellationPartitioning.FractionalOdd;
            return TerrainTriangleEstimate.InView(_estimateInputs, m, screen, NoiseKeywords(), partitioning, maxTiles);
        }

        /// <summary>Whether a grid is uploaded with valid settings: <see cref="WorldBounds"/> holds the drawn terrain.</summary>
        internal bool HasDrawn => _uploadedPatchGrid != null && _settingsError == null;

        static Float4x4 ToFloat4x4(Matrix4x4 m) => Float4x4.FromRows(
            m.m00, m.m01, m.m02, m.m03, m.m10, m.m11, m.m12, m.m13,
            m.m20, m.m21, m.m22, m.m23, m.m30, m.m31, m.m32, m.m33);
    }
}
