using System;
using System.Collections.Generic;
using UnityEngine;
using UnityEngine.Rendering;
using static GregoryTerrain.FlatSettingsUpgrade;
using static GregoryTerrain.UnityConversions;
#if UNITY_EDITOR
using UnityEditor;
#endif

namespace GregoryTerrain
{
    /// <summary>
    /// Draws a <see cref="PatchGridAsset"/> with GregoryTerrain/Terrain in one procedural draw per camera
    /// (<c>beginCameraRendering</c> in URP/HDRP, <c>Camera.onPreCull</c> in Built-in; Edit Mode too):
    /// M x M tessellated tiles over <see cref="Range"/> or the Horizon levels. Only <c>_Range</c> is sent
    /// every frame (<see cref="PerFrameTrafficBytes"/>), the rest on change; keywords go on a runtime
    /// copy of the material (DrawMaterialCopy). The frame: TerrainFrameDriver; queries on <see cref="Surface"/>;
    /// Core's FramePlanner and FrameResources; internals.md.
    /// </summary>
    [ExecuteAlways]
    [DisallowMultipleComponent]
    [AddComponentMenu("Gregory Terrain/Gregory Terrain Renderer")]
    public sealed class GregoryTerrainRenderer : MonoBehaviour, ISerializationCallbackReceiver
    {
        /// <summary>
        /// Bytes set per camera in the steady state: <c>_Range</c>, one float4 (Compute cache too);
        /// Horizon levels add 20 float4. The rest, on change only: index.md, "What is sent per frame".
        /// </summary>
        public const int PerFrameTrafficBytes = 16;

        [Tooltip("The patch grid to draw. Changing it frees the old GPU buffers and uploads the new grid once.")]
        [SerializeField] PatchGridAsset grid;

        [Tooltip("A material using the GregoryTerrain/Terrain shader. Noise, height colour and debug views are toggles on the material.")]
        [SerializeField] Material material;

        [SerializeField] TessellationSettings tessellation = TessellationSettings.Default;

        [Tooltip("Keep the tiles fixed on the terrain while the view pans, so vertices don't swim and the Compute cache updates only the tiles a pan brings in.")]
        [SerializeField] bool anchorTiles = true;

        [Tooltip("Off: draw one range (Range, or a range controller's). On: draw levels from each camera's feet to the horizon (even Tiles, at least 8).")]
        [SerializeField] bool horizonLevels;

        [Tooltip("Only on GPUs without tessellation: each tile is drawn as a fixed grid with this many cells per side.")]
        [SerializeField, Range(1, 64)] int fallbackGridFactor = 16;

        [Tooltip("Domain stage: every camera evaluates its own vertices. Compute cache: vertices are evaluated once per change into GPU memory, from the LOD camera's view.")]
        [SerializeField] VertexEvaluation vertexEvaluation = VertexEvaluation.DomainStage;
        [Tooltip("The compute shader of the Compute cache: Shaders/Cache/TerrainCache.compute.")]
        [SerializeField] ComputeShader cacheShader;
        [Tooltip("The camera whose view sets the detail and culls tiles for all cameras and shadows. Empty: the main camera.")]
        [SerializeField] Camera lodCamera;

        [Tooltip("Metres across the terrain's x and y (the whole grid). Keep the Transform's scale at 1: a scale there multiplies this.")]
        [SerializeField] Vector2 terrainSize = new Vector2(1f, 1f);
        [Tooltip("Metres per terrain height unit (a grid height of 0.01 on a terrainSize of 1000 m with heightScale 1000 is 10 m).")]
        [SerializeField] float heightScale = 1f;

        [Tooltip("The part of the terrain drawn, as min x, min y, max x, max y inside 0..1. Range controllers set it every frame.")]
        [SerializeField] Vector4 range = new Vector4(0f, 0f, 1f, 1f);

        [SerializeField] NoiseSettings noise = new NoiseSettings(0.02f, 16f, 2f, 2f, 6);
        [Tooltip("0: the mesh detail decides how many noise layers show. Above 0: assume this many vertices across the drawn area instead.")]
        [SerializeField, Min(0f)] float noiseVerticesAcross = 0f;

