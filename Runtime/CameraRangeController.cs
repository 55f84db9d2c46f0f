using UnityEngine;

namespace GregoryTerrain
{
    /// <summary>
    /// The range follows a camera: a square of <see cref="viewDistance"/> around the point below it,
    /// pushed ahead along its view; one float4 a frame, the camera never moved. In Edit Mode the
    /// saved range is not written (<see cref="GregoryTerrainRenderer.SetDrawnRange"/>).
    /// </summary>
    [ExecuteAlways]
    [AddComponentMenu("Gregory Terrain/Camera Range Controller")]
    public sealed class CameraRangeController : MonoBehaviour
    {
        [Tooltip("The terrain whose range follows the camera.")]
        [SerializeField] GregoryTerrainRenderer target = null;

        [Tooltip("The camera to follow; the main camera when empty.")]
        [SerializeField] Camera followCamera = null;

        [Tooltip("Side of the drawn square, shown in metres of the terrain's width (x); stored as a part of it (1 = all of it).")]
        [SerializeField, Range(0.0001f, 1f)] float viewDistance = 0.5f;

        [Tooltip("How far ahead of the camera (fraction of the side) the square's centre is pushed, so more of it lies in view.")]
        [SerializeField, Range(0f, 0.5f)] float lookAhead = 0.3f;

        internal GregoryTerrainRenderer Target => target;

        void OnDisable() { if (target) target.SyncRangeFromSerialized(); }

        void LateUpdate()
        {
            if (target == null) return;
            Camera cam = followCamera != null ? followCamera : Camera.main;
            if (cam == null) return;
            // Terrain object space is (x, height, y): q = (object x, object z), through the renderer's
            // world frame (Terrain Size and the floating-origin offset included).
            Double3 camOS = target.WorldToTerrainObject(cam.transform.position);
            Double3 fwdOS = target.WorldToTerrainObject(cam.transform.position + cam.transform.forward) - camOS;
            Vector2 ahead = new Vector2((float)fwdOS.x, (float)fwdOS.z);
            if (ahead.sqrMagnitude > 1e-12f) ahead.Normalize();
            double cx = camOS.x + ahead.x * lookAhead * viewDistance;
            double cy = camOS.z + ahead.y * lookAhead * viewDistance;
            TerrainRange r = RangeFit.Around(cx, cy, viewDistance, viewDistance);
            if (Application.isPlaying) target.Range = r;
            else target.SetDrawnRange(r);
        }
    }
}
