using System;

namespace GregoryTerrain
{
    /// <summary>A grid asset (instance ID; 0: none) and its version.</summary>
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

    /// <summary>A material asset: instance ID, content CRC, package keyword bits.</summary>
    internal readonly struct MaterialSourceKey : IEquatable<MaterialSourceKey>
    {
        public readonly int material, crc, keywords;

        public MaterialSourceKey(int material, int crc, int keywords) => (this.material, this.crc, this.keywords) = (material, crc, keywords);

        public bool Equals(MaterialSourceKey o) => material == o.material && crc == o.crc && keywords == o.keywords;
    }

    /// <summary>What a surface query is built from (noise null: GT_NOISE off).</summary>
    internal readonly struct QuerySourceKey : IEquatable<QuerySourceKey>
    {
        public readonly GridVersionKey grid;
        readonly NoiseSettings? _noise;
        readonly TerrainKeywords _keywords;

        public QuerySourceKey(GridVersionKey grid, NoiseSettings? noise, TerrainKeywords keywords) => (this.grid, _noise, _keywords) = (grid, noise, keywords);

        public bool Equals(QuerySourceKey o) => grid.Equals(o.grid) && SameSurfaceRules(o);

        public bool SameSurfaceRules(in QuerySourceKey o) => grid.grid == o.grid.grid && Nullable.Equals(_noise, o._noise) && _keywords == o._keywords;
    }

    /// <summary>What the grid upload should do this frame.</summary>
    internal enum UploadAction { Keep, Upload, Skip }

    /// <summary>What a renderer's GPU objects, draw material and queries were made from, and when to make them again.</summary>
    internal sealed class FrameResources
    {
        GridVersionKey _uploaded, _failed;   // _failed: not tried again until its version changes
        int _fallbackFactor;                 // 0: none made
        DrawModeKey _drawMode;
        bool _drawFallback;
        MaterialSourceKey _copiedFrom;
        int _materialCheckedFrame = -1;
        (int tiles, int limit, bool snow, long deviceLimit) _cacheCheckedFor;
        string _cacheFallbackReason, _levelKernelsReason;
        TerrainSurfaceQuery _query;           // null after a failure too
        QuerySourceKey _queryFrom;
        TerrainInputs _estimateInputs;
        PatchGrid _estimateGrid;

        public GridVersionKey HeldGrid => _uploaded;

        /// <summary>The uploaded grid's lowest and highest control point, in terrain height units (the draw's bounds).</summary>
        public float GridMinZ { get; private set; }
        public float GridMaxZ { get; private set; }

        /// <summary>True while the draw reads the vertex cache (GT_VERTEX_CACHE): only after <see cref="CacheFilled"/> this frame.</summary>
        public bool UsesCache { get; private set; }

        /// <summary>The vertex cache's size check verdict, or null.</summary>
        public string CacheError { get; private set; }

        public string CacheFallbackReason => _cacheFallbackReason;

        /// <summary>True while the levels' hull reads the factor kernels' records (<c>_LodLevels.y</c> = 1).</summary>
        public bool UsesLevelKernels { get; private set; }

        public UploadAction Upload(GridVersionKey grid, bool buffersHeld)
        {
            if (buffersHeld && grid.Equals(_uploaded)) return UploadAction.Keep;
            return grid.Equals(_failed) ? UploadAction.Skip : UploadAction.Upload;
        }

        /// <summary>The whole grid uploaded, its height range as it is now.</summary>
        public void Uploaded(GridVersionKey grid, float minZ, float maxZ) =>
            (_uploaded, _failed, GridMinZ, GridMaxZ) = (grid, default, minZ, maxZ);

        /// <summary>Only the edited patches uploaded: the height range only widens (the bounds stay bounds; a whole upload tightens it).</summary>
        public void PatchesUploaded(GridVersionKey grid, PatchGrid g, int[] changed)
        {
            (_uploaded, _failed) = (grid, default);
            foreach (int k in changed)
                foreach (Double3 c in g.Patches[k].Points)
                {
                    GridMinZ = Math.Min(GridMinZ, (float)c.z);
                    GridMaxZ = Math.Max(GridMaxZ, (float)c.z);
                }
        }

        public void UploadFailed(GridVersionKey grid) => _failed = grid;

