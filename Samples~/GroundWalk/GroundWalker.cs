using UnityEngine;
// ENABLE_INPUT_SYSTEM follows Active Input Handling, not whether the package is installed; the
// sample's asmdef defines GT_INPUT_SYSTEM_PACKAGE only when com.unity.inputsystem is (versionDefines).
#if ENABLE_INPUT_SYSTEM && GT_INPUT_SYSTEM_PACKAGE
using UnityEngine.InputSystem;
#endif

namespace GregoryTerrain.Samples.GroundWalk
{
    /// <summary>
    /// Sample: a first-person walker on the terrain. A Rigidbody capsule (rotation frozen) stands on the
    /// <see cref="GregoryTerrainCollider"/> patch that follows it; the camera is a child 1.7 m above the
    /// feet. WASD or the arrow keys walk, Space jumps, the mouse looks around while the right button is
    /// held: through the Input System package when the project's Active Input Handling includes it
    /// (ENABLE_INPUT_SYSTEM) and the package is installed, else through the legacy Input Manager's default axes.
    /// <para>While the walker touches the ground its velocity is set along the surface (the renderer's
    /// <see cref="GregoryTerrainRenderer.SampleNormal"/>), so it walks up and down slopes without
    /// hopping and stands still without sliding; slopes steeper than <see cref="maxSlope"/> are left to
    /// gravity. It waits, kinematic, until the collider has built its first patch (a few frames, off the
    /// main thread), and if it ever ends up under the surface (<see cref="GregoryTerrainRenderer.SampleHeight"/>;
    /// for example after a teleport faster than the patch follows) it is put back on top, with one log.</para>
    /// </summary>
    [RequireComponent(typeof(Rigidbody))]
    [AddComponentMenu("Gregory Terrain/Samples/Ground Walker")]
    public sealed class GroundWalker : MonoBehaviour
    {
        [Tooltip("The terrain walked on: its height and slope under the walker come from it.")]
        [SerializeField] GregoryTerrainRenderer terrain = null;

        [Tooltip("The collider patch that follows the walker. The walker waits in the air until its first patch is ready.")]
        [SerializeField] GregoryTerrainCollider groundCollider = null;

        [Tooltip("The first-person camera, a child of the walker at eye height. Mouse look turns it.")]
        [SerializeField] Transform view = null;

        [Tooltip("Walking speed, metres per second.")]
        [SerializeField, Range(0.5f, 30f)] float walkSpeed = 4f;

        [Tooltip("Upward speed of a jump, metres per second (4.5 is about a one-metre jump).")]
        [SerializeField, Range(0f, 20f)] float jumpSpeed = 4.5f;

        [Tooltip("Steepest slope walked on, in degrees. On steeper ground the walker slides.")]
        [SerializeField, Range(5f, 80f)] float maxSlope = 50f;

        [Tooltip("Counts as standing on the ground when the feet are at most this far above it, in metres.")]
        [SerializeField, Range(0.01f, 1f)] float groundTolerance = 0.2f;

        [Tooltip("Put the walker back on top when its feet are this far under the surface, in metres.")]
        [SerializeField, Range(0.05f, 10f)] float fallTolerance = 0.5f;

        [Tooltip("Degrees turned per unit of mouse movement while the right mouse button is held.")]
        [SerializeField, Range(0.1f, 10f)] float mouseSensitivity = 2f;

        Rigidbody _body;
        float _yaw, _pitch;
        float _moveX, _moveZ;
        bool _jumpRequested;
        bool _waiting = true;
        bool _loggedFall;
#if !(ENABLE_INPUT_SYSTEM && GT_INPUT_SYSTEM_PACKAGE) && !ENABLE_LEGACY_INPUT_MANAGER
        bool _loggedInput;
#endif

        void Awake()
        {
            _body = GetComponent<Rigidbody>();
            _body.freezeRotation = true;   // a standing capsule: turning is the camera's
        }

        void OnEnable()
        {
            // Kinematic until the collider's first patch is in place: with gravity on it would fall
            // through the empty space under it during the few frames the first rebuild takes.
            _waiting = true;
            _body.isKinematic = true;
            if (view != null)
            {
                Vector3 forward = view.forward;
                _yaw = Mathf.Atan2(forward.x, forward.z) * Mathf.Rad2Deg;
            }
        }

