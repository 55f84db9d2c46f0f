using System;
using UnityEngine;

namespace GregoryTerrain
{
    /// <summary>
    /// The compute pre-pass of <see cref="VertexEvaluation.ComputeCache"/>: owns <c>_TileFactors</c>,
    /// <c>_TileCells</c> and <c>_VertexCache</c> (sizes from Core's <see cref="VertexCacheBudget"/>) and dispatches
    /// <c>CacheTileFactors</c> then <c>CacheTileVertices</c> of <c>Shaders/Cache/TerrainCache.compute</c>
    /// only when something the kernels read differs from the last dispatch. What the kernels do not
    /// compare per tile (origin, lattice, grid, noise, colour, transform, effects, snow map, new
    /// buffers) makes this class zero the tiles' keys first, so everything is evaluated again
    /// (internals.md, "Vertex cache"). <see cref="UpdateFrame"/>: whether it runs in a renderer's frame.
    /// </summary>
    sealed class VertexCachePass
    {
        /// <summary>Effect keywords the kernels evaluate, mirrored from the material onto the compute shader.</summary>
        [Flags]
        public enum Effects { None = 0, Noise = 1, HeightColor = 2, Snow = 4, NoiseTable = 8 }

        /// <summary>Everything one dispatch reads besides the buffers this pass owns.</summary>
        public struct Inputs
        {
            public TerrainParams parameters;
            /// <summary>GPU projection * view (LOD camera) * the renderer's object matrix (deep-zoom offset included).</summary>
            public Matrix4x4 objectToClip;
            /// <summary>The renderer's world-to-object (the draw's own): the cache stores world normals.</summary>
            public Matrix4x4 worldToObject;
            /// <summary>(w, h, 1/w, 1/h) of the LOD camera in pixels.</summary>
            public Vector4 screenSize;
            public GraphicsBuffer controlPoints, regions, gridLines;
            /// <summary>Bumped by the renderer on every upload, so new grid buffers force a dispatch.</summary>
            public int gridStamp;
            public Effects effects;
            /// <summary>With <see cref="Effects.Snow"/>: the simulator's depth map, its (R, 1/R, cap, 0) and version.</summary>
            public GraphicsBuffer snowDepth;
            public Vector4 snowMapSize;
            public int snowVersion;
            /// <summary>With <see cref="Effects.NoiseTable"/>: the renderer's <c>_NoiseCells</c> (constant content: only bound, never compared).</summary>
            public GraphicsBuffer noiseCells;
        }

        GraphicsBuffer _factors, _cells, _vertices;
        int _tiles, _factorLimit;
        bool _snow;

        ComputeShader _kernelShader;
        int _factorsKernel = -1, _verticesKernel = -1;

        bool _valid;          // the buffers hold the result of _last
        Inputs _last;
        TileFactorRecord[] _zeroRecords;   // T^2 records of zero keys: "nothing evaluated yet"

        public GraphicsBuffer TileFactors => _factors;
        public GraphicsBuffer VertexCache => _vertices;
        public bool IsAllocated => _factors != null;
        /// <summary>True once a dispatch has filled the current buffers.</summary>
        public bool HasContent => _valid;
        /// <summary>GPU memory held now (0 when released).</summary>
        public long AllocatedBytes => IsAllocated ? VertexCacheBudget.TotalBytes(_tiles, _factorLimit, _snow) : 0;

        /// <summary>
        /// Looks the two kernels up in <paramref name="shader"/> (once per shader asset). False, with
        /// the missing kernel's name in <paramref name="missing"/>, when the shader lacks one.
        /// </summary>
        public bool FindKernels(ComputeShader shader, out string missing)
        {
            missing = null;
            if (shader == _kernelShader && _factorsKernel >= 0 && _verticesKernel >= 0) return true;
            _kernelShader = null; _factorsKernel = _verticesKernel = -1;
            if (!shader.HasKernel(ShaderIds.CacheFactorsKernel)) { missing = ShaderIds.CacheFactorsKernel; return false; }
            if (!shader.HasKernel(ShaderIds.CacheVerticesKernel)) { missing = ShaderIds.CacheVerticesKernel; return false; }
            _factorsKernel = shader.FindKernel(ShaderIds.CacheFactorsKernel);
            _verticesKernel = shader.FindKernel(ShaderIds.CacheVerticesKernel);
            _kernelShader = shader;
            _valid = false;   // another shader: its results are not ours
            return true;
        }

