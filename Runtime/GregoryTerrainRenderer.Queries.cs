using System;
using UnityEngine;

namespace GregoryTerrain
{
    // Height, normal and ray queries in world space on the surface this renderer draws at full detail
    // (Core's TerrainSurfaceQuery through the Transform). Main thread (they read the Transform); the
    // Core query behind them is thread-safe, and GregoryTerrainCollider uses it off the main thread.
    public sealed partial class GregoryTerrainRenderer
    {
        /// <summary>Vertical precision of <see cref="Raycast"/>: surface parts this far above a ray (metres) are always found.</summary>
        public const float RaycastToleranceMeters = 1e-4f;

        TerrainSurfaceQuery _query;
        PatchGridAsset _queryAsset;
        int _queryVersion;
        NoiseSettings? _queryNoise;
        TerrainKeywords _queryKeywords;

        /// <summary>
        /// The Core query for the current grid and noise (GT_NOISE on the material: the renderer's noise
        /// settings with every octave; tiled with GT_NOISE_TABLE), rebuilt when the grid's version, the noise
        /// settings or either keyword change; null without a valid grid. Main thread; the object it returns may then be used from any thread.
        /// </summary>
        internal TerrainSurfaceQuery SurfaceQuery
        {
            get
            {
                if (grid == null || !grid.IsValid) return null;
                NoiseSettings? noise = material != null && material.IsKeywordEnabled(ShaderIds.NoiseKeyword)
                    ? new NoiseSettings(noiseAmplitude, noiseFrequency, noiseAlpha, noiseBeta, noiseOctaves)
                    : (NoiseSettings?)null;
                TerrainKeywords keywords = NoiseKeywords();
                if (_queryAsset == grid && _queryVersion == grid.Version && Nullable.Equals(_queryNoise, noise) && _queryKeywords == keywords)
                    return _query;
                try { _query = EditedQuery(noise, keywords) ?? new TerrainSurfaceQuery(grid.ToPatchGrid(), noise, keywords); }
                catch (ArgumentException e)
                {
                    Debug.LogError($"{name}: cannot answer height queries: {e.Message}", this);
                    _query = null;
                }
                // Kept on failure too (null query): the collider asks every frame, and a grid or noise
                // that cannot be queried is logged once per version, not rebuilt and logged each time.
                _queryAsset = grid;
                _queryVersion = grid.Version;
                _queryNoise = noise;
                _queryKeywords = keywords;
                return _query;
            }
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
            TerrainSurfaceQuery q = SurfaceQuery;
            if (q == null) return false;
            var frame = new QueryFrame(WorldFrame);
            Double3 o = frame.ToObject(worldPosition);
            double h = q.Sample(o.x, o.z, out Double3 n);   // object (x, height, y)
            if (double.IsNaN(h)) return false;
            surfacePoint = frame.ToWorld(new Double3(o.x, h, o.z));
            surfaceNormal = frame.NormalToWorld(TerrainVertex.TerrainToObject(n));
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
            TerrainSurfaceQuery q = SurfaceQuery;
            var frame = new QueryFrame(WorldFrame);
            for (int i = 0; i < worldPositions.Length; i++)
            {
                if (q == null) { heights[i] = float.NaN; continue; }
                Double3 o = frame.ToObject(worldPositions[i]);
                double h = q.SampleHeight(o.x, o.z);
                heights[i] = double.IsNaN(h) ? float.NaN : frame.ToWorld(new Double3(o.x, h, o.z)).y;
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
            TerrainSurfaceQuery q = SurfaceQuery;
            if (q == null || !(maxDistance >= 0f)) return false;
            var frame = new QueryFrame(WorldFrame);
            Double3 o = frame.ToObject(ray.origin);
            Double3 d = frame.DirectionToObject(ray.direction);
            double worldLength = GMath.length(new Double3(ray.direction.x, ray.direction.y, ray.direction.z));
            double objectLength = GMath.length(d);
            if (!(worldLength > 0.0) || !(objectLength > 0.0)) return false;
            double perWorld = objectLength / worldLength;                          // object units per world unit along the ray
            var terrainRay = new TerrainRay(TerrainVertex.TerrainToObject(o), TerrainVertex.TerrainToObject(d),
                                            float.IsPositiveInfinity(maxDistance) ? double.PositiveInfinity : maxDistance * perWorld);
            double tolerance = RaycastToleranceMeters / Math.Max(frame.VerticalScale, 1e-30);
            if (q.Raycast(terrainRay, out TerrainRayHit hit, tolerance) != TerrainRayStatus.Hit) return false;
            point = frame.ToWorld(TerrainVertex.TerrainToObject(hit.point));
            normal = frame.NormalToWorld(TerrainVertex.TerrainToObject(hit.normal));
            distance = (float)(hit.distance / perWorld);
            return true;
        }

        /// <summary>
        /// The renderer's <see cref="WorldFrame"/> (Transform, terrain size, height scale, floating-origin
        /// offset; double), read once per call: world to object (x, height, y) and back, for points,
        /// directions and normals, the same frame the draw matrices come from.
        /// </summary>
        readonly struct QueryFrame
        {
            readonly TerrainWorldFrame _frame;

            public QueryFrame(TerrainWorldFrame frame) { _frame = frame; }

            /// <summary>World units per object unit along the terrain's up axis.</summary>
            public double VerticalScale => _frame.ObjectScale.y;

            public Double3 ToObject(Vector3 w) => _frame.WorldToObject(new Double3(w.x, w.y, w.z));

            public Double3 DirectionToObject(Vector3 w) => _frame.DirectionToObject(new Double3(w.x, w.y, w.z));

            public Vector3 ToWorld(Double3 o)
            {
                Double3 w = _frame.ObjectToWorld(o);
                return new Vector3((float)w.x, (float)w.y, (float)w.z);
            }

            public Vector3 NormalToWorld(Double3 n)
            {
                Double3 w = _frame.NormalToWorld(n);
                return new Vector3((float)w.x, (float)w.y, (float)w.z);
            }
        }
    }
}