        void Update()
        {
            ReadInput();
            if (view != null) view.rotation = Quaternion.Euler(_pitch, _yaw, 0f);
        }

#if ENABLE_INPUT_SYSTEM && GT_INPUT_SYSTEM_PACKAGE
        // The legacy "Mouse X"/"Mouse Y" axes are the mouse delta in pixels times 0.1 (their default
        // sensitivity): the same turn per pixel either way.
        const float PixelsToMouseAxis = 0.1f;

        static float Axis(bool negative, bool positive) => (positive ? 1f : 0f) - (negative ? 1f : 0f);

        void ReadInput()
        {
            Keyboard keys = Keyboard.current;
            Mouse mouse = Mouse.current;
            _moveX = keys == null ? 0f : Axis(keys.aKey.isPressed || keys.leftArrowKey.isPressed, keys.dKey.isPressed || keys.rightArrowKey.isPressed);
            _moveZ = keys == null ? 0f : Axis(keys.sKey.isPressed || keys.downArrowKey.isPressed, keys.wKey.isPressed || keys.upArrowKey.isPressed);
            if (keys != null && keys.spaceKey.wasPressedThisFrame) _jumpRequested = true;
            if (mouse != null && mouse.rightButton.isPressed)
            {
                Vector2 delta = mouse.delta.ReadValue() * PixelsToMouseAxis;
                Look(delta.x, delta.y);
            }
        }
#elif ENABLE_LEGACY_INPUT_MANAGER
        void ReadInput()
        {
            _moveX = Input.GetAxis("Horizontal");
            _moveZ = Input.GetAxis("Vertical");
            if (Input.GetButtonDown("Jump")) _jumpRequested = true;
            if (Input.GetMouseButton(1)) Look(Input.GetAxis("Mouse X"), Input.GetAxis("Mouse Y"));
        }
#else
        void ReadInput()
        {
            if (_loggedInput) return;
            _loggedInput = true;
            Debug.LogWarning($"{name}: the project has no input handling on (Project Settings > Player > Active Input Handling); the walker stands still.", this);
        }
#endif

        void Look(float mouseX, float mouseY)
        {
            _yaw += mouseX * mouseSensitivity;
            _pitch = Mathf.Clamp(_pitch - mouseY * mouseSensitivity, -89f, 89f);
        }

        void FixedUpdate()
        {
            if (terrain == null) return;
            Vector3 feet = _body.position;
            if (!terrain.TrySampleSurface(feet, out Vector3 ground, out Vector3 normal)) return;   // not over the terrain

            if (_waiting)
            {
                if (groundCollider != null && groundCollider.RebuildCount == 0) return;
                PutOnTop(ground);
                _body.isKinematic = false;
                _waiting = false;
                return;
            }

            if (feet.y < ground.y - fallTolerance)
            {
                if (!_loggedFall)
                {
                    _loggedFall = true;
                    Debug.Log($"{name}: fell {ground.y - feet.y:F2} m under the terrain surface (no collider under it yet); put back on top. Logged once.", this);
                }
                PutOnTop(ground);
                return;
            }

            // Wanted horizontal velocity: the input turned by the view's heading, at most walkSpeed.
            float sin = Mathf.Sin(_yaw * Mathf.Deg2Rad), cos = Mathf.Cos(_yaw * Mathf.Deg2Rad);
            float vx = _moveX * cos + _moveZ * sin, vz = _moveZ * cos - _moveX * sin;
            float length = System.MathF.Sqrt(vx * vx + vz * vz);
            if (length > 1f) { vx /= length; vz /= length; }
            vx *= walkSpeed;
            vz *= walkSpeed;

            Vector3 v = _body.velocity;
            bool grounded = feet.y - ground.y <= groundTolerance && v.y <= jumpSpeed * 0.5f;
            bool walkable = normal.y >= Mathf.Cos(maxSlope * Mathf.Deg2Rad);
            if (grounded && walkable)
            {
                // Along the surface: the vertical speed that keeps (vx, vy, vz) in the ground's tangent plane.
                float vy = -(normal.x * vx + normal.z * vz) / normal.y;
                if (_jumpRequested) vy = jumpSpeed;
                _body.velocity = new Vector3(vx, vy, vz);
            }
            else if (!grounded)
                _body.velocity = new Vector3(vx, v.y, vz);   // in the air: steer, gravity keeps the vertical speed
            // On ground too steep to walk the body is left to gravity and the collider: it slides.
            _jumpRequested = false;
        }

        void PutOnTop(Vector3 ground)
        {
            _body.position = new Vector3(ground.x, ground.y + 0.05f, ground.z);
            _body.velocity = Vector3.zero;
        }
    }
}