        /// <summary>
        /// A renderer's frame: runs, or stops (the domain stage draws). False when nothing may be drawn: the size
        /// check failed (logged once), or nothing evaluated yet. FrameResources.UsesCache: the draw reads it.
        /// </summary>
        public bool UpdateFrame(GregoryTerrainRenderer r, bool fallback, FrameState state, TerrainGpuBuffers gpu, int gridStamp, MaterialPropertyBlock props)
        {
            FrameResources keys = state.resources;
            // The levels have their own cache (LevelFactorPass): this one holds one range's tiles.
            if (r.VertexEvaluation != VertexEvaluation.ComputeCache || r.LevelsOn(fallback))
            {
                keys.CacheNotUsed(null);
                Stop();
                return true;
            }
            ComputeShader shader = r.CacheShader;
            Camera cam = r.EffectiveLodCamera;
            string reason = UnavailableReason(fallback, shader, cam);
            if (reason != null)
            {
                if (keys.CacheNotUsed(reason))
                    Debug.LogWarning($"{r.name}: Vertex evaluation is Compute cache, but {reason}; evaluating in the domain stage instead.", r);
                Stop();
                return true;
            }
            keys.CacheUsed();

            SnowSimulator snow = r.SnowOn() ? r.SnowSimulator : null;
            int tiles = r.CacheTilesAcross, limit = GregoryTerrain.VertexCache.FactorLimit(state.parameters.tess);
            string error = keys.CheckCacheFits(tiles, limit, snow != null, SystemInfo.maxGraphicsBufferSize, out bool fresh);
            if (error != null)
            {
                if (fresh) Debug.LogError($"{r.name}: cannot draw with these settings: {error}", r);
                return false;
            }

            EnsureBuffers(tiles, limit, snow != null);
            int w = cam.pixelWidth, h = cam.pixelHeight;
            if (w > 0 && h > 0)
            {
                var inputs = new VertexCachePass.Inputs
                {
                    parameters = state.parameters,
                    objectToClip = UnityConversions.ObjectToClip(cam, state.objectToWorld),
                    worldToObject = UnityConversions.ToMatrix4x4(state.worldToObject),
                    screenSize = new Vector4(w, h, 1f / w, 1f / h),
                    controlPoints = gpu.ControlPoints, regions = gpu.Regions, gridLines = gpu.GridLines,
                    gridStamp = gridStamp,
                    effects = EffectsOf(r.Material, gpu, snow != null),
                    noiseCells = gpu.NoiseCells,
                    snowDepth = snow != null ? snow.DepthBuffer : null,
                    snowMapSize = snow != null ? snow.MapSize : default,
                    snowVersion = snow != null ? snow.DepthVersion : 0,
                };
                if (Update(shader, inputs)) BindTo(props);
            }
            return keys.CacheFilled(HasContent);   // false: nothing evaluated yet (a camera without pixels)
        }

        /// <summary>Why the compute cache cannot run, naming the setting or device flag, or null.</summary>
        string UnavailableReason(bool fallback, ComputeShader shader, Camera cam)
        {
            if (fallback)
                return "the material draws its no-tessellator fallback SubShader (there is no domain stage to feed)";
            if (!SystemInfo.supportsComputeShaders)
                return "this device has no compute shaders (SystemInfo.supportsComputeShaders = false)";
            if (shader == null)
                return "no compute shader is assigned to Cache Shader (Shaders/Cache/TerrainCache.compute)";
            if (!FindKernels(shader, out string missing))
                return MissingKernelReason(shader, missing);
            if (cam == null)
                return "there is no LOD camera (LOD Camera is empty and no camera is tagged MainCamera)";
            return null;
        }

        // Built once per refused shader: Object.name makes a new string on every call, and this runs
        // for every camera of every frame while the setting stays wrong.
        ComputeShader _refusedShader;
        string _refusedKernel, _refusedReason;

        string MissingKernelReason(ComputeShader shader, string missing)
        {
            if (shader != _refusedShader || !ReferenceEquals(missing, _refusedKernel))
                (_refusedShader, _refusedKernel, _refusedReason) = (shader, missing, $"the Cache Shader '{shader.name}' has no kernel '{missing}'");
            return _refusedReason;
        }

        internal static Effects EffectsOf(Material material, TerrainGpuBuffers gpu, bool snow)
        {
            var e = Effects.None;
            if (material.IsKeywordEnabled(ShaderKeywords.Noise)) e |= Effects.Noise;
            if (material.IsKeywordEnabled(ShaderKeywords.HeightColor)) e |= Effects.HeightColor;
            if (gpu.NoiseCells != null) e |= Effects.NoiseTable;   // made by the noise table's binding while the noise is tiled
            if (snow) e |= Effects.Snow;
            return e;
        }

