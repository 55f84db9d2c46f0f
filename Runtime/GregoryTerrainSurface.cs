using System;
using UnityEngine;

namespace GregoryTerrain
{
    /// <summary>
    /// CPU queries in world space on the surface a renderer draws at full detail (Core's TerrainSurfaceQuery
    /// through its Transform, size, height scale and origin offset), and the triangles a camera draws now.
    /// From <see cref="GregoryTerrainRenderer.Surface"/>; main thread; valid while that renderer exists (a plain
    /// object: it does not read as null after Destroy).
    /// </summary>
    public sealed class GregoryTerrainSurface
    {
        /// <summary>Vertical precision of <see cref="Raycast"/>: surface parts this far above a ray (metres) are always found.</summary>
        public const float RaycastToleranceMeters = 1e-4f;

        readonly GregoryTerrainRenderer _renderer;
        readonly TerrainRange[] _levels = new TerrainRange[LodTiles.MaxLevels];   // scratch

        internal GregoryTerrainSurface(GregoryTerrainRenderer renderer) => _renderer = renderer;

        /// <summary>
        /// The Core query for the grid and noise (GT_NOISE: every octave; GT_NOISE_TABLE: tiled), rebuilt when
        /// the grid's version, noise or keywords change; null without a valid grid. Main thread; the query it returns may then be used from any thread.
        /// </summary>
        internal TerrainSurfaceQuery Query
        {
            get
            {
                PatchGridAsset grid = _renderer.Grid;
                if (grid == null || !grid.IsValid) return null;
                var key = new QuerySourceKey(new GridVersionKey(grid.GetInstanceID(), grid.Version), _renderer.QueryNoise, _renderer.NoiseKeywords());
                FrameResources built = _renderer.State.resources;
                if (built.TryQuery(key, out TerrainSurfaceQuery query)) return query;
                try { query = EditedQuery(grid, key) ?? new TerrainSurfaceQuery(grid.ToPatchGrid(), _renderer.QueryNoise, _renderer.NoiseKeywords()); }
                catch (ArgumentException e)
                {
                    Debug.LogError($"{_renderer.name}: cannot answer height queries: {e.Message}", _renderer);
                    query = null;
                }
                built.QueryBuilt(key, query);   // a failure too: logged once per version
                return query;
            }
        }

        /// <summary>The query brought to the grid's version at the cost of the patches edited since; null when only a rebuild can tell.</summary>
        TerrainSurfaceQuery EditedQuery(PatchGridAsset grid, in QuerySourceKey key)
        {
            TerrainSurfaceQuery old = _renderer.State.resources.QueryToCatchUp(key, out int version);
            if (old == null) return null;
            PatchGrid g = grid.UpdatedPatchGrid(old.Grid, version, out int[] changed);
            return g == null ? null : old.WithPatches(g, changed);
        }

        /// <summary>
        /// World-space height (y) of the terrain surface on the terrain's vertical line through
        /// <paramref name="worldPosition"/> (its up axis, object y); NaN where the point is not over the
        /// terrain or there is no valid grid. Unlike Unity's Terrain.SampleHeight this is the world y
        /// of the surface point itself, not a height relative to the Transform.
        /// </summary>
        public float SampleHeight(Vector3 worldPosition) =>
            TrySampleSurface(worldPosition, out Vector3 point, out _) ? point.y : float.NaN;

        /// <summary>World-space unit normal of the surface over <paramref name="worldPosition"/>; zero where there is none.</summary>
        public Vector3 SampleNormal(Vector3 worldPosition) =>
            TrySampleSurface(worldPosition, out _, out Vector3 normal) ? normal : Vector3.zero;

        /// <summary>
        /// The surface point on the terrain's vertical line through <paramref name="worldPosition"/> and
        /// its unit normal, in world space; false where the point is not over the terrain.
        /// </summary>
        public bool TrySampleSurface(Vector3 worldPosition, out Vector3 surfacePoint, out Vector3 surfaceNormal)
        {
            surfacePoint = surfaceNormal = Vector3.zero;
            TerrainSurfaceQuery q = Query;
            if (q == null) return false;
            TerrainWorldFrame frame = _renderer.WorldFrame;
            Double3 o = frame.WorldToObject(D(worldPosition));
            double h = q.Sample(o.x, o.z, out Double3 n);   // object (x, height, y)
            if (double.IsNaN(h)) return false;
            surfacePoint = V(frame.ObjectToWorld(new Double3(o.x, h, o.z)));
            surfaceNormal = V(frame.NormalToWorld(TerrainVertex.TerrainToObject(n)));
            return true;
        }

