using System.Collections.Generic;
using UnityEngine;

namespace GregoryTerrain
{
    /// <summary>
    /// The Horizon levels' factor kernels of TerrainCache.compute, dispatched per camera before the
    /// levels' draw, every frame, where they run; else the hull computes the factors (internals.md,
    /// "Levels of detail"). Without levels: no dispatch, no buffer. A buffer per camera: HDRP raises
    /// every camera's callback before it executes any camera's draws, so one shared buffer would hold
    /// the last camera's factors when the first one draws.
    /// </summary>
    sealed class LevelFactorPass
    {
        sealed class CameraFactors
        {
            public Camera camera;
            public GraphicsBuffer buffer;   // a LodFactorRecord a draw patch, sized on a level-layout change
            public int patches, frame;      // frame: Time.frameCount when last dispatched
        }

        readonly Dictionary<int, CameraFactors> _byCamera = new Dictionary<int, CameraFactors>();
        readonly List<int> _evicted = new List<int>();
        GraphicsBuffer _bound;     // what the property block's _LodFactors names now
        GraphicsBuffer _unused;    // one record bound while the hull computes the factors: every declared buffer is bound (Metal)
        ComputeShader _kernelShader;
        int _piecesKernel = -1, _seamsKernel = -1;
        readonly Vector4[] _ranges = new Vector4[LodTiles.MaxLevels];   // SetVectorArray's copy of the plan's levels

        /// <summary>GPU memory held now (0 when released).</summary>
        public long AllocatedBytes
        {
            get
            {
                long records = _unused != null ? 1 : 0;
                foreach (CameraFactors f in _byCamera.Values) records += f.patches;
                return records * LodFactorRecord.Stride;
            }
        }

        /// <summary>A camera's frame, after the plan: dispatches or stops. True when the hull's switch changed (<c>_LodLevels</c> to send).</summary>
        public bool UpdateFrame(GregoryTerrainRenderer r, Camera cam, bool fallback, FrameState state, TerrainGpuBuffers gpu, MaterialPropertyBlock props)
        {
            if (cam == null || cam.pixelWidth <= 0 || cam.pixelHeight <= 0) return false;   // draws nothing
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
                return was;
            }
            keys.LevelKernelsUsed();
            int tiles = r.Tiles, patches = state.levelCount * LodTiles.TilesPerLevel(tiles);
            CameraFactors f = FactorsOf(cam, patches);
            Bind(props, f.buffer);
            Dispatch(r, cam, state, gpu, tiles, f);
            return !was;
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
            bool found = shader.HasKernel(ShaderIds.LodFactorPiecesKernel) && shader.HasKernel(ShaderIds.LodFactorSeamsKernel);
            _piecesKernel = found ? shader.FindKernel(ShaderIds.LodFactorPiecesKernel) : -1;
            _seamsKernel = found ? shader.FindKernel(ShaderIds.LodFactorSeamsKernel) : -1;
            // A kernel that did not compile for this platform is found but cannot dispatch.
            if (found && !(shader.IsSupported(_piecesKernel) && shader.IsSupported(_seamsKernel))) _piecesKernel = _seamsKernel = -1;
            return _piecesKernel >= 0;
        }

        /// <summary>The camera's buffer, made again only when the level layout's size changes.</summary>
        CameraFactors FactorsOf(Camera cam, int patches)
        {
            if (_unused != null) { if (_unused == _bound) _bound = null; _unused.Release(); _unused = null; }
            int id = cam.GetInstanceID();
            if (!_byCamera.TryGetValue(id, out CameraFactors f))
            {
                if (_byCamera.Count >= CameraRangeOrigins.MaxCameras) EvictIdle();
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

        // What the hull would read: the params, levels, the camera's object-to-clip and pixels, the effects.
        void Dispatch(GregoryTerrainRenderer r, Camera cam, FrameState state, TerrainGpuBuffers gpu, int tiles, CameraFactors f)
        {
            ComputeShader shader = _kernelShader;
            ShaderIds.SetParams(shader, state.parameters);
            shader.SetVector(ShaderIds.LodLevels, new Vector4(state.levelCount, 1f, 0f, 0f));
            for (int k = 0; k < state.levelCount; k++) _ranges[k] = UnityConversions.ToVector(state.levelVectors[k]);
            shader.SetVectorArray(ShaderIds.Ranges, _ranges);
            shader.SetMatrix(ShaderIds.LodObjectToClip, UnityConversions.ObjectToClip(cam, state.objectToWorld));
            int w = cam.pixelWidth, h = cam.pixelHeight;
            shader.SetVector(ShaderIds.LodScreenSize, new Vector4(w, h, 1f / w, 1f / h));
            SnowSimulator snow = r.SnowOn() ? r.SnowSimulator : null;
            VertexCachePass.SetEffectKeywords(shader, VertexCachePass.EffectsOf(r.Material, gpu, snow != null));
            if (snow != null) shader.SetVector(ShaderIds.SnowMapSize, snow.MapSize);
            BindBuffers(shader, _piecesKernel, gpu, snow, f.buffer);
            BindBuffers(shader, _seamsKernel, gpu, snow, f.buffer);
            // A group a draw patch (M^2 x L: no axis above 65,535), then a thread a draw patch.
            shader.Dispatch(_piecesKernel, LodTiles.TilesPerLevel(tiles), state.levelCount, 1);
            shader.Dispatch(_seamsKernel, (f.patches + 63) / 64, 1, 1);
        }

        void BindBuffers(ComputeShader shader, int kernel, TerrainGpuBuffers gpu, SnowSimulator snow, GraphicsBuffer factors)
        {
            shader.SetBuffer(kernel, ShaderIds.ControlPoints, gpu.ControlPoints);
            shader.SetBuffer(kernel, ShaderIds.Regions, gpu.Regions);
            shader.SetBuffer(kernel, ShaderIds.GridLines, gpu.GridLines);
            if (snow != null) shader.SetBuffer(kernel, ShaderIds.SnowDepth, snow.DepthBuffer);
            if (gpu.NoiseCells != null) shader.SetBuffer(kernel, ShaderIds.NoiseCells, gpu.NoiseCells);
            shader.SetBuffer(kernel, ShaderIds.LodFactorsRW, factors);
        }

        /// <summary>Releases every buffer. Safe to call twice.</summary>
        public void Release()
        {
            ReleaseCameraBuffers();
            if (_unused == _bound) _bound = null;
            _unused?.Release();
            _unused = null;
        }

        // Buffers of destroyed cameras and of cameras not drawn this frame: a buffer a camera drew with
        // this frame may still be read by a draw HDRP has not executed yet, so those stay.
        void EvictIdle()
        {
            _evicted.Clear();
            foreach (KeyValuePair<int, CameraFactors> e in _byCamera)
                if (e.Value.camera == null || e.Value.frame != Time.frameCount) _evicted.Add(e.Key);
            foreach (int id in _evicted)
            {
                CameraFactors f = _byCamera[id];
                if (f.buffer == _bound) _bound = null;
                f.buffer?.Release();
                _byCamera.Remove(id);
            }
        }

        void ReleaseCameraBuffers()
        {
            if (_byCamera.Count == 0) return;
            foreach (CameraFactors f in _byCamera.Values)
            {
                if (f.buffer == _bound) _bound = null;
                f.buffer?.Release();
            }
            _byCamera.Clear();
        }
    }
}
