using System.Collections.Generic;
using UnityEngine;
using UnityEngine.Rendering;

namespace GregoryTerrain
{
    /// <summary>
    /// The Horizon levels' kernels of TerrainCache.compute, per camera before its draw, every frame,
    /// where they run (internals.md, "Levels of detail"): factors, then vertex records, read while
    /// <c>_LodLevels.y</c> and <c>.z</c> say so; else the hull and domain stage compute them. Buffers
    /// per camera: HDRP raises every camera's callback before it executes any camera's draws. The
    /// records grow from each frame's report (<see cref="AsyncGPUReadback"/>); until then the tiles
    /// past the end evaluate in the domain stage.
    /// </summary>
    sealed class LevelFactorPass
    {
        sealed class CameraFactors
        {
            public Camera camera;
            public GraphicsBuffer buffer;   // a LodFactorRecord a draw patch, sized on a level-layout change
            public int patches, frame;      // frame: Time.frameCount when last dispatched
            public GraphicsBuffer records;  // the vertex cache: C records of R uint4 (R = 2 with snow)
            public int capacity, uint4s;    // C, R
            public long needed;             // the records the last read-back frame needed
            public bool reading;            // a readback of draw patch 0's record is in flight
            public System.Action<AsyncGPUReadbackRequest> onRead;   // made once a camera: no allocation a frame

            // Draw patch 0's record: inside.w (float 7) holds the records the frame needed.
            public void Read(AsyncGPUReadbackRequest request)
            {
                reading = false;
                if (!request.hasError) needed = (long)request.GetData<float>()[7];
            }
        }

        readonly Dictionary<int, CameraFactors> _byCamera = new Dictionary<int, CameraFactors>();
        readonly List<int> _evicted = new List<int>();
        GraphicsBuffer _bound;     // what the property block's _LodFactors names now
        GraphicsBuffer _unused;    // one record bound while the hull computes the factors: every declared buffer is bound (Metal)
        GraphicsBuffer _noRecords; // one record bound while the domain stage evaluates every vertex
        GraphicsBuffer _boundRecords;   // what the property block's _VertexCache names now
        ComputeShader _kernelShader;
        int _piecesKernel = -1, _seamsKernel = -1, _slotsKernel = -1, _verticesKernel = -1;
        string _cacheOffReason;    // why the vertex cache did not run last frame (warned once a reason), or null
        readonly Vector4[] _ranges = new Vector4[LodTiles.MaxLevels];   // SetVectorArray's copy of the plan's levels

        /// <summary>GPU memory held now (0 when released).</summary>
        public long AllocatedBytes
        {
            get
            {
                long records = _unused != null ? 1 : 0, cache = _noRecords != null ? 2 : 0;
                foreach (CameraFactors f in _byCamera.Values) { records += f.patches; cache += (long)f.capacity * f.uint4s; }
                return records * LodFactorRecord.Stride + cache * GpuLayout.Uint4Stride;
            }
        }

        /// <summary>The records the camera's draw reads from (<c>_LodLevels.z</c>), 0 when the domain stage evaluates every vertex.</summary>
        public int CacheRecords { get; private set; }

