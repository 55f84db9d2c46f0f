using UnityEngine;

namespace GregoryTerrain.Samples.TerrainFlyover
{
    /// <summary>
    /// Sample: flies the camera in a slow loop over the terrain and zooms the drawn range in and out
    /// with it, so the constant vertex budget of the tile layout can be seen at every scale.
    /// </summary>
    [AddComponentMenu("Gregory Terrain/Samples/Flyover Camera")]
    public sealed class FlyoverCamera : MonoBehaviour
    {
        [Tooltip("The terrain to fly over.")]
        [SerializeField] GregoryTerrainRenderer terrain = null;

        [Tooltip("Seconds per loop.")]
        [SerializeField, Range(5f, 600f)] float loopSeconds = 60f;

        [Tooltip("Flight height above the terrain's base, in terrain units.")]
        [SerializeField, Range(0.001f, 1f)] float height = 0.08f;

        [Tooltip("Widest and narrowest range side during the loop, terrain units.")]
        [SerializeField] Vector2 rangeWidth = new Vector2(0.6f, 0.02f);

        void LateUpdate()
        {
            if (terrain == null) return;
            float phase = Mathf.Repeat(Time.time / loopSeconds, 1f) * 2f * Mathf.PI;
            // A loop of radius 0.3 around the terrain centre, in terrain (x, y).
            float x = 0.5f + 0.3f * Mathf.Cos(phase), y = 0.5f + 0.3f * Mathf.Sin(phase);
            float zoom = 0.5f + 0.5f * Mathf.Cos(2f * phase);            // zooms in and out twice per loop
            float width = Mathf.Lerp(rangeWidth.y, rangeWidth.x, zoom);

            Transform t = terrain.transform;
            transform.position = t.TransformPoint(new Vector3(x, height * Mathf.Lerp(0.3f, 1f, zoom), y));
            Vector3 ahead = new Vector3(0.5f + 0.3f * Mathf.Cos(phase + 0.3f), 0f, 0.5f + 0.3f * Mathf.Sin(phase + 0.3f));
            transform.LookAt(t.TransformPoint(ahead));

            terrain.Range = RangeFit.Around(x, y, width, width);
        }
    }
}