        /// <summary>The domain stage draws: the cache's memory given back (the draw material drops GT_VERTEX_CACHE).</summary>
        void Stop()
        {
            if (IsAllocated) Release();
        }
        /// <summary>
        /// Allocates the buffers for M = <paramref name="tiles"/>, L = <paramref name="factorLimit"/>
        /// and the snow record when one of them changed (call <see cref="VertexCacheBudget.CheckFits"/>
        /// first). Returns true when it allocated (the buffers must be bound again).
        /// </summary>
        public bool EnsureBuffers(int tiles, int factorLimit, bool snow)
        {
            if (IsAllocated && tiles == _tiles && factorLimit == _factorLimit && snow == _snow) return false;
            long vertexCount = VertexCacheBudget.VertexCacheUint4s(tiles, factorLimit, snow);
            Release();
            _factors = new GraphicsBuffer(GraphicsBuffer.Target.Structured, tiles * tiles, TileFactorRecord.Stride);
            _cells = new GraphicsBuffer(GraphicsBuffer.Target.Structured, tiles * tiles, TileCellRecord.Stride);
            _vertices = new GraphicsBuffer(GraphicsBuffer.Target.Structured, (int)vertexCount, GpuLayout.Uint4Stride);
            _tiles = tiles; _factorLimit = factorLimit; _snow = snow;
            _valid = false;
            return true;
        }

        /// <summary>Forgets the last dispatch: the next <see cref="Update"/> dispatches.</summary>
        public void Invalidate() => _valid = false;

        /// <summary>
        /// Dispatches both kernels when <paramref name="inputs"/> differ from the last dispatch's (or
        /// none yet); true when it did. Needs <see cref="FindKernels"/> and <see cref="EnsureBuffers"/> first.
        /// </summary>
        public bool Update(ComputeShader shader, in Inputs inputs)
        {
            if (!IsAllocated || shader != _kernelShader) throw new InvalidOperationException("VertexCachePass: FindKernels and EnsureBuffers come first");
            bool recordsHold = _valid && SameRecordInputs(inputs);
            if (recordsHold && SameFactorInputs(inputs)) return false;
            if (!recordsHold) ForgetEvaluatedTiles();

            ShaderIds.SetParams(shader, inputs.parameters);
            shader.SetMatrix(ShaderIds.LodObjectToClip, inputs.objectToClip);
            shader.SetMatrix(ShaderIds.WorldToObject, inputs.worldToObject);
            shader.SetVector(ShaderIds.LodScreenSize, inputs.screenSize);
            SetEffectKeywords(shader, inputs.effects);
            bool snow = (inputs.effects & Effects.Snow) != 0;
            if (snow) shader.SetVector(ShaderIds.SnowMapSize, inputs.snowMapSize);

            // Kernel 2 reads the factors as t5, not the UAV: FXC refuses its loop on a UAV read.
            BindPatchBuffers(shader, _factorsKernel, inputs, snow);
            shader.SetBuffer(_factorsKernel, ShaderIds.TileFactorsRW, _factors);
            shader.SetBuffer(_factorsKernel, ShaderIds.TileCellsRW, _cells);
            BindPatchBuffers(shader, _verticesKernel, inputs, snow);
            shader.SetBuffer(_verticesKernel, ShaderIds.TileFactors, _factors);
            shader.SetBuffer(_verticesKernel, ShaderIds.VertexCacheRW, _vertices);

            // A group a tile for the factors; groups (x, y, 0 .. G - 1) share tile y T + x for the vertices.
            shader.Dispatch(_factorsKernel, _tiles, _tiles, 1);
            shader.Dispatch(_verticesKernel, _tiles, _tiles, GregoryTerrain.VertexCache.GroupsPerTile(_factorLimit));

            _last = inputs;
            _valid = true;
            return true;
        }

        // Zero the keys (slots' and cells'): every tile reads as moved. Only _TileFactors is uploaded,
        // 64 bytes a tile (the snow path comes here every step); the dispatch that follows rewrites its factors.
        void ForgetEvaluatedTiles()
        {
            int count = _tiles * _tiles;
            if (_zeroRecords == null || _zeroRecords.Length != count) _zeroRecords = new TileFactorRecord[count];
            _factors.SetData(_zeroRecords);
        }

        /// <summary>Binds the buffers on the draw's property block under the graphics stages' names.</summary>
        public void BindTo(MaterialPropertyBlock props)
        {
            props.SetBuffer(ShaderIds.TileFactors, _factors);
            props.SetBuffer(ShaderIds.VertexCache, _vertices);
        }

        /// <summary>Releases the buffers. Safe to call twice.</summary>
        public void Release()
        {
            _factors?.Release(); _factors = null;
            _cells?.Release(); _cells = null;
            _vertices?.Release(); _vertices = null;
            _valid = false;
        }