        [SerializeField] HeightColorSettings heightColor = new HeightColorSettings(0.5f, 0.1f, 64f);
        [Tooltip("Colour of the low ground.")]
        [SerializeField] Color colorLow = new Color(0.22f, 0.33f, 0.14f);
        [Tooltip("Colour of the high ground.")]
        [SerializeField] Color colorHigh = new Color(0.9f, 0.9f, 0.92f);

        [Tooltip("Whether the terrain casts shadows.")]
        [SerializeField] ShadowCastingMode shadowCasting = ShadowCastingMode.On;
        [Tooltip("Whether the terrain receives shadows.")]
        [SerializeField] bool receiveShadows = true;

        // The old flat layout, unset unless old data wrote it (FlatSettingsUpgrade).
        const string MovedIntoStructs = "moved into tessellation, noise and heightColor";
        [SerializeField, HideInInspector, Obsolete(MovedIntoStructs)] int tiles = UnsetInt;
        [SerializeField, HideInInspector, Obsolete(MovedIntoStructs)] float maxFactor = UnsetFloat;
        [SerializeField, HideInInspector, Obsolete(MovedIntoStructs)] float targetPixelError = UnsetFloat;
        [SerializeField, HideInInspector, Obsolete(MovedIntoStructs)] int uniformFactor = UnsetInt;
        [SerializeField, HideInInspector, Obsolete(MovedIntoStructs)] float noiseAmplitude = UnsetFloat;
        [SerializeField, HideInInspector, Obsolete(MovedIntoStructs)] float noiseFrequency = UnsetFloat;
        [SerializeField, HideInInspector, Obsolete(MovedIntoStructs)] float noiseAlpha = UnsetFloat;
        [SerializeField, HideInInspector, Obsolete(MovedIntoStructs)] float noiseBeta = UnsetFloat;
        [SerializeField, HideInInspector, Obsolete(MovedIntoStructs)] int noiseOctaves = UnsetInt;
        [SerializeField, HideInInspector, Obsolete(MovedIntoStructs)] float colorGamma = UnsetFloat;
        [SerializeField, HideInInspector, Obsolete(MovedIntoStructs)] float colorNoiseAmplitude = UnsetFloat;
        [SerializeField, HideInInspector, Obsolete(MovedIntoStructs)] float colorNoiseFrequency = UnsetFloat;

        /// <summary>Draws the patches' control points in the Scene view (editor only).</summary>
        [Tooltip("Draw the control points in the Scene view, to move them with handles (shortcut G in the Scene view by default).")]
        public bool debugShowControlPoints;
        /// <summary>Draws the patch boundaries in the Scene view (editor only).</summary>
        [Tooltip("Draw the patch boundaries in the Scene view (shortcut Shift+G in the Scene view by default).")]
        public bool debugShowPatchWireframe;

        // ---- state: the inputs set through the API, and the owners ------------------------------------
        TerrainRange _range = TerrainRange.full;         // the drawn range (SetDrawnRange leaves the saved one alone)
        Double3 _worldOffset;                            // ShiftOrigin's sum, in double (floating origin)
        SnowSimulator _snow;                             // the enabled simulator attached to this renderer
        TerrainFrameDriver _frameDriver;                 // the per-camera frame: GPU objects, Core's FrameState
        GregoryTerrainSurface _surface;                  // made on first use

        TerrainFrameDriver Frame => _frameDriver ??= new TerrainFrameDriver(this);
        FrameState _state => Frame.State;
        FrameResources _keys => _state.resources;

        // ---- public API -----------------------------------------------------------------------------

        /// <summary>Height, normal, ray and triangle-count queries on the surface this renderer draws.</summary>
        public GregoryTerrainSurface Surface => _surface ??= new GregoryTerrainSurface(this);

        /// <inheritdoc cref="GregoryTerrainSurface.RaycastToleranceMeters"/>
        public const float RaycastToleranceMeters = GregoryTerrainSurface.RaycastToleranceMeters;

        /// <inheritdoc cref="GregoryTerrainSurface.SampleHeight"/>
        public float SampleHeight(Vector3 worldPosition) => Surface.SampleHeight(worldPosition);

        /// <inheritdoc cref="GregoryTerrainSurface.SampleNormal"/>
        public Vector3 SampleNormal(Vector3 worldPosition) => Surface.SampleNormal(worldPosition);

