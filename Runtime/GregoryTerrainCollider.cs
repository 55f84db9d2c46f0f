using System;
using System.Threading.Tasks;
using Unity.Profiling;
using UnityEngine;

namespace GregoryTerrain
{
    /// <summary>
    /// Keeps a physics surface of the terrain around a target (a player, a vehicle): a MeshCollider patch
    /// of N x N samples of the full-detail surface, re-centred when the target leaves the patch's middle,
    /// sampled and cooked off the main thread; the collider in use is never touched meanwhile
    /// (internals.md, "Terrain collider"). Put it on an empty GameObject of its own (scale 1): it moves
    /// its Transform. The samples lie on a lattice fixed in the terrain (<see cref="ColliderPatch"/>).
    /// </summary>
    [DisallowMultipleComponent]
    [RequireComponent(typeof(MeshCollider))]
    [AddComponentMenu("Gregory Terrain/Gregory Terrain Collider")]
    public sealed class GregoryTerrainCollider : MonoBehaviour
    {
        [Tooltip("The terrain whose surface (with its noise, all octaves) the collider follows.")]
        [SerializeField] GregoryTerrainRenderer terrain;

        [Tooltip("What stands on the terrain: the patch is kept around it.")]
        [SerializeField] Transform target;

        [Tooltip("Height samples per side of the collider's patch. 65 samples 1 m apart cover 64 m.")]
        [SerializeField, Range(2, 255)] int samples = 65;

        [Tooltip("Distance between samples along the terrain, in metres. Smaller follows fine noise more closely (the manual lists how closely).")]
        [SerializeField, Min(0.01f)] float spacing = 1f;

        [Tooltip("Re-centre the patch when the target is farther than this fraction of the half patch from its centre (0.5: a quarter of the patch).")]
        [SerializeField, Range(0.05f, 1f)] float recentreThreshold = 0.5f;

        enum Stage { Idle, Sampling, Baking }

        // The main thread's whole share of a rebuild, one frame's slice at a time, as the Profiler shows it.
        static readonly ProfilerMarker s_UpdateMarker = new ProfilerMarker("GregoryTerrainCollider.Update");

        MeshCollider _collider;
        readonly Mesh[] _meshes = new Mesh[2];
        readonly int[] _meshSamples = new int[2];   // N each mesh was built for
        int _spare;                      // the mesh being built (the other is in use)
        Stage _stage;
        Task _task;
        Task _bakeInFlight;              // a cook of the spare mesh that OnDisable did not wait for
        ColliderPatch _current, _pending;
        bool _hasCurrent;
        TerrainSurfaceQuery _builtFrom;  // the query the current patch was sampled from
        float[] _heights;
        Vector3[] _vertices;
        int[] _triangles;
        int _builtSamples;
        int _pendingSamples;             // N of the rebuild under way (samples may change meanwhile)
        Vector3 _pendingPosition;
        Quaternion _pendingRotation;

        /// <summary>The terrain followed.</summary>
        public GregoryTerrainRenderer Terrain { get => terrain; set => terrain = value; }
        /// <summary>The transform the patch is kept around.</summary>
        public Transform Target { get => target; set => target = value; }
        /// <summary>Samples per side (2 .. 255).</summary>
        public int Samples
        {
            get => samples;
            set
            {
                if (value < 2 || value > 255) throw new ArgumentException($"Samples ({value}) must lie in [2, 255]", nameof(value));
                samples = value;
            }
        }
        /// <summary>Distance between samples, world units.</summary>
        public float Spacing
        {
            get => spacing;
            set
            {
                if (!(value >= 0.01f) || float.IsInfinity(value)) throw new ArgumentException($"Spacing ({value}) must be finite and at least 0.01", nameof(value));
                spacing = value;
            }
        }
        /// <summary>Rebuilds finished since enabled (for tests and statistics).</summary>
        public int RebuildCount { get; private set; }
        /// <summary>True while a rebuild is under way (sampling or cooking off the main thread).</summary>
        public bool Rebuilding => _stage != Stage.Idle;

        void OnEnable()
        {
            _collider = GetComponent<MeshCollider>();
            _stage = Stage.Idle;
            _hasCurrent = false;
            RebuildCount = 0;
        }

        void OnDisable()
        {
            // Never wait here. A sampling task finishes into arrays no one reads; a cook still reads the
            // spare mesh natively, so it is waited for before that mesh is written or destroyed.
            if (_stage == Stage.Sampling) _heights = null;   // the next rebuild samples into new arrays
            if (_stage == Stage.Baking) _bakeInFlight = _task;
            _task = null;
            _stage = Stage.Idle;
        }

        // A cook abandoned by OnDisable: usually long finished when the spare mesh is next touched.
        void FinishAbandonedBake()
        {
            try { _bakeInFlight?.Wait(); } catch (AggregateException) { }
            _bakeInFlight = null;
        }

        void OnDestroy()
        {
            FinishAbandonedBake();
            for (int k = 0; k < _meshes.Length; k++)
                if (_meshes[k] != null) { Destroy(_meshes[k]); _meshes[k] = null; }
        }

        void Update()
        {
            if (terrain == null || target == null || _collider == null) return;
            using var slice = s_UpdateMarker.Auto();
            switch (_stage)
            {
                case Stage.Idle: StartIfNeeded(); break;
                case Stage.Sampling: if (_task.IsCompleted) ApplySamples(); break;
                case Stage.Baking: if (_task.IsCompleted) Swap(); break;
            }
        }

