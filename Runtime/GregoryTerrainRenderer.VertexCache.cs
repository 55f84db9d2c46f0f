using System;
using UnityEngine;

namespace GregoryTerrain
{
    // Vertex evaluation = Compute cache: when the cache runs and its size check. Its keyword,
    // GT_VERTEX_CACHE, is the draw material's (.DrawMaterial.cs), never the asset's.
    // The pass itself (buffers, dispatch, what changed) is VertexCachePass.
    public sealed partial class GregoryTerrainRenderer
    {
        readonly VertexCachePass _cache = new VertexCachePass();
        string _cacheError;                              // the size check's message (not drawn until fixed)
        (int tiles, int limit, bool snow, long deviceLimit) _cacheCheckedFor;   // what _cacheError is the verdict on
        string _cacheFallbackReason;                     // why Compute cache is not used now, logged once per reason
        bool _usesCache;

        /// <summary>
        /// This frame's part of the compute cache, after the constants are current. Decides whether
        /// the cache runs (else the domain stage draws: GT_VERTEX_CACHE off, buffers released), checks
        /// the buffer sizes before touching anything, (re)allocates only when M, L or snow changed, and
        /// dispatches only when the pass's inputs changed (<see cref="VertexCachePass.Update"/>).
        /// Returns false when nothing may be drawn this frame: the size check failed (logged once,
        /// <see cref="SettingsError"/>; the old buffers, bindings and keyword are left as they were),
        /// or the cache has never been filled and the LOD camera has no pixels yet.
        /// </summary>
        bool UpdateVertexCache(bool fallback)
        {
            _usesCache = false;
            // The levels draw through the domain stage (the cache holds one range's tiles).
            if (vertexEvaluation != VertexEvaluation.ComputeCache || LevelsOn(fallback))
            {
                _cacheFallbackReason = null;
                ClearCacheCheck();
                StopCache();
                return true;
            }
            bool snow = SnowOn();
            Camera cam = EffectiveLodCamera;
            SnowSimulator snowSource = snow ? _snow : null;
            string reason = CacheUnavailableReason(fallback, cam, snow, snowSource);
            if (reason != null)
            {
                if (reason != _cacheFallbackReason)
                    Debug.LogWarning($"{name}: Vertex evaluation is Compute cache, but {reason}; evaluating in the domain stage instead.", this);
                _cacheFallbackReason = reason;
                ClearCacheCheck();
                StopCache();
                return true;
            }
            _cacheFallbackReason = null;

            int limit = VertexCache.FactorLimit(_params.tess);
            if (!CacheFits(limit, snow)) return false;

            _cache.EnsureBuffers(CacheTilesAcross, limit, snow);
            int w = cam.pixelWidth, h = cam.pixelHeight;
            if (w > 0 && h > 0)
            {
                var inputs = new VertexCachePass.Inputs
                {
                    parameters = _params,
                    objectToClip = ObjectToClip(cam),
                    worldToObject = _worldToObject,
                    screenSize = new Vector4(w, h, 1f / w, 1f / h),
                    controlPoints = _controlPoints, regions = _regions, gridLines = _gridLines,
                    gridStamp = _gridStamp,
                    effects = Effects(snow),
                    noiseCells = _noiseCells,
                    snowDepth = snowSource != null ? snowSource.DepthBuffer : null,
                    snowMapSize = snowSource != null ? snowSource.MapSize : default,
                    snowVersion = snowSource != null ? snowSource.DepthVersion : 0,
                };
                if (_cache.Update(cacheShader, inputs)) _cache.BindTo(_props);
            }
            if (!_cache.HasContent) return false;   // nothing evaluated yet (a camera without pixels)
            _usesCache = true;   // the draw material gets GT_VERTEX_CACHE
            return true;
        }

        /// <summary>
        /// The terrain's object -> clip transform for a camera, as the graphics stages get it
        /// (GT_ObjectToClip: UNITY_MATRIX_P with the platform's depth range and orientation). A
        /// render-texture y flip would not change a factor (screen lengths) or the culling (symmetric
        /// in y), so renderIntoTexture = false serves every target.
        /// </summary>
        Matrix4x4 ObjectToClip(Camera cam) =>
            GL.GetGPUProjectionMatrix(cam.projectionMatrix, false) * cam.worldToCameraMatrix * _objectToWorld;

        /// <summary>
        /// The size check (Core's <see cref="VertexCacheBudget.CheckFits"/>), run only when M, L, snow
        /// or the device's limit changed: a failing check would otherwise throw every frame. Logs once
        /// per failing setting; <see cref="SettingsError"/> shows it.
        /// </summary>
        bool CacheFits(int limit, bool snow)
        {
            long deviceLimit = SystemInfo.maxGraphicsBufferSize;
            int across = CacheTilesAcross;
            var key = (across, limit, snow, deviceLimit);
            if (key.Equals(_cacheCheckedFor)) return _cacheError == null;
            _cacheCheckedFor = key;
            _cacheError = null;
            try { VertexCacheBudget.CheckFits(across, limit, snow, deviceLimit > 0 ? deviceLimit : GpuLayout.MaxBufferBytes); }
            catch (ArgumentException e)
            {
                _cacheError = $"vertexEvaluation = ComputeCache: {e.Message}";
                Debug.LogError($"{name}: cannot draw with these settings: {_cacheError}", this);
            }
            return _cacheError == null;
        }

        /// <summary>Forgets the size check's verdict (the cache is not used now; checked afresh when it is).</summary>
        void ClearCacheCheck()
        {
            _cacheError = null;
            _cacheCheckedFor = default;
        }

        /// <summary>Why the compute cache cannot run this frame, or null. The message names the setting or device flag.</summary>
        string CacheUnavailableReason(bool fallback, Camera cam, bool snow, SnowSimulator snowSource)
        {
            if (fallback)
                return "the material draws its no-tessellator fallback SubShader (there is no domain stage to feed)";
            if (!SystemInfo.supportsComputeShaders)
                return "this device has no compute shaders (SystemInfo.supportsComputeShaders = false)";
            if (cacheShader == null)
                return "no compute shader is assigned to Cache Shader (Shaders/Cache/TerrainCache.compute)";
            if (!_cache.FindKernels(cacheShader, out string missing))
                return $"the Cache Shader '{cacheShader.name}' has no kernel '{missing}'";
            if (cam == null)
                return "there is no LOD camera (LOD Camera is empty and no camera is tagged MainCamera)";
            return null;
        }

        VertexCachePass.Effects Effects(bool snow)
        {
            var e = VertexCachePass.Effects.None;
            if (material.IsKeywordEnabled(ShaderIds.NoiseKeyword)) e |= VertexCachePass.Effects.Noise;
            if (material.IsKeywordEnabled(ShaderIds.HeightColorKeyword)) e |= VertexCachePass.Effects.HeightColor;
            if (_noiseCells != null) e |= VertexCachePass.Effects.NoiseTable;   // made by UpdateNoiseTableBinding while the noise is tiled
            if (snow) e |= VertexCachePass.Effects.Snow;
            return e;
        }

        /// <summary>The domain stage draws: the cache's memory given back (the draw material drops GT_VERTEX_CACHE).</summary>
        void StopCache()
        {
            if (_cache.IsAllocated) _cache.Release();
        }
    }
}