        /// <inheritdoc cref="GregoryTerrainSurface.TrySampleSurface"/>
        public bool TrySampleSurface(Vector3 worldPosition, out Vector3 surfacePoint, out Vector3 surfaceNormal) =>
            Surface.TrySampleSurface(worldPosition, out surfacePoint, out surfaceNormal);

        /// <inheritdoc cref="GregoryTerrainSurface.SampleHeights"/>
        public void SampleHeights(ReadOnlySpan<Vector3> worldPositions, Span<float> heights) => Surface.SampleHeights(worldPositions, heights);

        /// <inheritdoc cref="GregoryTerrainSurface.Raycast"/>
        public bool Raycast(Ray ray, float maxDistance, out Vector3 point, out Vector3 normal, out float distance) =>
            Surface.Raycast(ray, maxDistance, out point, out normal, out distance);

        /// <inheritdoc cref="GregoryTerrainSurface.EstimateTrianglesInView"/>
        public TriangleEstimate? EstimateTrianglesInView(Camera cam, int maxTiles = 256) => Surface.EstimateTrianglesInView(cam, maxTiles);

        /// <summary>The Core query behind <see cref="Surface"/> (GregoryTerrainCollider).</summary>
        internal TerrainSurfaceQuery SurfaceQuery => Surface.Query;

        /// <summary>The queries' noise: with GT_NOISE the noise settings, else null.</summary>
        internal NoiseSettings? QueryNoise => material != null && material.IsKeywordEnabled(ShaderKeywords.Noise)
            ? noise : (NoiseSettings?)null;

        /// <summary>Whether a grid is uploaded with valid settings: <see cref="WorldBounds"/> holds the drawn terrain.</summary>
        internal bool HasDrawn => Frame.Gpu.Grid != null && _state.error == null;

        // The estimate's inputs.
        internal PatchGrid UploadedPatchGrid => Frame.Gpu.Grid;
        internal FrameState State => _state;

        /// <summary>The patch grid drawn. Setting another asset releases and re-uploads on the next frame.</summary>
        public PatchGridAsset Grid { get => grid; set => grid = value; }

        /// <summary>The material (GregoryTerrain/Terrain shader).</summary>
        public Material Material { get => material; set => material = value; }

        /// <summary>
        /// Metres across the terrain's x and y (Unity's x and z): the object-to-world matrix carries it,
        /// so the Transform can keep scale 1 (a scale there multiplies it). Throws ArgumentException (naming the
        /// field and value) unless both are finite and positive.
        /// </summary>
        public Vector2 TerrainSize
        {
            get => terrainSize;
            set
            {
                TerrainWorldFrame.CheckScale(new Double2(value.x, value.y), heightScale);
                terrainSize = value;
            }
        }

        /// <summary>Metres per terrain height unit (Unity's y). Throws ArgumentException unless finite and positive.</summary>
        public float HeightScale
        {
            get => heightScale;
            set
            {
                TerrainWorldFrame.CheckScale(new Double2(terrainSize.x, terrainSize.y), value);
                heightScale = value;
            }
        }

        /// <summary>
        /// Floating origin: the world moved by <paramref name="delta"/>; the terrain follows as a double
        /// offset, not in the float Transform (4 mm steps at 50 km; do not move it too). Queries and the
        /// collider follow. Throws ArgumentException unless <paramref name="delta"/> is finite.
        /// </summary>
        public void ShiftOrigin(Vector3 delta)
        {
            if (!(float.IsFinite(delta.x) && float.IsFinite(delta.y) && float.IsFinite(delta.z)))
                throw new ArgumentException($"delta {delta} must be finite", nameof(delta));
            _worldOffset += new Double3(delta.x, delta.y, delta.z);
        }

        /// <summary>The sum of every <see cref="ShiftOrigin"/> so far, rounded to float (the renderer keeps it in double).</summary>
        public Vector3 WorldOriginOffset => new Vector3((float)_worldOffset.x, (float)_worldOffset.y, (float)_worldOffset.z);

        /// <summary>Transform, size, height scale and origin offset, in double: for matrices, queries, the collider.</summary>
        internal TerrainWorldFrame WorldFrame
        {
            get
            {
                Transform t = transform;
                return new TerrainWorldFrame(ToFloat4x4(t.localToWorldMatrix), ValidSize(), ValidHeightScale(), _worldOffset);
            }
        }