        /// <summary>The buffers freed: upload and read the tag again; a failure stays remembered.</summary>
        public void Released()
        {
            _uploaded = default;
            _fallbackFactor = 0;
            _drawMode = default;
            UsesCache = false;
            UsesLevelKernels = false;
            (_estimateInputs, _estimateGrid) = (null, null);   // the grid's CPU copy
        }

        /// <summary>True when the fallback's index grid must be built (then taken as built).</summary>
        public bool RebuildFallbackIndices(int factor, bool held)
        {
            if (held && _fallbackFactor == factor) return false;
            _fallbackFactor = factor;
            return true;
        }

        /// <summary>The draw mode read for key, if it was (GetTag allocates).</summary>
        public bool TryDrawMode(in DrawModeKey key, out bool fallback)
        {
            fallback = _drawFallback;
            return key.Equals(_drawMode);   // a real key names a material: never default
        }

        public void DrawModeRead(in DrawModeKey key, bool fallback) => (_drawMode, _drawFallback) = (key, fallback);

        public bool LastDrawFallback => _drawFallback;

        /// <summary>In play mode (frame &gt;= 0) the asset's CRC (every property) is computed once a frame, not once a camera.</summary>
        public bool MaterialComparedThisFrame(int material, int frame) =>
            frame >= 0 && _materialCheckedFrame == frame && _copiedFrom.material == material;

        /// <summary>True when the copy must take the asset's shader, properties and keywords again.</summary>
        public bool CopyStale(in MaterialSourceKey asset, int frame)
        {
            _materialCheckedFrame = frame;
            return !asset.Equals(_copiedFrom);
        }

        public void Copied(in MaterialSourceKey asset) => _copiedFrom = asset;

        public void CopyReleased() => (_copiedFrom, _materialCheckedFrame) = (default, -1);

        /// <summary>The cache's size check, made again when M, the factor limit, snow or the device's limit change; fresh: a new verdict (to log once).</summary>
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

        /// <summary>The cache not used (for reason, or off): the size check forgotten; true for a new reason (to log once).</summary>
        public bool CacheNotUsed(string reason)
        {
            (CacheError, _cacheCheckedFor, UsesCache) = (null, default, false);
            bool fresh = reason != null && reason != _cacheFallbackReason;
            _cacheFallbackReason = reason;
            return fresh;
        }

        /// <summary>The cache runs this frame: no reason stands, and it is not drawn until <see cref="CacheFilled"/>.</summary>
        public void CacheUsed() => (_cacheFallbackReason, UsesCache) = (null, false);

        /// <summary>The pass holds a dispatch's result (else nothing may draw: a camera without pixels); returns it.</summary>
        public bool CacheFilled(bool filled) => UsesCache = filled;

        /// <summary>The levels' factor kernels not run (for reason, or levels off: null); true for a new reason (to warn once).</summary>
        public bool LevelKernelsNotUsed(string reason)
        {
            UsesLevelKernels = false;
            bool fresh = reason != null && reason != _levelKernelsReason;
            _levelKernelsReason = reason;
            return fresh;
        }

        /// <summary>The kernels run this frame before the draw: the hull reads their records.</summary>
        public void LevelKernelsUsed() => (_levelKernelsReason, UsesLevelKernels) = (null, true);

        /// <summary>The query built for key (null: that failed), if one was.</summary>
        public bool TryQuery(in QuerySourceKey key, out TerrainSurfaceQuery query)
        {
            query = _query;
            return key.Equals(_queryFrom);
        }

        /// <summary>The query of an older version of the same grid, noise and keywords (to catch up on edits), or null.</summary>
        public TerrainSurfaceQuery QueryToCatchUp(in QuerySourceKey key, out int version)
        {
            version = _queryFrom.grid.version;
            return key.SameSurfaceRules(_queryFrom) ? _query : null;
        }

        public void QueryBuilt(in QuerySourceKey key, TerrainSurfaceQuery query) => (_queryFrom, _query) = (key, query);

        /// <summary>The uploaded grid packed for the estimate once per grid, with these constants.</summary>
        public TerrainInputs EstimateInputs(PatchGrid grid, in TerrainParams parameters)
        {
            if (_estimateGrid == grid) return _estimateInputs = _estimateInputs.WithParams(parameters);
            (_estimateInputs, _estimateGrid) = (TerrainInputs.Create(grid, parameters), grid);
            return _estimateInputs;
        }
    }
}
