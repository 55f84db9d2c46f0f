using System;

namespace GregoryTerrain
{
    /// <summary>A grid asset's version (Unity's instance ID and <c>PatchGridAsset.Version</c>; 0: none).</summary>
    internal readonly struct GridVersionKey : IEquatable<GridVersionKey>
    {
        public readonly int grid, version;

        public GridVersionKey(int grid, int version) => (this.grid, this.version) = (grid, version);

        public bool Equals(GridVersionKey o) => grid == o.grid && version == o.version;
    }

    /// <summary>What Unity picks the SubShader by besides the device, as instance IDs and LODs.</summary>
    internal readonly struct DrawModeKey : IEquatable<DrawModeKey>
    {
        readonly int _material, _shader, _globalLod, _shaderLod, _pipeline;

        public DrawModeKey(int material, int shader, int globalLod, int shaderLod, int pipeline) =>
            (_material, _shader, _globalLod, _shaderLod, _pipeline) = (material, shader, globalLod, shaderLod, pipeline);

        public bool Equals(DrawModeKey o) => _material == o._material && _shader == o._shader
            && _globalLod == o._globalLod && _shaderLod == o._shaderLod && _pipeline == o._pipeline;
    }

    /// <summary>A material asset as the draw material's copy was made from it: instance ID, content CRC, package keyword bits.</summary>
    internal readonly struct MaterialSourceKey : IEquatable<MaterialSourceKey>
    {
        public readonly int material, crc, keywords;

        public MaterialSourceKey(int material, int crc, int keywords) => (this.material, this.crc, this.keywords) = (material, crc, keywords);

        public bool Equals(MaterialSourceKey o) => material == o.material && crc == o.crc && keywords == o.keywords;
    }

    /// <summary>What the grid upload should do this frame.</summary>
    internal enum UploadAction { Keep, Upload, Skip }

    /// <summary>
    /// What a renderer's GPU objects and its draw material were last made from, and the rules that say
    /// when to make them again. The renderer only executes the answers (FrameResourcesTests).
    /// </summary>
    internal sealed class FrameResources
    {
        GridVersionKey _uploaded, _failed;   // _failed: not tried again (nor logged) until its version changes
        int _fallbackFactor;                 // F of the fallback's index grid; 0: none made
        DrawModeKey _drawMode;
        bool _drawFallback;
        MaterialSourceKey _copiedFrom;
        int _materialCheckedFrame = -1;
        (int tiles, int limit, bool snow, long deviceLimit) _cacheCheckedFor;
        string _cacheFallbackReason;

        /// <summary>The grid in the buffers, for an upload of the patches edited since.</summary>
        public GridVersionKey HeldGrid => _uploaded;

        /// <summary>The vertex cache's size check verdict (<c>vertexEvaluation = ComputeCache: ...</c>), or null.</summary>
        public string CacheError { get; private set; }

        /// <summary>Why the Compute cache is not used now, or null.</summary>
        public string CacheFallbackReason => _cacheFallbackReason;

        public UploadAction Upload(GridVersionKey grid, bool buffersHeld)
        {
            if (buffersHeld && grid.Equals(_uploaded)) return UploadAction.Keep;
            return grid.Equals(_failed) ? UploadAction.Skip : UploadAction.Upload;
        }

        public void Uploaded(GridVersionKey grid) => (_uploaded, _failed) = (grid, default);

        public void UploadFailed(GridVersionKey grid) => _failed = grid;

        /// <summary>The buffers freed: the grid is uploaded again and the SubShader's tag read again; a failure stays remembered.</summary>
        public void Released()
        {
            _uploaded = default;
            _fallbackFactor = 0;
            _drawMode = default;
        }

        /// <summary>True when the fallback's index grid must be built for <paramref name="factor"/>; it is then taken as built.</summary>
        public bool RebuildFallbackIndices(int factor, bool held)
        {
            if (held && _fallbackFactor == factor) return false;
            _fallbackFactor = factor;
            return true;
        }

        /// <summary>The draw mode read for <paramref name="key"/>, if it was (the tag read allocates).</summary>
        public bool TryDrawMode(in DrawModeKey key, out bool fallback)
        {
            fallback = _drawFallback;
            return key.Equals(_drawMode);   // a real key names a material: never default
        }

        public void DrawModeRead(in DrawModeKey key, bool fallback) => (_drawMode, _drawFallback) = (key, fallback);

        /// <summary>The last draw mode read (the estimate and the bounds, between draws).</summary>
        public bool LastDrawFallback => _drawFallback;

        /// <summary>In play mode (<paramref name="frame"/> &gt;= 0) the asset is compared once a frame, not once a camera.</summary>
        public bool MaterialComparedThisFrame(int material, int frame) =>
            frame >= 0 && _materialCheckedFrame == frame && _copiedFrom.material == material;

        /// <summary>Compares the asset now; true when the copy must take its shader, properties and keywords again.</summary>
        public bool CopyStale(in MaterialSourceKey asset, int frame)
        {
            _materialCheckedFrame = frame;
            return !asset.Equals(_copiedFrom);
        }

        public void Copied(in MaterialSourceKey asset) => _copiedFrom = asset;

        /// <summary>The copy destroyed: the next one is made afresh.</summary>
        public void CopyReleased() => (_copiedFrom, _materialCheckedFrame) = (default, -1);

        /// <summary>
        /// The vertex cache's size check, made again only when M, the factor limit, snow or the
        /// device's limit changed. <paramref name="fresh"/>: the verdict is new (to log once).
        /// </summary>
        public string CheckCacheFits(int tiles, int limit, bool snow, long deviceLimit, out bool fresh)
        {
            var key = (tiles, limit, snow, deviceLimit);
            fresh = !key.Equals(_cacheCheckedFor);
            if (!fresh) return CacheError;
            _cacheCheckedFor = key;
            CacheError = null;
            try { VertexCacheBudget.CheckFits(tiles, limit, snow, deviceLimit > 0 ? deviceLimit : GpuLayout.MaxBufferBytes); }
            catch (ArgumentException e) { CacheError = $"vertexEvaluation = ComputeCache: {e.Message}"; }
            return CacheError;
        }

        /// <summary>The cache not used (for <paramref name="reason"/>, or chosen off): the size check forgotten. True when the reason is new (to log once).</summary>
        public bool CacheNotUsed(string reason)
        {
            (CacheError, _cacheCheckedFor) = (null, default);
            bool fresh = reason != null && reason != _cacheFallbackReason;
            _cacheFallbackReason = reason;
            return fresh;
        }

        /// <summary>The cache runs: no fallback reason.</summary>
        public void CacheUsed() => _cacheFallbackReason = null;
    }
}