        /// <summary>A world point in the terrain's object space (x, height, y; the unit square across).</summary>
        internal Double3 WorldToTerrainObject(Vector3 world) => WorldFrame.WorldToObject(new Double3(world.x, world.y, world.z));

        /// <summary>An object point (x, height, y) in the world, through <see cref="WorldFrame"/>.</summary>
        internal Vector3 TerrainObjectToWorld(Double3 o)
        {
            Double3 w = WorldFrame.ObjectToWorld(o);
            return new Vector3((float)w.x, (float)w.y, (float)w.z);
        }

        /// <summary>World units per object unit along object x, height and y.</summary>
        internal Double3 WorldUnitsPerObjectUnit => WorldFrame.ObjectScale;

        // The serialized values can be anything the Inspector or a scene file holds: a bad one draws
        // at 1 (logged by OnValidate) rather than throwing from every frame.
        internal Double2 ValidSize() => terrainSize.x > 0f && terrainSize.y > 0f && float.IsFinite(terrainSize.x) && float.IsFinite(terrainSize.y)
            ? new Double2(terrainSize.x, terrainSize.y) : new Double2(1.0, 1.0);
        internal double ValidHeightScale() => heightScale > 0f && float.IsFinite(heightScale) ? heightScale : 1.0;

        /// <summary>Tiles per side M.</summary>
        public int Tiles { get => tessellation.tiles; set => tessellation.tiles = Mathf.Clamp(value, 1, 64); }

        /// <summary>
        /// The view: false draws one range (<c>Range</c> or a range controller's, the paper's view);
        /// true draws levels of detail from each camera's feet to the horizon (internals.md, "Levels of
        /// detail"), which needs an even <see cref="Tiles"/> of at least 8 and the tessellator.
        /// </summary>
        public bool HorizonLevels { get => horizonLevels; set => horizonLevels = value; }

        /// <summary>Uniform factor (0 = adaptive); the Scene view's Uniform Factor Down / Up shortcuts (U / I by default) change it.</summary>
        public int UniformFactor { get => (int)tessellation.uniformFactor; set => tessellation.uniformFactor = Mathf.Clamp(value, 0, 64); }

        /// <summary>The drawn range. Throws ArgumentException (field and value) unless finite, non-empty and in the unit square; the old one is kept.</summary>
        public TerrainRange Range
        {
            get => _range;
            set
            {
                value.Validate("Range");
                _range = value;
                range = new Vector4((float)value.c, (float)value.d, (float)value.g, (float)value.h);
            }
        }

        /// <summary>The drawn range, the serialized one left alone (range controllers in Edit Mode: no Undo, no scene change). Throws like <see cref="Range"/>.</summary>
        public void SetDrawnRange(TerrainRange value)
        {
            value.Validate("Range");
            _range = value;
        }

        /// <summary>The saved range (the serialized field), which <see cref="SetDrawnRange"/> leaves alone.</summary>
        internal Vector4 SavedRange => range;

        /// <summary>True when this device has no tessellation shaders (Unity then skips the tessellated SubShaders).</summary>
        public static bool UsesFallback => !SystemInfo.supportsTessellationShaders;

        /// <summary>True when the vertex-shader fallback draws: the SubShader's "GregoryTerrainDraw" tag (Material.GetTag), else no tessellation on the device.</summary>
        public bool DrawsFallback => material != null ? Frame.ReadDrawMode() : UsesFallback;

        /// <summary>The most triangles these settings draw: 2 F^2 per tile, F the uniform factor, else maxFactor (fallback: its grid's). A view's: <see cref="EstimateTrianglesInView"/>.</summary>
        public double EstimatedTriangleCount => DrawnTileCount * TessellationPolicy.EstimateTriangleCount(1,
            DrawsFallback ? fallbackGridFactor : tessellation.IsUniform ? tessellation.uniformFactor : tessellation.maxFactor);

        /// <summary>Tiles drawn: M^2 ((M + 1)^2 anchored), or the Horizon levels' (<see cref="LodLevels.DrawnTileCount"/>).</summary>
        internal int DrawnTileCount
        {
            get
            {
                int levels = LevelCount;
                if (levels > 0) return LodLevels.DrawnTileCount(levels, tessellation.tiles);
                int across = TilesAcross(DrawsFallback);
                return across * across;
            }
        }