        /// <summary>A camera's frame, after the plan: dispatches or stops. True when the hull's switch or the records' count changed (<c>_LodLevels</c> to send).</summary>
        public bool UpdateFrame(GregoryTerrainRenderer r, Camera cam, bool fallback, FrameState state, TerrainGpuBuffers gpu, MaterialPropertyBlock props)
        {
            // Draws nothing; the single range's pass may bind _VertexCache meanwhile, so the records' memo goes.
            // With the levels off the release below runs whatever the camera.
            if ((cam == null || cam.pixelWidth <= 0 || cam.pixelHeight <= 0) && r.LevelsOn(fallback)) { _boundRecords = null; return false; }
            FrameResources keys = state.resources;
            bool was = keys.UsesLevelKernels;
            string reason = r.LevelsOn(fallback) ? UnavailableReason(r.CacheShader) : null;
            if (!r.LevelsOn(fallback) || reason != null)
            {
                if (keys.LevelKernelsNotUsed(reason))
                    Debug.LogWarning($"{r.name}: the Horizon levels' factor kernels do not run ({reason}); the hull stage computes the factors instead (slower).", r);
                ReleaseCameraBuffers();
                if (!r.LevelsOn(fallback)) { Release(); return was; }
                _unused ??= new GraphicsBuffer(GraphicsBuffer.Target.Structured, 1, LodFactorRecord.Stride);
                Bind(props, _unused);
                return BindRecords(props, NoRecords(), 0) || was;
            }
            keys.LevelKernelsUsed();
            int tiles = r.Tiles, patches = state.levelCount * LodTiles.TilesPerLevel(tiles);
            CameraFactors f = FactorsOf(cam, patches);
            Bind(props, f.buffer);
            Dispatch(r, cam, state, gpu, tiles, f);
            bool cache = CacheRuns(r);
            if (cache) { EnsureRecords(f, state, r.SnowOn(), tiles); DispatchCache(state, tiles, f); }
            bool changed = BindRecords(props, cache ? f.records : NoRecords(), cache ? f.capacity : 0);
            return !was || changed;
        }

        GraphicsBuffer NoRecords() => _noRecords ??= new GraphicsBuffer(GraphicsBuffer.Target.Structured, 2, GpuLayout.Uint4Stride);

        /// <summary>Binds the draw's records and their count; true when the count changed (<c>_LodLevels</c> to send).</summary>
        bool BindRecords(MaterialPropertyBlock props, GraphicsBuffer records, int count)
        {
            if (records != _boundRecords || !props.HasBuffer(ShaderIds.VertexCache))
            {
                props.SetBuffer(ShaderIds.VertexCache, records);
                _boundRecords = records;
            }
            bool changed = count != CacheRecords;
            CacheRecords = count;
            return changed;
        }

        /// <summary>Whether the vertex cache's kernels run with the factor kernels; warns once a reason, naming it.</summary>
        bool CacheRuns(GregoryTerrainRenderer r)
        {
            string reason = _slotsKernel < 0 ? "the Cache Shader has no kernels LodVertexSlots and LodCacheVertices that this device runs"
                          : !SystemInfo.supportsAsyncGPUReadback ? "this device has no buffer readback (SystemInfo.supportsAsyncGPUReadback = false)" : null;
            if (reason != null && reason != _cacheOffReason)
                Debug.LogWarning($"{r.name}: the Horizon levels' vertex cache does not run ({reason}); the domain stage evaluates the vertices instead (slower).", r);
            _cacheOffReason = reason;
            return reason == null;
        }

        /// <summary>The camera's records buffer, made again when a frame needed more (or snow changes the record).</summary>
        void EnsureRecords(CameraFactors f, FrameState state, bool snow, int tiles)
        {
            int uint4s = VertexCache.Uint4sPerRecord(snow);
            int limit = VertexCache.FactorLimit(state.parameters.tess);
            int capacity = f.records == null ? LevelVertexCache.FirstRecords(LodLevels.DrawnTileCount(state.levelCount, tiles), limit)
                                             : LevelVertexCache.GrownRecords(f.needed, f.capacity);
            // Past what a device binds or allocates, tiles draw through the domain stage.
            capacity = System.Math.Min(capacity, LevelVertexCache.RecordLimit(uint4s * GpuLayout.Uint4Stride, SystemInfo.maxGraphicsBufferSize));
            if (f.records != null && capacity == f.capacity && uint4s == f.uint4s) return;
            ReleaseRecords(f);
            f.records = new GraphicsBuffer(GraphicsBuffer.Target.Structured, capacity * uint4s, GpuLayout.Uint4Stride);
            f.capacity = capacity;
            f.uint4s = uint4s;
        }

        /// <summary>Why the kernels cannot run, naming the device flag or the asset, or null.</summary>
        string UnavailableReason(ComputeShader shader)
        {
            if (!SystemInfo.supportsComputeShaders) return "this device has no compute shaders (SystemInfo.supportsComputeShaders = false)";
            if (shader == null) return "no compute shader is assigned to Cache Shader (Shaders/Cache/TerrainCache.compute)";
            if (!FindKernels(shader)) return "the Cache Shader has no kernels LodFactorPieces and LodFactorSeams that this device runs";
            return null;
        }

