using System;
using UnityEngine;
using UnityEngine.Rendering;
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
    /// copy of the material. Files: this, <c>.Cameras</c>, <c>.DrawMaterial</c>, <c>.Buffers</c>,
    /// <c>.VertexCache</c>, <c>.Levels</c>, <c>.Estimate</c>, <c>.Queries</c>; internals.md.
    /// </summary>
    [ExecuteAlways]
    [DisallowMultipleComponent]
    [AddComponentMenu("Gregory Terrain/Gregory Terrain Renderer")]
    public sealed partial class GregoryTerrainRenderer : MonoBehaviour
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

        [Tooltip("Tiles per side of the drawn area. More tiles draw more detail at the same max factor; fewer, larger tiles draw the same triangles faster.")]
        [SerializeField, Range(1, 64)] int tiles = 16;

        [Tooltip("Most subdivisions of a tile edge (at most 64). Caps the triangle count.")]
        [SerializeField, Range(1f, 64f)] float maxFactor = 64f;

        [Tooltip("How far, in pixels, the drawn triangles may stray from the surface (like Unity Terrain's Pixel Error). Halving it about doubles the triangles.")]
        [SerializeField, Range(0.25f, 64f)] float targetPixelError = 8f;

        [Tooltip("0: subdivide each tile edge by its size on screen. Above 0: subdivide every edge this many times (for testing and measuring).")]
        [SerializeField, Range(0, 64)] int uniformFactor;

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

        [Tooltip("Height of the largest noise layer, in terrain height units (the inspector shows metres: times Height Scale).")]
        [SerializeField, Range(0f, 0.5f)] float noiseAmplitude = 0.02f;
        [Tooltip("Noise cells across the whole terrain in the largest noise layer (the inspector shows one cell's width in metres).")]
        [SerializeField, Range(0.5f, 4096f)] float noiseFrequency = 16f;
        [Tooltip("How much finer each noise layer is than the one before it (2: twice as fine).")]
        [SerializeField, Range(1.1f, 8f)] float noiseAlpha = 2f;
        [Tooltip("How much weaker each noise layer is than the one before it (2: half the height).")]
        [SerializeField, Range(1.1f, 8f)] float noiseBeta = 2f;
        [Tooltip("Most noise layers added. Layers finer than the mesh can show are left out.")]
        [SerializeField, Range(0, 16)] int noiseOctaves = 6;
        [Tooltip("0: the mesh detail decides how many noise layers show. Above 0: assume this many vertices across the drawn area instead.")]
        [SerializeField, Min(0f)] float noiseVerticesAcross = 0f;

        [Tooltip("Height over which the colour blends from the low colour to the high colour, in terrain height units (the inspector shows metres).")]
        [SerializeField, Range(0.001f, 4f)] float colorGamma = 0.5f;
        [Tooltip("How strongly noise breaks up the boundary between the low and high colours.")]
        [SerializeField, Range(0f, 1f)] float colorNoiseAmplitude = 0.1f;
        [Tooltip("Noise cells across the whole terrain for the colour noise (the inspector shows one cell's width in metres).")]
        [SerializeField, Range(0.5f, 4096f)] float colorNoiseFrequency = 64f;
        [Tooltip("Colour of the low ground.")]
        [SerializeField] Color colorLow = new Color(0.22f, 0.33f, 0.14f);
        [Tooltip("Colour of the high ground.")]
        [SerializeField] Color colorHigh = new Color(0.9f, 0.9f, 0.92f);

        [Tooltip("Whether the terrain casts shadows.")]
        [SerializeField] ShadowCastingMode shadowCasting = ShadowCastingMode.On;
        [Tooltip("Whether the terrain receives shadows.")]
        [SerializeField] bool receiveShadows = true;

        /// <summary>Draws the patches' control points in the Scene view (editor only).</summary>
        [Tooltip("Draw the control points in the Scene view, to move them with handles (shortcut G in the Scene view by default).")]
        public bool debugShowControlPoints;
        /// <summary>Draws the patch boundaries in the Scene view (editor only).</summary>
        [Tooltip("Draw the patch boundaries in the Scene view (shortcut Shift+G in the Scene view by default).")]
        public bool debugShowPatchWireframe;

        // ---- state ----------------------------------------------------------------------------------
        MaterialPropertyBlock _props;
        GraphicsBuffer _controlPoints, _regions, _gridLines, _fallbackIndices;
        PatchGridAsset _uploadedGrid;
        int _uploadedVersion;
        int _fallbackIndexFactor;
        bool _settingsDirty = true;
        bool _originDirty = true;
        string _settingsError;
        PatchGrid _uploadedPatchGrid;
        TerrainRange _range = TerrainRange.full;
        readonly RangeOriginTracker _rangeOrigin = new RangeOriginTracker();    // the one range's origin
        readonly CameraRangeOrigins _cameraOrigins = new CameraRangeOrigins();  // with the levels, each camera's
        RangeOriginTracker _origin = new RangeOriginTracker();                  // the draw's: one of those (OriginTracker)
        TerrainParams _params;          // the constants last sent (range and origin kept current)
        Double3 _outputOffset;          // terrain space; what the deep-zoom relative output leaves out
        // What _outputOffset (a double Gregory evaluation plus the octaves) was computed from, and the
        // one before: two cameras with origins of their own (Horizon levels) switch without recomputing.
        OffsetInputs _offsetFor, _offsetForBefore;
        Double3 _outputOffsetBefore;
        float _gridMinZ, _gridMaxZ;
        DrawModeKey _drawModeKey;         // what _drawFallback was read for
        bool _drawFallback;
        static bool s_FallbackLogged;
        Matrix4x4 _objectToWorld = Matrix4x4.identity;   // what PushMatrices sent (deep-zoom offset included)
        Matrix4x4 _worldToObject = Matrix4x4.identity;   // its inverse, as sent (the cache's world normals)
        Matrix4x4 _pushedLocalToWorld;                   // the Transform's matrix when PushMatrices ran (offset not added)
        Double3 _worldOffset;                            // ShiftOrigin's sum, in double (floating origin)
        bool _frameDirty = true;                         // terrainSize, heightScale or the world offset changed
        int _gridStamp;                                  // bumped on every upload: the cache sees new grid buffers
        readonly System.Collections.Generic.List<int> _setLastPrepare = new System.Collections.Generic.List<int>(16);
        SnowSimulator _snow;                             // the enabled simulator attached to this renderer

        /// <summary>
        /// SubShader tag of GregoryTerrain.shader: "Tessellated" or "Fallback", the draw the SubShader
        /// expects (4-control-point tile patches, or the instanced vertex grid).
        /// </summary>
        const string DrawTag = "GregoryTerrainDraw";

        // ---- public API -----------------------------------------------------------------------------

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
                _frameDirty = true;
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
                _frameDirty = true;
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
            _frameDirty = true;
        }

        /// <summary>The sum of every <see cref="ShiftOrigin"/> so far, rounded to float (the renderer keeps it in double).</summary>
        public Vector3 WorldOriginOffset => new Vector3((float)_worldOffset.x, (float)_worldOffset.y, (float)_worldOffset.z);

        /// <summary>Transform, <see cref="TerrainSize"/>, <see cref="HeightScale"/> and the origin offset, in double: for matrices, queries, the collider.</summary>
        internal TerrainWorldFrame WorldFrame
        {
            get
            {
                Transform t = transform;
                return new TerrainWorldFrame(ToFloat4x4(t.localToWorldMatrix), ValidSize(), ValidHeightScale(), _worldOffset);
            }
        }

        /// <summary>A world point in the terrain's object space (x, height, y; the unit square across), through <see cref="WorldFrame"/>.</summary>
        internal Double3 WorldToTerrainObject(Vector3 world) => WorldFrame.WorldToObject(new Double3(world.x, world.y, world.z));

        /// <summary>An object point (x, height, y) in the world, through <see cref="WorldFrame"/>.</summary>
        internal Vector3 TerrainObjectToWorld(Double3 o)
        {
            Double3 w = WorldFrame.ObjectToWorld(o);
            return new Vector3((float)w.x, (float)w.y, (float)w.z);
        }

        /// <summary>World units per object unit along object x, height and y (Terrain Size, Height Scale and the Transform's scale).</summary>
        internal Double3 WorldUnitsPerObjectUnit => WorldFrame.ObjectScale;

        // The serialized values can be anything the Inspector or a scene file holds: a bad one draws
        // at 1 (logged by OnValidate) rather than throwing from every frame.
        Double2 ValidSize() => terrainSize.x > 0f && terrainSize.y > 0f && float.IsFinite(terrainSize.x) && float.IsFinite(terrainSize.y)
            ? new Double2(terrainSize.x, terrainSize.y) : new Double2(1.0, 1.0);
        double ValidHeightScale() => heightScale > 0f && float.IsFinite(heightScale) ? heightScale : 1.0;

        /// <summary>Tiles per side M.</summary>
        public int Tiles { get => tiles; set { tiles = Mathf.Clamp(value, 1, 64); _settingsDirty = true; } }

        /// <summary>
        /// The view: false draws one range (<c>Range</c> or a range controller's, the paper's view);
        /// true draws levels of detail from each camera's feet to the horizon (internals.md, "Levels of
        /// detail"), which needs an even <see cref="Tiles"/> of at least 8 and the tessellator.
        /// </summary>
        public bool HorizonLevels { get => horizonLevels; set { horizonLevels = value; _settingsDirty = true; } }

        /// <summary>Uniform factor (0 = adaptive); the Scene view's Uniform Factor Down / Up shortcuts (U / I by default) change it.</summary>
        public int UniformFactor { get => uniformFactor; set { uniformFactor = Mathf.Clamp(value, 0, 64); _settingsDirty = true; } }

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
        public bool DrawsFallback => material != null ? ReadDrawMode() : UsesFallback;

        /// <summary>The most triangles these settings draw: 2 F^2 per tile, F the uniform factor, else maxFactor (fallback: its grid's). A view's: <see cref="EstimateTrianglesInView"/>.</summary>
        public double EstimatedTriangleCount => DrawnTileCount * TessellationPolicy.EstimateTriangleCount(1,
            DrawsFallback ? fallbackGridFactor : uniformFactor > 0 ? uniformFactor : maxFactor);

        /// <summary>Tiles drawn: M^2 ((M + 1)^2 anchored), or the Horizon levels' (<see cref="LodLevels.DrawnTileCount"/>).</summary>
        internal int DrawnTileCount
        {
            get
            {
                int levels = LevelCount;
                if (levels > 0) return LodLevels.DrawnTileCount(levels, tiles);
                int across = TilesAcross(DrawsFallback);
                return across * across;
            }
        }

        /// <summary>Why the terrain cannot be drawn: the device (no structured buffers), or the current settings (Core's message, naming field and value); else null.</summary>
        public string SettingsError => s_DeviceError ?? _settingsError ?? _cacheError;

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
        public ComputeShader CacheShader { get => cacheShader; set { cacheShader = value; _cache.Invalidate(); } }

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
        public bool UsesVertexCache => _usesCache;

        /// <summary>Why Compute cache is chosen but the domain stage draws (no compute shaders, cache shader, LOD camera...), or null.</summary>
        public string VertexCacheFallbackReason => _cacheFallbackReason;

        /// <summary>
        /// GPU memory the vertex cache needs at the current settings, in bytes, whichever evaluation is
        /// chosen (Core's <see cref="VertexCacheBudget.TotalBytes"/>).
        /// </summary>
        public long VertexCacheBytes
        {
            get
            {
                int limit = VertexCache.FactorLimit(new TessellationSettings(tiles, maxFactor, targetPixelError, uniformFactor).ToFloat4());
                return VertexCacheBudget.TotalBytes(CacheTilesAcross, limit, SnowOn());
            }
        }

        /// <summary>Whether the tiles are anchored to the terrain: the setting, with adaptive factors and a tessellator.</summary>
        bool AnchorsTiles(bool fallback) => anchorTiles && !fallback && uniformFactor == 0 && !LevelsOn(fallback);

        /// <summary>Tiles per axis the draw makes: M + 1 anchored (<see cref="AnchorsTiles"/>), else M.</summary>
        int TilesAcross(bool fallback) => tiles + (AnchorsTiles(fallback) ? 1 : 0);

        /// <summary>Tiles per axis the cache holds (it never runs with the fallback grid).</summary>
        int CacheTilesAcross => TilesAcross(false);

        /// <summary>GPU memory the vertex cache holds now (0 while it is not allocated).</summary>
        public long VertexCacheAllocatedBytes => _cache.AllocatedBytes;

        /// <summary>True while GPU buffers for a grid are held.</summary>
        public bool HasGpuResources => _controlPoints != null;

        // ---- Unity messages -------------------------------------------------------------------------

        void OnEnable()
        {
            _settingsDirty = true;
            _originDirty = true;
            SyncRangeFromSerialized();
            RegisterCameraCallbacks();
#if UNITY_EDITOR
            // Buffers and the runtime material are native objects: free them before scripts reload,
            // or they leak (Unity warns); OnDisable does not run on a reload.
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
            _settingsDirty = true;
            _frameDirty = true;
            SyncRangeFromSerialized();
            try { TerrainWorldFrame.CheckScale(new Double2(terrainSize.x, terrainSize.y), heightScale); }
            catch (ArgumentException e) { Debug.LogError($"{name}: {e.Message}; drawing at 1 until fixed", this); }
        }

        /// <summary>GPU buffers, the runtime material copy and the per-draw state: what OnDisable and a domain reload free.</summary>
        internal void ReleaseAll()
        {
            ReleaseGpuResources();
            ReleaseDrawMaterial();
            _usesCache = false;
        }

        // ---- drawing --------------------------------------------------------------------------------

        /// <summary>Uploads, constants on change, <c>_Range</c>, the vertex cache, the material: steady state only <c>_Range</c>, no allocation. False when nothing can be drawn.</summary>
        bool Prepare(Camera cam = null)
        {
            _setLastPrepare.Clear();
            if (material == null || grid == null || !grid.IsValid) return false;
            if (!DeviceCanDraw()) return false;
            if (!EnsureUploaded()) return false;

            bool fallback = ReadDrawMode();
            if (fallback && !EnsureFallbackIndices()) return false;

            _origin = OriginTracker(cam, fallback);
            if (_origin.Update(OriginRange(cam, fallback)) || !_origin.Origin.Equals(_sent.origin)) _originDirty = true;
            // The lattice before the output offset: with noise the offset's octave count follows
            // the lattice's width (TileLattice.LayoutWidth).
            if (_settingsDirty)
            {
                PushSettings(fallback);   // all ten TerrainParams float4, _Range and _RangeOrigin included
                if (_settingsError == null) UpdateTileLattice(fallback);
                UpdateOutputOffset();
                PushMatrices();
                _settingsDirty = false;
            }
            else
            {
                PushRange();
                if (_settingsError == null) UpdateTileLattice(fallback);
                if (UpdateOutputOffset() || TransformMoved() || _frameDirty) PushMatrices();
            }
            if (_settingsError != null) return false;   // logged once; drawn again after the next valid change
            PushTessellationView(cam);
            UpdateNoiseTableBinding();   // before the cache: its kernels read the same table
            bool cacheReady;
            using (s_VertexCacheMarker.Auto())
                cacheReady = UpdateVertexCache(fallback);
            if (!cacheReady) return false;
            UpdateSnowBinding();
            // The range-origin keyword from the very _RangeOrigin just sent (_params): the stages
            // without it compile no origin code and would draw a set origin as 0.
            bool levels = LevelsOn(fallback);
            return UpdateDrawMaterial(_usesCache, SnowOn(), levels, RelativeSurface.NeedsRangeOriginKeyword(_params.rangeOrigin, levels, _usesCache)) != null;
        }

        /// <summary>
        /// The per-frame part: <c>_Range</c> relative to the origin (16 bytes). <c>_RangeOrigin</c>
        /// goes with it only in a frame where the origin re-snapped.
        /// </summary>
        void PushRange()
        {
            RangeMapping.EncodeRange(_range, _origin.Origin, out Float4 r, out Float4 o);
            SetVector(ShaderIds.Range, ToVector(r));
            _params.range = r;
            _params.rangeOrigin = o;
            if (_originDirty)
            {
                SetVector(ShaderIds.RangeOrigin, ToVector(o));
                _sent.origin = _origin.Origin;
                _params.tileLattice = default;   // in the old origin's coordinates: anchor again
                _originDirty = false;
            }
        }

        /// <summary>
        /// Anchored tiles (<see cref="TileLattice"/>): <c>_TileLattice</c> kept while the range only pans,
        /// anchored again on a zoom, re-snap or settings change; 0 when the tiles lie on the range.
        /// </summary>
        void UpdateTileLattice(bool fallback)
        {
            Float4 lattice = AnchorsTiles(fallback) ? TileLattice.Follow(_params.tileLattice, _params.range, tiles) : default;
            if (lattice.Equals(_params.tileLattice)) return;   // PushSettings sent 0 with the block
            _params = _params.WithTileLattice(lattice);
            SetVector(ShaderIds.TileLattice, ToVector(lattice));
        }

        /// <summary>
        /// Builds the TerrainParams block with Core (which validates every input) and sets each float4.
        /// On invalid settings nothing is set and nothing drawn until a change fixes them.
        /// </summary>
        void PushSettings(bool fallback)
        {
            var tess = new TessellationSettings(tiles, maxFactor, targetPixelError, fallback ? fallbackGridFactor : uniformFactor);
            var noise = new NoiseSettings(noiseAmplitude, noiseFrequency, noiseAlpha, noiseBeta, noiseOctaves);
            var heightColor = new HeightColorSettings(colorGamma, colorNoiseAmplitude, colorNoiseFrequency);
            Color low = colorLow.linear, high = colorHigh.linear;
            TerrainParams p;
            try
            {
                p = TerrainParams.Create(_uploadedPatchGrid, _range, _origin.Origin, tess, noise, heightColor,
                    new Float3(low.r, low.g, low.b), new Float3(high.r, high.g, high.b), noiseVerticesAcross);
                if (LevelsOn(fallback))
                {
                    string levels = LevelsSettingsError();
                    if (levels != null) throw new ArgumentException(levels, nameof(tiles));
                    // The continuous octave rule: both sides of a level seam draw the same noise.
                    p.noiseOctaves = new Float4(p.noiseOctaves.x, p.noiseOctaves.y, LevelSegmentPixels, 0f);
                }
            }
            catch (ArgumentException e)
            {
                if (_settingsError != e.Message)
                    Debug.LogError($"{name}: cannot draw with these settings: {e.Message}", this);
                _settingsError = e.Message;
                return;
            }
            _settingsError = null;
            _params = p;
            for (int k = 0; k < TerrainParams.Float4Count; k++)
                SetVector(ShaderIds.Params[k], ToVector(p[k]));
            _originDirty = false;   // and _TileLattice = 0: UpdateTileLattice anchors at the range if it should
            _sent.origin = _origin.Origin;
        }

        static Vector4 ToVector(Float4 v) => new Vector4(v.x, v.y, v.z, v.w);

        // Every value the renderer puts on its property block goes through these, so the steady
        // state (only _Range) can be checked: PropertiesSetLastPrepare.
        void SetVector(int id, Vector4 v) { _props.SetVector(id, v); _setLastPrepare.Add(id); }
        void SetMatrix(int id, Matrix4x4 m) { _props.SetMatrix(id, m); _setLastPrepare.Add(id); }
        void SetBuffer(int id, GraphicsBuffer b) { _props.SetBuffer(id, b); _setLastPrepare.Add(id); }

        /// <summary>Property IDs the last preparation set, in order (<c>_Range</c> alone when steady; cache buffers not listed).</summary>
        internal System.Collections.Generic.IReadOnlyList<int> PropertiesSetLastPrepare => _setLastPrepare;

        /// <summary>The property ID of <c>_Range</c> (for the Unity-side tests).</summary>
        internal static int RangePropertyId => ShaderIds.Range;

        /// <summary>What Unity picks the SubShader by, besides the device: material, shader, shader LOD (global, own), pipeline.</summary>
        readonly struct DrawModeKey
        {
            readonly Material _material;
            readonly Shader _shader;
            readonly int _globalLod, _shaderLod;
            readonly UnityEngine.Rendering.RenderPipelineAsset _pipeline;

            public DrawModeKey(Material material)
            {
                _material = material;
                _shader = material.shader;
                _globalLod = Shader.globalMaximumLOD;
                _shaderLod = _shader != null ? _shader.maximumLOD : 0;
                _pipeline = UnityEngine.Rendering.GraphicsSettings.currentRenderPipeline;
            }

            public bool Matches(in DrawModeKey o) => _material == o._material && _shader == o._shader
                && _globalLod == o._globalLod && _shaderLod == o._shaderLod && _pipeline == o._pipeline;
        }

        /// <summary>
        /// The draw the material's SubShader expects (<see cref="DrawsFallback"/>), read again only when
        /// its <see cref="DrawModeKey"/> changes (GetTag allocates); a change marks the settings dirty.
        /// </summary>
        bool ReadDrawMode()
        {
            var key = new DrawModeKey(material);
            if (key.Matches(_drawModeKey)) return _drawFallback;
            string tag = material.GetTag(DrawTag, false, "");
            bool fallback = tag == "Fallback" || (tag.Length == 0 && UsesFallback);
            if (fallback != _drawFallback) _settingsDirty = true;
            _drawModeKey = key;
            _drawFallback = fallback;
            return fallback;
        }

        /// <summary>With a range origin the shaders output <c>S(q) - S(O)</c>: S(O) in double (<see cref="TerrainVertex.OutputOffset(PatchGrid, TerrainParams, TerrainKeywords)"/>). True when it changed (matrices resent).</summary>
        bool UpdateOutputOffset()
        {
            TerrainKeywords keywords = NoiseKeywords();
            var inputs = new OffsetInputs(_uploadedPatchGrid, keywords, _params.rangeOrigin, _params.noise, TerrainVertex.OutputOffsetOctaves(_params));
            if (inputs.Same(_offsetFor)) return false;
            Double3 offset = inputs.Same(_offsetForBefore) ? _outputOffsetBefore
                : _uploadedPatchGrid == null ? Double3.zero : TerrainVertex.OutputOffset(_uploadedPatchGrid, _params, keywords);
            (_offsetForBefore, _outputOffsetBefore) = (_offsetFor, _outputOffset);
            _offsetFor = inputs;
            if (offset.x == _outputOffset.x && offset.y == _outputOffset.y && offset.z == _outputOffset.z) return false;
            _outputOffset = offset;
            return true;
        }

        readonly struct OffsetInputs
        {
            readonly PatchGrid _grid;
            readonly TerrainKeywords _keywords;
            readonly Float4 _origin, _noise;
            readonly float _octaves;

            public OffsetInputs(PatchGrid grid, TerrainKeywords keywords, Float4 origin, Float4 noise, float octaves)
            {
                _grid = grid; _keywords = keywords; _origin = origin; _noise = noise; _octaves = octaves;
            }

            // _grid null (nothing computed yet) never matches: an offset needs a grid.
            public bool Same(in OffsetInputs o) => _grid != null && _grid == o._grid && _keywords == o._keywords
                && _origin.Equals(o._origin) && _noise.Equals(o._noise) && _octaves.Equals(o._octaves);
        }

        /// <summary>RenderPrimitives has no object matrix: ours, <c>T(worldOffset) localToWorld S T(t)</c> and inverse in double (<see cref="TerrainWorldFrame.DrawMatrices"/>), sent on change.</summary>
        void PushMatrices()
        {
            _pushedLocalToWorld = transform.localToWorldMatrix;
            _frameDirty = false;
            WorldFrame.DrawMatrices(TerrainVertex.TerrainToObject(_outputOffset), out Float4x4 fm, out Float4x4 fw);
            Matrix4x4 m = ToMatrix4x4(fm), w = ToMatrix4x4(fw);
            SetMatrix(ShaderIds.ObjectToWorld, m);
            SetMatrix(ShaderIds.WorldToObject, w);
            _objectToWorld = m;   // the vertex cache's LOD matrix uses the same object matrix
            _worldToObject = w;
        }

        /// <summary>
        /// Whether the Transform moved since <see cref="PushMatrices"/>: compared, not Transform.hasChanged,
        /// which another script may clear.
        /// </summary>
        bool TransformMoved() => !VertexCachePass.SameMatrix(transform.localToWorldMatrix, _pushedLocalToWorld);

        /// <summary>
        /// World bounds of the drawn range: height between the lowest and highest control point,
        /// widened by the largest noise and raised by the snow cap (what the shader's culling keeps).
        /// </summary>
        internal Bounds WorldBounds()
        {
            float noise = NoiseMargin();
            float snow = SnowDepthCap();   // the shader's tile culling raises a tile's box by it (TileCulled)
            TerrainRange drawn = LevelsOn(_drawFallback) ? TerrainRange.full : _range;   // the levels end with the whole terrain
            Vector3 min = new Vector3((float)drawn.c, _gridMinZ - noise, (float)drawn.d);
            Vector3 max = new Vector3((float)drawn.g, _gridMaxZ + noise + snow, (float)drawn.h);
            Matrix4x4 m = _objectToWorld;   // size, height scale and offset included (t is added to the object points below)
            Double3 t = TerrainVertex.TerrainToObject(_outputOffset);
            min -= new Vector3((float)t.x, (float)t.y, (float)t.z);
            max -= new Vector3((float)t.x, (float)t.y, (float)t.z);
            Vector3 c = m.MultiplyPoint3x4(0.5f * (min + max));
            Vector3 e = 0.5f * (max - min);
            // Extents of a transformed box: |M| applied to the half sizes.
            Vector3 we = new Vector3(
                Mathf.Abs(m.m00) * e.x + Mathf.Abs(m.m01) * e.y + Mathf.Abs(m.m02) * e.z,
                Mathf.Abs(m.m10) * e.x + Mathf.Abs(m.m11) * e.y + Mathf.Abs(m.m12) * e.z,
                Mathf.Abs(m.m20) * e.x + Mathf.Abs(m.m21) * e.y + Mathf.Abs(m.m22) * e.z);
            return new Bounds(c, 2f * we);
        }

        static Matrix4x4 ToMatrix4x4(Float4x4 f) => new Matrix4x4
        {
            m00 = f.c0.x, m10 = f.c0.y, m20 = f.c0.z, m30 = f.c0.w,
            m01 = f.c1.x, m11 = f.c1.y, m21 = f.c1.z, m31 = f.c1.w,
            m02 = f.c2.x, m12 = f.c2.y, m22 = f.c2.z, m32 = f.c2.w,
            m03 = f.c3.x, m13 = f.c3.y, m23 = f.c3.z, m33 = f.c3.w,
        };

        /// <summary>
        /// The material's keywords that change the height noise, as Core names them: GT_NOISE, and
        /// with it GT_NOISE_TABLE (tiled noise is another noise, so other heights and offsets).
        /// </summary>
        TerrainKeywords NoiseKeywords()
        {
            if (material == null || !material.IsKeywordEnabled(ShaderIds.NoiseKeyword)) return TerrainKeywords.None;
            return material.IsKeywordEnabled(ShaderIds.NoiseTableKeyword) ? TerrainKeywords.Noise | TerrainKeywords.NoiseTable : TerrainKeywords.Noise;
        }

        /// <summary>sum_k amplitude / beta^k over the octaves: the most noise can move a point.</summary>
        float NoiseMargin()
        {
            float sum = 0f, a = noiseAmplitude;
            for (int k = 0; k < noiseOctaves; k++) { sum += a; a /= noiseBeta; }
            return sum;
        }

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