        /// <summary>
        /// <see cref="SampleHeight"/> for many points: <paramref name="heights"/>[i] for
        /// <paramref name="worldPositions"/>[i] (NaN where not over the terrain). No allocation.
        /// </summary>
        public void SampleHeights(ReadOnlySpan<Vector3> worldPositions, Span<float> heights)
        {
            if (heights.Length < worldPositions.Length)
                throw new ArgumentException($"heights.Length ({heights.Length}) must be at least worldPositions.Length ({worldPositions.Length})", nameof(heights));
            TerrainSurfaceQuery q = Query;
            TerrainWorldFrame frame = _renderer.WorldFrame;
            for (int i = 0; i < worldPositions.Length; i++)
            {
                if (q == null) { heights[i] = float.NaN; continue; }
                Double3 o = frame.WorldToObject(D(worldPositions[i]));
                double h = q.SampleHeight(o.x, o.z);
                heights[i] = double.IsNaN(h) ? float.NaN : V(frame.ObjectToWorld(new Double3(o.x, h, o.z))).y;
            }
        }

        /// <summary>
        /// The first point where <paramref name="ray"/> meets the terrain's surface from above, within
        /// <paramref name="maxDistance"/> (world units), with its unit normal and distance. Every part of
        /// the surface more than <see cref="RaycastToleranceMeters"/> above the ray is found, at any
        /// grazing angle (internals.md, "CPU queries"); the surface is one-sided, like a TerrainCollider.
        /// </summary>
        public bool Raycast(Ray ray, float maxDistance, out Vector3 point, out Vector3 normal, out float distance)
        {
            point = normal = Vector3.zero;
            distance = 0f;
            TerrainSurfaceQuery q = Query;
            if (q == null || !(maxDistance >= 0f)) return false;
            TerrainWorldFrame frame = _renderer.WorldFrame;
            Double3 o = frame.WorldToObject(D(ray.origin));
            Double3 d = frame.DirectionToObject(D(ray.direction));
            double worldLength = GMath.length(D(ray.direction));
            double objectLength = GMath.length(d);
            if (!(worldLength > 0.0) || !(objectLength > 0.0)) return false;
            double perWorld = objectLength / worldLength;                          // object units per world unit along the ray
            var terrainRay = new TerrainRay(TerrainVertex.TerrainToObject(o), TerrainVertex.TerrainToObject(d),
                                            float.IsPositiveInfinity(maxDistance) ? double.PositiveInfinity : maxDistance * perWorld);
            double tolerance = RaycastToleranceMeters / Math.Max(frame.ObjectScale.y, 1e-30);
            if (q.Raycast(terrainRay, out TerrainRayHit hit, tolerance) != TerrainRayStatus.Hit) return false;
            point = V(frame.ObjectToWorld(TerrainVertex.TerrainToObject(hit.point)));
            normal = V(frame.NormalToWorld(TerrainVertex.TerrainToObject(hit.normal)));
            distance = (float)(hit.distance / perWorld);
            return true;
        }

        /// <summary>
        /// Triangles drawn for <paramref name="cam"/> now (with Horizon levels, every level), from at most
        /// <paramref name="maxTiles"/> tiles (an even sample beyond). Null without a drawn grid, with the fallback or no pixels.
        /// </summary>
        public TriangleEstimate? EstimateTrianglesInView(Camera cam, int maxTiles = 256)
        {
            if (cam == null) throw new ArgumentNullException(nameof(cam));
            GregoryTerrainRenderer r = _renderer;
            if (!r.HasDrawn || r.State.resources.LastDrawFallback) return null;
            int w = cam.pixelWidth, h = cam.pixelHeight;
            if (w <= 0 || h <= 0) return null;
            TerrainInputs inputs = r.State.resources.EstimateInputs(r.UploadedPatchGrid, r.State.parameters);
            Float4x4 m = UnityConversions.ToFloat4x4(r.ObjectToClip(cam));
            var screen = new Float2(w, h);
            if (r.HorizonLevels)
            {
                // The camera's levels, against the origin the draw matrix (ObjectToClip) cancels.
                Double3 local = r.WorldToTerrainObject(cam.transform.position);
                // The uploaded tile count, not the field: an inspector edit is not drawn (or checked) yet.
                int uploadedTiles = inputs.TileCountInt();
                if (uploadedTiles % 2 != 0 || uploadedTiles < LodLevels.MinTiles) return null;
                int count = LodLevels.Layout(new Double2(local.x, local.z), r.FinestExponent(), uploadedTiles, _levels);
                return TerrainTriangleEstimate.InLevels(inputs, new ReadOnlySpan<TerrainRange>(_levels, 0, count), r.State.origin, m, screen, r.NoiseKeywords(), maxTiles);
            }
            var partitioning = r.UsesVertexCache ? TessellationPartitioning.Integer : TessellationPartitioning.FractionalOdd;
            return TerrainTriangleEstimate.InView(inputs, m, screen, r.NoiseKeywords(), partitioning, maxTiles);
        }

        // WorldFrame is read once per call: the frame the draw matrices come from.
        static Double3 D(Vector3 v) => new Double3(v.x, v.y, v.z);
        static Vector3 V(Double3 d) => new Vector3((float)d.x, (float)d.y, (float)d.z);
    }
}
