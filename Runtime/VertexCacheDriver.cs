using UnityEngine;

namespace GregoryTerrain
{
    /// <summary>
    /// The renderer's frame of <see cref="VertexEvaluation.ComputeCache"/>, after the constants: whether
    /// the pass runs (else the domain stage draws, buffers released), the size check before touching
    /// anything, buffers made when M, L or snow changed, a dispatch when the pass's inputs changed
    /// (<see cref="VertexCachePass.Update"/>). Its verdicts are Core's (<see cref="FrameResources"/>:
    /// the size check, the fallback reason, whether the draw reads the cache).
    /// </summary>
    sealed class VertexCacheDriver
    {
        /// <summary>What one frame of the cache reads from the renderer.</summary>
        public struct Inputs
        {
            /// <summary>Compute cache chosen and one range drawn (the levels draw through the domain stage).</summary>
            public bool chosen;
            public bool fallback;
            public ComputeShader shader;
            public Camera lodCamera;
            public Material material;
            /// <summary>The attached simulator while it holds a depth map, else null.</summary>
            public SnowSimulator snow;
            public int tilesAcross;
            public int gridStamp;
            public TerrainParams parameters;
            public Float4x4 objectToWorld, worldToObject;
            public TerrainGpuBuffers gpu;
        }

        readonly VertexCachePass _pass = new VertexCachePass();

        public long AllocatedBytes => _pass.AllocatedBytes;

        /// <summary>Another cache shader: its kernels are looked up and dispatched again.</summary>
        public void Invalidate() => _pass.Invalidate();

        public void Release() => _pass.Release();

        /// <summary>
        /// This frame's part of the cache. False when nothing may be drawn: the size check failed (logged
        /// once, the renderer's SettingsError; the old buffers kept), or the cache was never filled (an LOD
        /// camera without pixels). <paramref name="keys"/>.UsesCache says whether the draw reads it.
        /// </summary>
        public bool Update(in Inputs f, FrameResources keys, MaterialPropertyBlock props, Object context)
        {
            if (!f.chosen)
            {
                keys.CacheNotUsed(null);
                Stop();
                return true;
            }
            string reason = UnavailableReason(f);
            if (reason != null)
            {
                if (keys.CacheNotUsed(reason))
                    Debug.LogWarning($"{context.name}: Vertex evaluation is Compute cache, but {reason}; evaluating in the domain stage instead.", context);
                Stop();
                return true;
            }
            keys.CacheUsed();

            bool snow = f.snow != null;
            int limit = VertexCache.FactorLimit(f.parameters.tess);
            string error = keys.CheckCacheFits(f.tilesAcross, limit, snow, SystemInfo.maxGraphicsBufferSize, out bool fresh);
            if (error != null)
            {
                if (fresh) Debug.LogError($"{context.name}: cannot draw with these settings: {error}", context);
                return false;
            }

            _pass.EnsureBuffers(f.tilesAcross, limit, snow);
            Camera cam = f.lodCamera;
            int w = cam.pixelWidth, h = cam.pixelHeight;
            if (w > 0 && h > 0)
            {
                var inputs = new VertexCachePass.Inputs
                {
                    parameters = f.parameters,
                    objectToClip = UnityConversions.ObjectToClip(cam, f.objectToWorld),
                    worldToObject = UnityConversions.ToMatrix4x4(f.worldToObject),
                    screenSize = new Vector4(w, h, 1f / w, 1f / h),
                    controlPoints = f.gpu.ControlPoints, regions = f.gpu.Regions, gridLines = f.gpu.GridLines,
                    gridStamp = f.gridStamp,
                    effects = Effects(f),
                    noiseCells = f.gpu.NoiseCells,
                    snowDepth = snow ? f.snow.DepthBuffer : null,
                    snowMapSize = snow ? f.snow.MapSize : default,
                    snowVersion = snow ? f.snow.DepthVersion : 0,
                };
                if (_pass.Update(f.shader, inputs)) _pass.BindTo(props);
            }
            return keys.CacheFilled(_pass.HasContent);   // false: nothing evaluated yet (a camera without pixels)
        }

        /// <summary>Why the compute cache cannot run, naming the setting or device flag, or null.</summary>
        string UnavailableReason(in Inputs f)
        {
            if (f.fallback)
                return "the material draws its no-tessellator fallback SubShader (there is no domain stage to feed)";
            if (!SystemInfo.supportsComputeShaders)
                return "this device has no compute shaders (SystemInfo.supportsComputeShaders = false)";
            if (f.shader == null)
                return "no compute shader is assigned to Cache Shader (Shaders/Cache/TerrainCache.compute)";
            if (!_pass.FindKernels(f.shader, out string missing))
                return $"the Cache Shader '{f.shader.name}' has no kernel '{missing}'";
            if (f.lodCamera == null)
                return "there is no LOD camera (LOD Camera is empty and no camera is tagged MainCamera)";
            return null;
        }

        static VertexCachePass.Effects Effects(in Inputs f)
        {
            var e = VertexCachePass.Effects.None;
            if (f.material.IsKeywordEnabled(ShaderIds.NoiseKeyword)) e |= VertexCachePass.Effects.Noise;
            if (f.material.IsKeywordEnabled(ShaderIds.HeightColorKeyword)) e |= VertexCachePass.Effects.HeightColor;
            if (f.gpu.NoiseCells != null) e |= VertexCachePass.Effects.NoiseTable;   // made by the noise table's binding while the noise is tiled
            if (f.snow != null) e |= VertexCachePass.Effects.Snow;
            return e;
        }

        /// <summary>The domain stage draws: the cache's memory given back (the draw material drops GT_VERTEX_CACHE).</summary>
        void Stop()
        {
            if (_pass.IsAllocated) _pass.Release();
        }
    }
}