        /// <summary>Why the terrain cannot be drawn: the device (no structured buffers), or the current settings (Core's message, naming field and value); else null.</summary>
        public string SettingsError => TerrainFrameDriver.DeviceError ?? _state.error ?? _keys.CacheError;

        /// <summary>
        /// Where the vertices are evaluated (<see cref="GregoryTerrain.VertexEvaluation"/>). Compute
        /// cache falls back to the domain stage where it cannot run (<see cref="VertexCacheFallbackReason"/>).
        /// </summary>
        public VertexEvaluation VertexEvaluation
        {
            get => vertexEvaluation;
            set
            {
                if (value != VertexEvaluation.DomainStage && value != VertexEvaluation.ComputeCache)
                    throw new ArgumentException($"VertexEvaluation ({(int)value}) must be DomainStage or ComputeCache", nameof(value));
                vertexEvaluation = value;
            }
        }

        /// <summary>Shaders/Cache/TerrainCache.compute, for <see cref="VertexEvaluation.ComputeCache"/>.</summary>
        public ComputeShader CacheShader { get => cacheShader; set { cacheShader = value; Frame.InvalidateCache(); } }

        /// <summary>The camera whose view sets the cached tessellation (null: Camera.main).</summary>
        public Camera LodCamera { get => lodCamera; set => lodCamera = value; }

        /// <summary>The camera the cache's tessellation follows now: <see cref="LodCamera"/>, else Camera.main (may be null).</summary>
        public Camera EffectiveLodCamera => lodCamera != null ? lodCamera : Camera.main;

        /// <summary>
        /// The enabled Snow Simulator whose Terrain is this renderer, or null. It attaches itself;
        /// while attached the draw has GT_SNOW and samples its depth map (see <see cref="SnowOn"/>).
        /// </summary>
        public SnowSimulator SnowSimulator => _snow;

        /// <summary>True when the last frame drew from the vertex cache (GT_VERTEX_CACHE on).</summary>
        public bool UsesVertexCache => _keys.UsesCache;

        /// <summary>Why Compute cache is chosen but the domain stage draws (no compute shaders, cache shader, LOD camera...), or null.</summary>
        public string VertexCacheFallbackReason => _keys.CacheFallbackReason;

        /// <summary>
        /// GPU memory the vertex cache needs at the current settings, in bytes, whichever evaluation is
        /// chosen (Core's <see cref="VertexCacheBudget.TotalBytes"/>).
        /// </summary>
        public long VertexCacheBytes
        {
            get
            {
                int limit = VertexCache.FactorLimit(Settings(false).tess.ToFloat4());
                return VertexCacheBudget.TotalBytes(CacheTilesAcross, limit, SnowOn());
            }
        }

        /// <summary>Tiles per axis the draw makes: M + 1 anchored, else M.</summary>
        int TilesAcross(bool fallback) => tessellation.tiles + (Settings(fallback).AnchorsTiles ? 1 : 0);

        /// <summary>Tiles per axis the cache holds (it never runs with the fallback grid).</summary>
        internal int CacheTilesAcross => TilesAcross(false);

        /// <summary>GPU memory the vertex caches hold now: the single range's, or with Horizon levels every camera's factor and vertex buffers (0 while none is allocated).</summary>
        public long VertexCacheAllocatedBytes => Frame.CacheAllocatedBytes;

        /// <summary>True while GPU buffers for a grid are held.</summary>
        public bool HasGpuResources => Frame.Gpu.ControlPoints != null;

        // ---- Horizon levels (internals.md), laid out by the planner

        /// <summary>Narrowest level, in metres: the feet's level is the first power-of-two part at least this wide.</summary>
        internal const double FinestLevelMeters = 16.0;

        /// <summary>The levels drawn: the setting, with the tessellator.</summary>
        internal bool LevelsOn(bool fallback) => horizonLevels && !fallback;

        /// <summary>The finest level's exponent for the terrain's width in world units.</summary>
        internal int FinestExponent()
        {
            double metres = WorldUnitsPerObjectUnit.x;   // world units across the terrain's x
            if (!(metres > 0.0) || double.IsInfinity(metres)) metres = 1.0;
            return Math.Min(LodLevels.FinestExponent(metres, FinestLevelMeters), LodTiles.MaxLevels - 1);
        }