        bool FindKernels(ComputeShader shader)
        {
            if (shader == _kernelShader) return _piecesKernel >= 0;
            _kernelShader = shader;
            _piecesKernel = FindKernel(shader, ShaderIds.LodFactorPiecesKernel);
            _seamsKernel = FindKernel(shader, ShaderIds.LodFactorSeamsKernel);
            if (_piecesKernel < 0 || _seamsKernel < 0) _piecesKernel = _seamsKernel = -1;
            // The vertex cache's kernels only with the factor kernels, whose records they read.
            _slotsKernel = _piecesKernel >= 0 ? FindKernel(shader, ShaderIds.LodVertexSlotsKernel) : -1;
            _verticesKernel = _slotsKernel >= 0 ? FindKernel(shader, ShaderIds.LodCacheVerticesKernel) : -1;
            if (_verticesKernel < 0) _slotsKernel = -1;
            return _piecesKernel >= 0;
        }

        // A kernel that did not compile for this platform is found but cannot dispatch: -1 then.
        static int FindKernel(ComputeShader shader, string name)
        {
            if (!shader.HasKernel(name)) return -1;
            int kernel = shader.FindKernel(name);
            return shader.IsSupported(kernel) ? kernel : -1;
        }

        /// <summary>The camera's buffer, made again only when the level layout's size changes.</summary>
        CameraFactors FactorsOf(Camera cam, int patches)
        {
            if (_unused != null) { if (_unused == _bound) _bound = null; _unused.Release(); _unused = null; }
            int id = cam.GetInstanceID();
            if (!_byCamera.TryGetValue(id, out CameraFactors f))
            {
                EvictCameras(idleToo: _byCamera.Count >= CameraRangeOrigins.MaxCameras);
                _byCamera.Add(id, f = new CameraFactors { camera = cam });
            }
            f.frame = Time.frameCount;
            if (f.buffer != null && f.patches == patches) return f;
            f.buffer?.Release();
            f.buffer = new GraphicsBuffer(GraphicsBuffer.Target.Structured, patches, LodFactorRecord.Stride);
            f.patches = patches;
            return f;
        }

        void Bind(MaterialPropertyBlock props, GraphicsBuffer buffer)
        {
            if (buffer == _bound && props.HasBuffer(ShaderIds.LodFactors)) return;
            props.SetBuffer(ShaderIds.LodFactors, buffer);
            _bound = buffer;
        }

        // What the hull would read (the params, levels, the camera's object-to-clip and pixels, the effects) and the cache's world-to-object.
        void Dispatch(GregoryTerrainRenderer r, Camera cam, FrameState state, TerrainGpuBuffers gpu, int tiles, CameraFactors f)
        {
            ComputeShader shader = _kernelShader;
            ShaderIds.SetParams(shader, state.parameters);
            shader.SetVector(ShaderIds.LodLevels, new Vector4(state.levelCount, 1f, 0f, 0f));
            for (int k = 0; k < state.levelCount; k++) _ranges[k] = UnityConversions.ToVector(state.levelVectors[k]);
            shader.SetVectorArray(ShaderIds.Ranges, _ranges);
            shader.SetMatrix(ShaderIds.LodObjectToClip, UnityConversions.ObjectToClip(cam, state.objectToWorld));
            shader.SetMatrix(ShaderIds.WorldToObject, UnityConversions.ToMatrix4x4(state.worldToObject));   // the cached normals' transform
            int w = cam.pixelWidth, h = cam.pixelHeight;
            shader.SetVector(ShaderIds.LodScreenSize, new Vector4(w, h, 1f / w, 1f / h));
            SnowSimulator snow = r.SnowOn() ? r.SnowSimulator : null;
            VertexCachePass.SetEffectKeywords(shader, VertexCachePass.EffectsOf(r.Material, gpu, snow != null));
            if (snow != null) shader.SetVector(ShaderIds.SnowMapSize, snow.MapSize);
            BindBuffers(shader, _piecesKernel, gpu, snow, f.buffer);
            BindBuffers(shader, _seamsKernel, gpu, snow, f.buffer);
            if (_slotsKernel >= 0)
            {
                shader.SetBuffer(_slotsKernel, ShaderIds.LodFactorsRW, f.buffer);   // the scan reads and writes the records only
                BindBuffers(shader, _verticesKernel, gpu, snow, null);                // reads them through _LodFactors (DispatchCache)
            }
            // A group a draw patch (M^2 x L: no axis above 65,535), then a thread a draw patch.
            shader.Dispatch(_piecesKernel, LodTiles.TilesPerLevel(tiles), state.levelCount, 1);
            shader.Dispatch(_seamsKernel, (f.patches + 63) / 64, 1, 1);
        }

