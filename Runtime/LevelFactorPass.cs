using UnityEngine;

namespace GregoryTerrain
{
    /// <summary>
    /// The Horizon levels' factor kernels of TerrainCache.compute, dispatched per camera before the
    /// levels' draw, every frame, where they run; else the hull computes the factors (internals.md,
    /// "Levels of detail"). Without levels: no dispatch, no buffer.
    /// </summary>
    sealed class LevelFactorPass
    {
        GraphicsBuffer _factors;   // LodTiles.FactorFloat4sPerPatch float4 a draw patch, sized on a level-layout change
        int _patches;
        ComputeShader _kernelShader;
        int _piecesKernel = -1, _seamsKernel = -1;
        readonly Vector4[] _ranges = new Vector4[LodTiles.MaxLevels];   // SetVectorArray's copy of the plan's levels

        public const string PiecesKernel = "LodFactorPieces", SeamsKernel = "LodFactorSeams";

        /// <summary>GPU memory held now (0 when released).</summary>
        public long AllocatedBytes => _factors != null ? (long)_patches * LodTiles.FactorFloat4sPerPatch * GpuLayout.Float4Stride : 0;

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
                Release();
                return was;
            }
            keys.LevelKernelsUsed();
            int tiles = r.Tiles, patches = state.levelCount * LodTiles.TilesPerLevel(tiles);
            if (EnsureBuffer(patches) || !props.HasBuffer(ShaderIds.LodFactors)) props.SetBuffer(ShaderIds.LodFactors, _factors);
            Dispatch(r, cam, state, gpu, tiles);
            return !was;
        }

        /// <summary>Why the kernels cannot run, naming the device flag or the asset, or null.</summary>
        string UnavailableReason(ComputeShader shader)
        {
            if (!SystemInfo.supportsComputeShaders) return "this device has no compute shaders (SystemInfo.supportsComputeShaders = false)";
            if (shader == null) return "no compute shader is assigned to Cache Shader (Shaders/Cache/TerrainCache.compute)";
            if (!FindKernels(shader)) return "the Cache Shader has no kernels LodFactorPieces and LodFactorSeams";
            return null;
        }

        bool FindKernels(ComputeShader shader)
        {
            if (shader == _kernelShader) return _piecesKernel >= 0;
            _kernelShader = shader;
            bool found = shader.HasKernel(PiecesKernel) && shader.HasKernel(SeamsKernel);
            _piecesKernel = found ? shader.FindKernel(PiecesKernel) : -1;
            _seamsKernel = found ? shader.FindKernel(SeamsKernel) : -1;
            return found;
        }

        /// <summary>Made again only when the level layout's size changes; true when made.</summary>
        bool EnsureBuffer(int patches)
        {
            if (_factors != null && patches == _patches) return false;
            Release();
            _factors = new GraphicsBuffer(GraphicsBuffer.Target.Structured, patches * LodTiles.FactorFloat4sPerPatch, GpuLayout.Float4Stride);
            _patches = patches;
            return true;
        }

        // What the hull would read: the params, levels, the camera's object-to-clip and pixels, the effects.
        void Dispatch(GregoryTerrainRenderer r, Camera cam, FrameState state, TerrainGpuBuffers gpu, int tiles)
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
            BindBuffers(shader, _piecesKernel, gpu, snow);
            BindBuffers(shader, _seamsKernel, gpu, snow);
            // A group a draw patch (M^2 x L: no axis above 65,535), then a thread a draw patch.
            shader.Dispatch(_piecesKernel, LodTiles.TilesPerLevel(tiles), state.levelCount, 1);
            shader.Dispatch(_seamsKernel, (_patches + 63) / 64, 1, 1);
        }

        void BindBuffers(ComputeShader shader, int kernel, TerrainGpuBuffers gpu, SnowSimulator snow)
        {
            shader.SetBuffer(kernel, ShaderIds.ControlPoints, gpu.ControlPoints);
            shader.SetBuffer(kernel, ShaderIds.Regions, gpu.Regions);
            shader.SetBuffer(kernel, ShaderIds.GridLines, gpu.GridLines);
            if (snow != null) shader.SetBuffer(kernel, ShaderIds.SnowDepth, snow.DepthBuffer);
            if (gpu.NoiseCells != null) shader.SetBuffer(kernel, ShaderIds.NoiseCells, gpu.NoiseCells);
            shader.SetBuffer(kernel, ShaderIds.LodFactorsRW, _factors);
        }

        /// <summary>Releases the buffer. Safe to call twice.</summary>
        public void Release()
        {
            _factors?.Release();
            _factors = null;
            _patches = 0;
        }
    }
}