        static void BindPatchBuffers(ComputeShader shader, int kernel, in Inputs inputs, bool snow)
        {
            shader.SetBuffer(kernel, ShaderIds.ControlPoints, inputs.controlPoints);
            shader.SetBuffer(kernel, ShaderIds.Regions, inputs.regions);
            shader.SetBuffer(kernel, ShaderIds.GridLines, inputs.gridLines);
            if (snow) shader.SetBuffer(kernel, ShaderIds.SnowDepth, inputs.snowDepth);
            if ((inputs.effects & Effects.NoiseTable) != 0) shader.SetBuffer(kernel, ShaderIds.NoiseCells, inputs.noiseCells);
        }

        /// <summary>The material's effects as the kernels' keywords (TerrainCache.compute: the cache's and the levels' kernels).</summary>
        internal static void SetEffectKeywords(ComputeShader shader, Effects effects)
        {
            SetKeyword(shader, ShaderKeywords.Noise, (effects & Effects.Noise) != 0);
            SetKeyword(shader, ShaderKeywords.HeightColor, (effects & Effects.HeightColor) != 0);
            SetKeyword(shader, ShaderKeywords.NoiseTable, (effects & Effects.NoiseTable) != 0);
            SetKeyword(shader, ShaderKeywords.Snow, (effects & Effects.Snow) != 0);
        }

        static void SetKeyword(ComputeShader shader, string keyword, bool on)
        {
            if (on) shader.EnableKeyword(keyword); else shader.DisableKeyword(keyword);
        }

        /// <summary>The rest of what the kernels read: the range (anchored, only its first cells), pixel target, uniform factor, LOD camera.</summary>
        bool SameFactorInputs(in Inputs i) =>
            SameParams(WithKernelRange(i.parameters), WithKernelRange(_last.parameters)) &&
            SameMatrix(i.objectToClip, _last.objectToClip) && SameVector(i.screenSize, _last.screenSize);

        /// <summary>Everything a tile's records depend on besides what the kernels compare per tile (factors, <c>_Range</c>).</summary>
        bool SameRecordInputs(in Inputs i)
        {
            if (!SameParams(WithoutPerTileInputs(i.parameters), WithoutPerTileInputs(_last.parameters))) return false;
            if (!SameMatrix(i.worldToObject, _last.worldToObject)) return false;
            if (i.controlPoints != _last.controlPoints || i.regions != _last.regions || i.gridLines != _last.gridLines) return false;
            if (i.gridStamp != _last.gridStamp || i.effects != _last.effects) return false;
            if ((i.effects & Effects.Snow) != 0 &&
                (i.snowDepth != _last.snowDepth || i.snowVersion != _last.snowVersion || !SameVector(i.snowMapSize, _last.snowMapSize)))
                return false;
            return true;
        }

        // _Range and _Tess.zw zeroed (compared per tile); a new _TileLattice forgets every tile.
        static TerrainParams WithoutPerTileInputs(TerrainParams p)
        {
            p.range = default;
            p.tess = new Float4(p.tess.x, p.tess.y, 0f, 0f);
            return p;
        }

        static TerrainParams WithKernelRange(TerrainParams p)
        {
            p.range = TileLattice.KernelRange(p);
            return p;
        }

        static bool SameParams(in TerrainParams a, in TerrainParams b)
        {
            for (int k = 0; k < TerrainParams.Float4Count; k++)
                if (!a[k].Equals(b[k])) return false;
            return true;
        }

        // Bit-level equality through float.Equals (NaN equals NaN, so a NaN never forces a dispatch per frame).
        internal static bool SameVector(Vector4 a, Vector4 b) =>
            a.x.Equals(b.x) && a.y.Equals(b.y) && a.z.Equals(b.z) && a.w.Equals(b.w);

        /// <summary>Every entry equal, bit for bit as float.Equals compares.</summary>
        internal static bool SameMatrix(in Matrix4x4 a, in Matrix4x4 b) =>
            a.m00.Equals(b.m00) && a.m01.Equals(b.m01) && a.m02.Equals(b.m02) && a.m03.Equals(b.m03) &&
            a.m10.Equals(b.m10) && a.m11.Equals(b.m11) && a.m12.Equals(b.m12) && a.m13.Equals(b.m13) &&
            a.m20.Equals(b.m20) && a.m21.Equals(b.m21) && a.m22.Equals(b.m22) && a.m23.Equals(b.m23) &&
            a.m30.Equals(b.m30) && a.m31.Equals(b.m31) && a.m32.Equals(b.m32) && a.m33.Equals(b.m33);
    }
}