        /// <summary>Horizon levels drawn (L), 0 for one range.</summary>
        internal int LevelCount => LevelsOn(DrawsFallback) ? LodLevels.LevelCount(FinestExponent()) : 0;

        internal Matrix4x4 ObjectToClip(Camera cam) => UnityConversions.ObjectToClip(cam, _state.objectToWorld);

        // ---- the draw material and the Snow Simulator attached

        /// <summary>The material drawn now: the asset, or its runtime copy while the keywords differ.</summary>
        internal Material DrawMaterial => Frame.DrawMaterial;

        internal Material UpdateDrawMaterial(FrameKeywords keywords) => Frame.UpdateDrawMaterial(keywords);

        /// <summary>True while the tiled noise's table is held (the Unity-side tests).</summary>
        internal bool HasNoiseTable => Frame.Gpu.NoiseCells != null;

        /// <summary>Whole grid uploads (the Unity-side tests).</summary>
        internal int UploadCount => Frame.UploadCount;

        /// <summary>True while an enabled Snow Simulator is attached and holds a depth map: the draw has GT_SNOW.</summary>
        internal bool SnowOn() => _snow != null && _snow.DepthBuffer != null;

        /// <summary>HLSL <c>SnowDepthCap()</c>: the deepest snow drawn, in terrain height units (0 without snow).</summary>
        internal float SnowDepthCap() => SnowOn() ? _snow.MapSize.z : 0f;

        /// <summary>Called by a Snow Simulator whose Terrain is this renderer, when it is enabled.</summary>
        internal void AttachSnow(SnowSimulator simulator)
        {
            if (_snow != null && _snow != simulator)
                Debug.LogWarning($"{name}: Snow Simulator '{simulator.name}' replaces '{_snow.name}'; one simulator per terrain.", this);
            _snow = simulator;
        }

        /// <summary>Called by the attached Snow Simulator when it is disabled or retargeted.</summary>
        internal void DetachSnow(SnowSimulator simulator)
        {
            if (_snow != simulator) return;
            _snow = null;
        }

        /// <summary>
        /// What a Snow Simulator evaluates its field from: the grid's buffers, the constants last
        /// sent (any range: the simulator replaces it), whether the material has GT_NOISE, and with tiled
        /// noise (GT_NOISE_TABLE) the noise table, else null. False until a grid is uploaded with valid settings.
        /// </summary>
        internal bool TryGetSnowTerrain(out TerrainGpuBuffers buffers, out TerrainParams parameters, out bool noise, out GraphicsBuffer noiseCells, out int gridStamp)
        {
            buffers = Frame.Gpu;
            parameters = _state.parameters; gridStamp = Frame.GridStamp;
            noise = material != null && material.IsKeywordEnabled(ShaderKeywords.Noise);
            bool ready = HasDrawn;
            // The table the draw binds (made here if the simulator asks before the next draw does).
            noiseCells = ready && noise ? Frame.EnsureNoiseTable() : null;
            return ready;
        }

        // ---- Unity messages -------------------------------------------------------------------------

        void OnEnable()
        {
            SyncRangeFromSerialized();
            RegisterCameraCallbacks();
#if UNITY_EDITOR
            // Buffers and the runtime material are native objects: free them before scripts reload,
            // or they leak (Unity warns), whether or not OnDisable runs first (releasing twice is safe).
            AssemblyReloadEvents.beforeAssemblyReload += ReleaseAll;
#endif
        }

        void OnDisable()
        {
#if UNITY_EDITOR
            AssemblyReloadEvents.beforeAssemblyReload -= ReleaseAll;
#endif
            UnregisterCameraCallbacks();
            ReleaseAll();
        }

        void OnDestroy() => ReleaseAll();

        void OnValidate()
        {
            SyncRangeFromSerialized();
            try { TerrainWorldFrame.CheckScale(new Double2(terrainSize.x, terrainSize.y), heightScale); }
            catch (ArgumentException e) { Debug.LogError($"{name}: {e.Message}; drawing at 1 until fixed", this); }
        }

        /// <summary>What OnDisable and a domain reload free.</summary>
        internal void ReleaseAll() => _frameDriver?.ReleaseAll();

        /// <summary>Releases every GPU buffer this renderer holds. Safe to call twice.</summary>
        public void ReleaseGpuResources() => _frameDriver?.ReleaseGpuResources();

        // ---- drawing --------------------------------------------------------------------------------

