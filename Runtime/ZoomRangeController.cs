using UnityEngine;

namespace GregoryTerrain
{
    /// <summary>
    /// Zoom into a fixed box: zoom and pan change only the range (one float4 a frame); the camera is
    /// placed over it. <see cref="Zoom"/>, <see cref="Pan"/>, or wheel and arrows (legacy Input Manager).
    /// In Edit Mode it previews (<see cref="GregoryTerrainRenderer.SetDrawnRange"/>, nothing saved) and
    /// moves the camera only with <c>Place Camera In Edit Mode</c> (one Undo step each).
    /// </summary>
    [ExecuteAlways]
    [AddComponentMenu("Gregory Terrain/Zoom Range Controller")]
    public sealed class ZoomRangeController : MonoBehaviour
    {
        [Tooltip("The terrain whose range this controller sets.")]
        [SerializeField] GregoryTerrainRenderer target = null;

        [Tooltip("Camera placed over the range so the range fills its view (optional).")]
        [SerializeField] Camera viewCamera = null;

        [Tooltip("Range centre in the terrain's unit square.")]
        [SerializeField] Vector2 center = new Vector2(0.5f, 0.5f);

        [Tooltip("Zoom steps: each step halves the drawn width. 0 shows the whole terrain; about 20 reaches a millionth of it.")]
        [SerializeField, Range(0f, 23f)] float zoomLevel;

        [Tooltip("Zoom levels per mouse-wheel notch.")]
        [SerializeField, Range(0.01f, 2f)] float wheelZoomStep = 0.25f;

        [Tooltip("Pan speed in range widths per second (arrow keys / WASD).")]
        [SerializeField, Range(0.01f, 4f)] float panSpeed = 0.5f;

        [Tooltip("Camera pitch in degrees (90 = looking straight down).")]
        [SerializeField, Range(10f, 90f)] float cameraPitch = 50f;

        [Tooltip("Also move the View Camera over the range in Edit Mode (undoable). Off: it stays where you place it until Play Mode.")]
        [SerializeField] bool placeCameraInEditMode;

        // Centre kept in double: a float centre cannot address a 1e-6 range precisely.
        double _cx = 0.5, _cy = 0.5;

        /// <summary>Range width 2^-zoomLevel.</summary>
        public double Width => System.Math.Pow(2.0, -zoomLevel);

        void OnEnable() { _cx = center.x; _cy = center.y; }

        void OnDisable() { if (target) target.SyncRangeFromSerialized(); }

        void OnValidate() { _cx = center.x; _cy = center.y; }

        /// <summary>Zooms by <paramref name="levels"/> (positive = in) keeping the point at <paramref name="pivot01"/> of the view fixed.</summary>
        public void Zoom(float levels, Vector2 pivot01)
        {
            RecordEditModeChange("Zoom range");
            double before = Width;
            zoomLevel = Mathf.Clamp(zoomLevel + levels, 0f, 23f);
            double after = Width;
            // The pivot's terrain point stays where it is on screen.
            _cx += (pivot01.x - 0.5) * (before - after);
            _cy += (pivot01.y - 0.5) * (before - after);
            KeepEditModeCenter();
        }

        /// <summary>Moves the range by <paramref name="deltaInWidths"/> range widths.</summary>
        public void Pan(Vector2 deltaInWidths)
        {
            RecordEditModeChange("Pan range");
            double w = Width;
            _cx += deltaInWidths.x * w;
            _cy += deltaInWidths.y * w;
            KeepEditModeCenter();
        }

        // In Edit Mode Zoom and Pan change the saved settings: one Undo step each.
        void RecordEditModeChange(string name)
        {
#if UNITY_EDITOR
            if (!Application.isPlaying) UnityEditor.Undo.RecordObject(this, name);
#endif
        }

        // In Edit Mode the serialized centre is the truth (OnValidate reads it back), so a pan is kept there.
        void KeepEditModeCenter()
        {
            if (!Application.isPlaying) center = new Vector2((float)_cx, (float)_cy);
        }

        void Update()
        {
#if ENABLE_LEGACY_INPUT_MANAGER
            if (Application.isPlaying)
            {
                float wheel = Input.mouseScrollDelta.y;
                if (wheel != 0f) Zoom(wheel * wheelZoomStep, new Vector2(0.5f, 0.5f));
                Vector2 pan = new Vector2(Input.GetAxis("Horizontal"), Input.GetAxis("Vertical"));
                if (pan != Vector2.zero) Pan(pan * (panSpeed * Time.deltaTime));
            }
#endif
            Apply();
        }

        /// <summary>The terrain whose range this controller sets.</summary>
        public GregoryTerrainRenderer Target { get => target; set => target = value; }

        /// <summary>The camera placed over the range (optional).</summary>
        public Camera ViewCamera { get => viewCamera; set => viewCamera = value; }

        /// <summary>Whether the View Camera is also moved in Edit Mode (off by default; in Play Mode it always is).</summary>
        public bool PlaceCameraInEditMode { get => placeCameraInEditMode; set => placeCameraInEditMode = value; }

        /// <summary>Sends the range and places the camera (Edit Mode: drawn range only; camera with <see cref="PlaceCameraInEditMode"/>).</summary>
        public void Apply()
        {
            if (target == null) return;
            bool playing = Application.isPlaying;
            if (!playing) { _cx = center.x; _cy = center.y; }   // after an Undo too
            double w = Width;
            TerrainRange r = RangeFit.Around(_cx, _cy, w, w);
            _cx = 0.5 * (r.c + r.g);          // stay where the clamped range is
            _cy = 0.5 * (r.d + r.h);
            if (playing)
            {
                center = new Vector2((float)_cx, (float)_cy);
                target.Range = r;
            }
            else target.SetDrawnRange(r);
            if (viewCamera != null && (playing || placeCameraInEditMode)) PlaceCamera(r, recordUndo: !playing);
        }

        void PlaceCamera(TerrainRange r, bool recordUndo)
        {
            // Object space is (x, height, y); the range's centre at mid height, through the renderer's
            // world frame (Terrain Size and the floating-origin offset included).
            Vector3 centreWS = target.TerrainObjectToWorld(new Double3(0.5 * (r.c + r.g), 0.0, 0.5 * (r.d + r.h)));
            float worldWidth = (float)(r.Width * target.WorldUnitsPerObjectUnit.x);
            float halfFov = 0.5f * viewCamera.fieldOfView * Mathf.Deg2Rad;
            float distance = 0.5f * worldWidth / Mathf.Tan(halfFov) * 1.1f;
            Quaternion rot = Quaternion.Euler(cameraPitch, 0f, 0f);
            Vector3 position = centreWS - rot * Vector3.forward * distance;
            float near = Mathf.Max(1e-4f, 0.01f * distance), far = Mathf.Max(near * 10f, 10f * distance);
            Transform ct = viewCamera.transform;
            if (position == ct.position && rot == ct.rotation && viewCamera.nearClipPlane == near && viewCamera.farClipPlane == far) return;
#if UNITY_EDITOR
            // Edit Mode: one Undo step, the scene marked changed.
            if (recordUndo)
            {
                UnityEditor.Undo.RecordObject(ct, "Place camera over range");
                UnityEditor.Undo.RecordObject(viewCamera, "Place camera over range");
            }
#endif
            ct.SetPositionAndRotation(position, rot);
            viewCamera.nearClipPlane = near;
            viewCamera.farClipPlane = far;
        }
    }
}
