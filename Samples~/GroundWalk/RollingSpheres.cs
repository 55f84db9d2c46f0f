using UnityEngine;

namespace GregoryTerrain.Samples.GroundWalk
{
    /// <summary>
    /// Sample: rigidbody spheres dropped in front of the walker once the terrain collider's first patch
    /// is ready, to roll down the slopes. The collider is only a patch around the walker, so a sphere
    /// that rolls too far from it, or ends up under the surface (off the patch, where nothing holds it),
    /// is dropped again in front of the walker.
    /// </summary>
    [AddComponentMenu("Gregory Terrain/Samples/Rolling Spheres")]
    public sealed class RollingSpheres : MonoBehaviour
    {
        [Tooltip("The terrain: the drop points are set above its surface.")]
        [SerializeField] GregoryTerrainRenderer terrain = null;

        [Tooltip("The collider patch the spheres roll on. Spheres are dropped once its first patch is ready.")]
        [SerializeField] GregoryTerrainCollider groundCollider = null;

        [Tooltip("The spheres are dropped in front of this (the walker's camera: where it looks).")]
        [SerializeField] Transform around = null;

        [Tooltip("How many spheres.")]
        [SerializeField, Range(1, 32)] int count = 6;

        [Tooltip("Sphere radius, in metres.")]
        [SerializeField, Range(0.05f, 5f)] float radius = 0.5f;

        [Tooltip("Height above the ground the spheres are dropped from, in metres.")]
        [SerializeField, Range(0.5f, 50f)] float dropHeight = 4f;

        [Tooltip("Distance in front of the walker where the spheres are dropped, in metres.")]
        [SerializeField, Range(1f, 50f)] float dropDistance = 8f;

        [Tooltip("A sphere farther than this from the walker, in metres, is dropped again. Keep it inside the collider patch's half width.")]
        [SerializeField, Range(5f, 500f)] float recycleDistance = 30f;

        Rigidbody[] _spheres;
        int _nextSlot;

        // GameObject.CreatePrimitive(Sphere) adds these three, which the scene does not hold; a build
        // strips engine components nothing references, and CreatePrimitive then fails. Naming their
        // types keeps them, as the Scripting Reference's note on CreatePrimitive advises.
        MeshFilter KeptForCreatePrimitiveFilter => null;
        MeshRenderer KeptForCreatePrimitiveRenderer => null;
        SphereCollider KeptForCreatePrimitiveCollider => null;

        void OnDisable()
        {
            if (_spheres == null) return;
            foreach (Rigidbody s in _spheres)
                if (s != null) Destroy(s.gameObject);
            _spheres = null;
        }

        void FixedUpdate()
        {
            if (terrain == null || around == null) return;
            if (_spheres == null)
            {
                if (groundCollider != null && groundCollider.RebuildCount == 0) return;   // nothing to land on yet
                _spheres = new Rigidbody[count];
                for (int k = 0; k < count; k++) _spheres[k] = Create(k);
                for (int k = 0; k < count; k++) Drop(_spheres[k]);
                return;
            }
            Vector3 centre = around.position;
            foreach (Rigidbody s in _spheres)
            {
                if (s == null) continue;
                Vector3 p = s.position;
                float dx = p.x - centre.x, dz = p.z - centre.z;
                float ground = terrain.SampleHeight(p);
                bool far = dx * dx + dz * dz > recycleDistance * recycleDistance;
                bool under = float.IsNaN(ground) || p.y < ground - radius;   // NaN: off the terrain
                if (far || under) Drop(s);
            }
        }

        Rigidbody Create(int index)
        {
            GameObject go = GameObject.CreatePrimitive(PrimitiveType.Sphere);   // a sphere mesh and SphereCollider of radius 0.5
            go.name = $"Rolling Sphere {index}";
            go.transform.localScale = Vector3.one * (2f * radius);
            Rigidbody body = go.AddComponent<Rigidbody>();
            // A solid wooden ball (500 kg per cubic metre): the 70 kg walker nudges a small one, not a large one.
            body.mass = 500f * (4f / 3f) * Mathf.PI * radius * radius * radius;
            body.interpolation = RigidbodyInterpolation.Interpolate;
            return body;
        }

        // Drops a sphere at the next of `count` points on an arc in front of the walker, above the ground.
        void Drop(Rigidbody s)
        {
            Vector3 forward = around.forward;
            float heading = Mathf.Atan2(forward.x, forward.z);
            float spread = ((_nextSlot % count) - 0.5f * (count - 1)) * 0.25f;   // radians between neighbours
            _nextSlot++;
            float a = heading + spread;
            Vector3 at = around.position + new Vector3(Mathf.Sin(a), 0f, Mathf.Cos(a)) * dropDistance;
            float ground = terrain.SampleHeight(at);
            if (float.IsNaN(ground)) ground = around.position.y;   // beyond the terrain's edge: drop it level with the walker
            s.position = new Vector3(at.x, ground + radius + dropHeight, at.z);
            s.velocity = Vector3.zero;
            s.angularVelocity = Vector3.zero;
        }
    }
}
