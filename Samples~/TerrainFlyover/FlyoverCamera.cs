using UnityEngine;

namespace GregoryTerrain.Samples.TerrainFlyover
{
    /// <summary>
    /// Sample: flies the camera in a slow loop over the terrain, a stated clearance above the surface
    /// the renderer draws (<see cref="GregoryTerrainRenderer.SampleHeight"/> under and ahead of it,
    /// <see cref="FlyoverPath"/>), and either draws the whole terrain or zooms the drawn range in and
    /// out with the loop as the paper does, so the constant vertex budget shows at every scale.
    /// </summary>
    [AddComponentMenu("Gregory Terrain/Samples/Flyover Camera")]
    public sealed class FlyoverCamera : MonoBehaviour
    {
        /// <summary>What the terrain draws during the flight.</summary>
        public enum View
        {
            /// <summary>The whole terrain, every frame (Range 0..1).</summary>
            WholeTerrain,
            /// <summary>The paper's zoom: a range around the camera that narrows and widens twice per loop.</summary>
            PaperZoom,
        }

        [Tooltip("The terrain to fly over.")]
        [SerializeField] GregoryTerrainRenderer terrain = null;

        [Tooltip("Whole terrain: draw all of it. Paper zoom: draw a range around the camera that narrows to the Range Metres' second value and widens to its first, twice per loop, at the same vertex count. Switch it in Play Mode.")]
        [SerializeField] View view = View.PaperZoom;

        [Tooltip("Seconds per loop.")]
        [SerializeField, Range(5f, 600f)] float loopSeconds = 60f;

        [Tooltip("Metres the camera keeps above the surface under it, at least. It climbs before higher ground ahead and sinks gently after it.")]
        [SerializeField, Range(1f, 500f)] float clearance = 25f;

        [Tooltip("Seconds of the flight ahead whose ground the camera climbs for in advance.")]
        [SerializeField, Range(0f, 20f)] float lookAheadSeconds = 3f;

        [Tooltip("Seconds the camera takes to follow the ground ahead (about 63% of a change).")]
        [SerializeField, Range(0.05f, 10f)] float smoothSeconds = 1f;

        [Tooltip("Paper zoom only: widest and narrowest side of the drawn range, in metres.")]
        [SerializeField] Vector2 rangeMetres = new Vector2(600f, 20f);

        float _height = float.NaN;   // world y of the camera, eased from frame to frame

        System.Func<double, double, double> _surfaceAt;   // made once: a method group passed as a delegate allocates at every call

        void OnEnable()
        {
            _height = float.NaN;
            _surfaceAt ??= SurfaceAt;
        }

        void LateUpdate()
        {
            if (terrain == null) return;
            double perSecond = 2.0 * System.Math.PI / loopSeconds;
            double phase = Mathf.Repeat(Time.time / loopSeconds, 1f) * 2.0 * System.Math.PI;
            FlyoverPath.Point(phase, out double x, out double y);

            double under = SurfaceAt(x, y);
            double ahead = FlyoverPath.GroundAhead(phase, lookAheadSeconds * perSecond, _surfaceAt);
            double next = FlyoverPath.NextHeight(_height, under, ahead, clearance, Time.deltaTime, smoothSeconds);
            if (!double.IsNaN(next)) _height = (float)next;

            Vector3 position = WorldPoint(x, y);
            position.y = float.IsNaN(_height) ? transform.position.y : _height;
            transform.position = position;
            FlyoverPath.Point(phase + FlyoverPath.LookAngle, out double ax, out double ay);
            Vector3 target = WorldPoint(ax, ay);
            double groundThere = SurfaceAt(ax, ay);
            if (!double.IsNaN(groundThere)) target.y = (float)groundThere;
            transform.LookAt(target);

            if (view == View.WholeTerrain) terrain.Range = TerrainRange.full;
            else
            {
                double metres = FlyoverPath.RangeWidth(phase, rangeMetres.x, rangeMetres.y);
                Vector2 size = TerrainMetres();
                terrain.Range = RangeFit.Around(x, y, metres / size.x, metres / size.y);
            }
        }

        /// <summary>The world point over the terrain's unit-square point (x, y), at the terrain's base.</summary>
        Vector3 WorldPoint(double x, double y)
        {
            Vector2 size = terrain.TerrainSize;
            return terrain.transform.TransformPoint(new Vector3((float)(x * size.x), 0f, (float)(y * size.y)));
        }

        /// <summary>The terrain's width and depth in world metres (Terrain Size times the Transform's scale).</summary>
        Vector2 TerrainMetres()
        {
            Vector3 scale = terrain.transform.lossyScale;
            return new Vector2(terrain.TerrainSize.x * Mathf.Abs(scale.x), terrain.TerrainSize.y * Mathf.Abs(scale.z));
        }

        /// <summary>World height of the surface the renderer draws over the unit-square point (x, y); NaN off the terrain.</summary>
        double SurfaceAt(double x, double y) => terrain.SampleHeight(WorldPoint(x, y));
    }
}