        /// <summary>Terrain-space point (the unit square) under a world position, through the renderer's world frame.</summary>
        static Double2 TerrainPoint(in TerrainWorldFrame frame, Vector3 world)
        {
            Double3 o = frame.WorldToObject(new Double3(world.x, world.y, world.z));
            return new Double2(o.x, o.z);
        }

        void StartIfNeeded()
        {
            TerrainSurfaceQuery query = terrain.SurfaceQuery;
            if (query == null) return;
            // The renderer's frame (terrain size, height scale, floating-origin offset): the same as the draw's.
            TerrainWorldFrame frame = terrain.WorldFrame;
            Double3 scale = frame.ObjectScale;
            double spacingTerrain = spacing / Math.Max(scale.x, 1e-30);
            Double2 at = TerrainPoint(frame, target.position);
            bool stale = !_hasCurrent || query != _builtFrom || _builtSamples != samples || _current.spacing != spacingTerrain;
            if (!stale && !_current.NeedsRebuild(at, recentreThreshold)) return;
            ColliderPatch patch;
            try { patch = ColliderPatch.Around(at, spacingTerrain, samples); }
            catch (ArgumentException e) { Debug.LogError($"{name}: {e.Message}", this); enabled = false; return; }

            int n = samples;
            if (_heights == null || _heights.Length != n * n)
            {
                _heights = new float[n * n];
                _vertices = new Vector3[n * n];
                _triangles = ColliderPatch.Triangles(n);
            }
            // The patch's pose: centre on the surface, the terrain's rotation, unit scale; vertices relative
            // to it in world units, so float keeps millimetres at any distance.
            Double2 c = patch.Center;
            double centreHeight = query.SampleHeight(GMath.clamp(c.x, 0.0, 1.0), GMath.clamp(c.y, 0.0, 1.0));
            if (double.IsNaN(centreHeight)) centreHeight = 0.0;
            // In double: rounding the object point to float first would misplace the patch on a large terrain.
            Double3 centre = frame.ObjectToWorld(new Double3(c.x, centreHeight, c.y));
            _pendingPosition = new Vector3((float)centre.x, (float)centre.y, (float)centre.z);
            _pendingRotation = terrain.transform.rotation;
            double sx = scale.x, sy = scale.y, sz = scale.z;
            float[] heights = _heights;
            Vector3[] vertices = _vertices;
            _pending = patch;
            _pendingSamples = n;
            _builtFrom = query;
            _task = Task.Run(() =>
            {
                patch.SampleHeights(query, heights);
                for (int j = 0; j < n; j++)
                    for (int i = 0; i < n; i++)
                    {
                        Double2 p = patch.Point(i, j);
                        int v = j * n + i;
                        vertices[v] = new Vector3((float)(sx * (p.x - c.x)), (float)(sy * (heights[v] - centreHeight)), (float)(sz * (p.y - c.y)));
                    }
            });
            _stage = Stage.Sampling;
        }

        /// <summary>Main thread: the samples into the spare mesh (its vertex count is fixed per N), then the cook off the main thread.</summary>
        void ApplySamples()
        {
            if (_task.IsFaulted)
            {
                Debug.LogError($"{name}: sampling the terrain failed: {_task.Exception?.GetBaseException().Message}", this);
                _stage = Stage.Idle;
                enabled = false;
                return;
            }
            FinishAbandonedBake();
            Mesh mesh = _meshes[_spare];
            int n = _pendingSamples;   // what _vertices and _triangles were sized for, not a newer setting
            if (mesh != null && _meshSamples[_spare] != n) { Destroy(mesh); mesh = null; }   // another vertex count
            bool fresh = mesh == null;
            if (fresh)
            {
                mesh = _meshes[_spare] = new Mesh { name = "Gregory Terrain Collider", hideFlags = HideFlags.HideAndDontSave };
                mesh.MarkDynamic();
                _meshSamples[_spare] = n;
            }
            mesh.SetVertices(_vertices);
            if (fresh) mesh.SetTriangles(_triangles, 0);   // the same for every patch of N x N
            mesh.RecalculateBounds();
            int id = mesh.GetInstanceID();
            MeshColliderCookingOptions options = _collider.cookingOptions;
            _task = Task.Run(() => Physics.BakeMesh(id, false, options));
            _stage = Stage.Baking;
        }

        /// <summary>Main thread: the cooked mesh becomes the collider's, at the patch's pose.</summary>
        void Swap()
        {
            if (_task.IsFaulted)
                Debug.LogWarning($"{name}: cooking the collider off the main thread failed ({_task.Exception?.GetBaseException().Message}); Unity cooks it on assignment.", this);
            transform.SetPositionAndRotation(_pendingPosition, _pendingRotation);
            _collider.sharedMesh = _meshes[_spare];
            // The new mesh reaches physics at once, the move (autoSyncTransforms off) only before the
            // next simulation step: sync now, so no query sees the new patch at the old pose.
            Physics.SyncTransforms();
            _spare = 1 - _spare;
            _current = _pending;
            _hasCurrent = true;
            _builtSamples = _pendingSamples;   // a newer setting makes the next Update rebuild
            _stage = Stage.Idle;
            _task = null;
            RebuildCount++;
        }
    }
}