        // The callbacks each pipeline calls for every camera it renders (Game, Scene view in Edit Mode,
        // reflection probes, several cameras), which cameras draw, and the draw.

        /// <summary>Both registered: <c>beginCameraRendering</c> (URP, HDRP), <c>Camera.onPreCull</c> (Built-in).</summary>
        void RegisterCameraCallbacks()
        {
            RenderPipelineManager.beginCameraRendering += OnBeginCameraRendering;
            Camera.onPreCull += OnCameraPreCull;
        }

        void UnregisterCameraCallbacks()
        {
            RenderPipelineManager.beginCameraRendering -= OnBeginCameraRendering;
            Camera.onPreCull -= OnCameraPreCull;
        }

        void OnBeginCameraRendering(ScriptableRenderContext context, Camera cam) => DrawFor(cam);

        void OnCameraPreCull(Camera cam) => DrawFor(cam);

        internal void DrawFor(Camera cam) => Frame.DrawFor(cam);

        /// <summary>Property IDs the last preparation set, in order (cache buffers not listed).</summary>
        internal IReadOnlyList<int> PropertiesSetLastPrepare => Frame.PropertiesSetLastPrepare;

        internal Bounds WorldBounds() => Frame.WorldBounds();

        /// <summary>The serialized settings as Core values; the fallback draws its grid's factor as the uniform factor.</summary>
        internal FrameSettings Settings(bool fallback)
        {
            Color low = colorLow.linear, high = colorHigh.linear;
            TessellationSettings tess = tessellation;
            if (fallback) tess.uniformFactor = fallbackGridFactor;
            return new FrameSettings
            {
                tess = tess, noise = noise, heightColor = heightColor,
                colorLow = new Float3(low.r, low.g, low.b), colorHigh = new Float3(high.r, high.g, high.b),
                noiseVerticesAcross = noiseVerticesAcross, anchorTiles = anchorTiles, levels = LevelsOn(fallback), fallback = fallback,
            };
        }

        // What the frame reads besides the public settings.
        internal ShadowCastingMode ShadowCasting => shadowCasting;
        internal bool ReceivesShadows => receiveShadows;
        internal int FallbackGridFactor => fallbackGridFactor;
        internal Double3 WorldOffset => _worldOffset;

        /// <summary>
        /// The material's keywords that change the height noise, as Core names them: GT_NOISE, and
        /// with it GT_NOISE_TABLE (tiled noise is another noise, so other heights and offsets).
        /// </summary>
        internal TerrainKeywords NoiseKeywords()
        {
            if (material == null || !material.IsKeywordEnabled(ShaderKeywords.Noise)) return TerrainKeywords.None;
            return material.IsKeywordEnabled(ShaderKeywords.NoiseTable) ? TerrainKeywords.Noise | TerrainKeywords.NoiseTable : TerrainKeywords.Noise;
        }

        /// <summary>sum_k amplitude / beta^k over the octaves: the most noise can move a point.</summary>
        internal float NoiseMargin()
        {
            float sum = 0f, a = noise.amplitude;
            for (int k = 0; k < noise.octaves; k++) { sum += a; a /= noise.beta; }
            return sum;
        }

        void ISerializationCallbackReceiver.OnBeforeSerialize() { }

#pragma warning disable CS0618
        void ISerializationCallbackReceiver.OnAfterDeserialize() => Move(ref tessellation, ref noise, ref heightColor,
            tiles: ref tiles, maxFactor: ref maxFactor, targetPixelError: ref targetPixelError, uniformFactor: ref uniformFactor,
            noiseAmplitude: ref noiseAmplitude, noiseFrequency: ref noiseFrequency, noiseAlpha: ref noiseAlpha, noiseBeta: ref noiseBeta,
            noiseOctaves: ref noiseOctaves, colorGamma: ref colorGamma, colorNoiseAmplitude: ref colorNoiseAmplitude,
            colorNoiseFrequency: ref colorNoiseFrequency);
#pragma warning restore CS0618

        internal void SyncRangeFromSerialized()
        {
            var r = new TerrainRange(range.x, range.y, range.z, range.w);
            try { r.Validate("range"); }
            catch (ArgumentException e)
            {
                Debug.LogError($"{name}: {e.Message}; keeping {_range}", this);
                return;
            }
            _range = r;
        }
    }
}