        // After the factor kernels, on the same parameters (dispatches run in the order issued).
        void DispatchCache(FrameState state, int tiles, CameraFactors f)
        {
            ComputeShader shader = _kernelShader;
            shader.SetVector(ShaderIds.LodLevels, new Vector4(state.levelCount, 1f, f.capacity, 0f));
            shader.SetBuffer(_verticesKernel, ShaderIds.LodFactors, f.buffer);
            shader.SetBuffer(_verticesKernel, ShaderIds.VertexCacheRW, f.records);
            shader.Dispatch(_slotsKernel, 1, 1, 1);
            int groups = VertexCache.GroupsPerTile(VertexCache.FactorLimit(state.parameters.tess));
            shader.Dispatch(_verticesKernel, LodTiles.TilesPerLevel(tiles), state.levelCount, groups);
            if (f.reading) return;
            f.reading = true;
            AsyncGPUReadback.Request(f.buffer, LodFactorRecord.Stride, 0, f.onRead ??= f.Read);
        }

        void BindBuffers(ComputeShader shader, int kernel, TerrainGpuBuffers gpu, SnowSimulator snow, GraphicsBuffer factors)
        {
            shader.SetBuffer(kernel, ShaderIds.ControlPoints, gpu.ControlPoints);
            shader.SetBuffer(kernel, ShaderIds.Regions, gpu.Regions);
            shader.SetBuffer(kernel, ShaderIds.GridLines, gpu.GridLines);
            if (snow != null) shader.SetBuffer(kernel, ShaderIds.SnowDepth, snow.DepthBuffer);
            if (gpu.NoiseCells != null) shader.SetBuffer(kernel, ShaderIds.NoiseCells, gpu.NoiseCells);
            if (factors != null) shader.SetBuffer(kernel, ShaderIds.LodFactorsRW, factors);
        }

        /// <summary>Releases every buffer. Safe to call twice.</summary>
        public void Release()
        {
            ReleaseCameraBuffers();
            if (_unused == _bound) _bound = null;
            _unused?.Release();
            _unused = null;
            if (_noRecords == _boundRecords) _boundRecords = null;
            _noRecords?.Release();
            _noRecords = null;
            CacheRecords = 0;
        }

        // When a camera is added: the buffers of destroyed cameras (records up to 128 MiB each), and at the
        // camera limit those of cameras not drawn this frame too. A buffer a camera drew with this frame may
        // still be read by a draw HDRP has not executed yet, so those stay.
        void EvictCameras(bool idleToo)
        {
            _evicted.Clear();
            foreach (KeyValuePair<int, CameraFactors> e in _byCamera)
                if (e.Value.camera == null || (idleToo && e.Value.frame != Time.frameCount)) _evicted.Add(e.Key);
            foreach (int id in _evicted)
            {
                ReleaseCamera(_byCamera[id]);
                _byCamera.Remove(id);
            }
        }

        void ReleaseCameraBuffers()
        {
            if (_byCamera.Count == 0) return;
            foreach (CameraFactors f in _byCamera.Values) ReleaseCamera(f);
            _byCamera.Clear();
        }

        void ReleaseCamera(CameraFactors f)
        {
            if (f.buffer == _bound) _bound = null;
            f.buffer?.Release();
            ReleaseRecords(f);
        }

        // A released buffer is never named again by the property block's memo (a new one may reuse nothing of it).
        void ReleaseRecords(CameraFactors f)
        {
            if (f.records != null && f.records == _boundRecords) _boundRecords = null;
            f.records?.Release();
        }
    }
}
