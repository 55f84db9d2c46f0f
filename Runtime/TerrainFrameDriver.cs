using System;
using System.Collections.Generic;
using Unity.Profiling;
using UnityEngine;
using UnityEngine.Rendering;
#if UNITY_EDITOR
using UnityEditor.SceneManagement;
#endif
using static GregoryTerrain.UnityConversions;

namespace GregoryTerrain
{
    /// <summary>
    /// A renderer's per-camera frame (Tools~/docs/design-notes.md, "Renderer map"): uploads, Core's plan sent on the
    /// property block, the vertex cache, the draw material, the draw. It reads the component's settings.
    /// </summary>
    sealed class TerrainFrameDriver
    {
        readonly GregoryTerrainRenderer _r;
        MaterialPropertyBlock _props;
        readonly FrameState _state = new FrameState();
        readonly TerrainGpuBuffers _gpu = new TerrainGpuBuffers();
        readonly VertexCachePass _cache = new VertexCachePass();
        readonly LevelFactorPass _levelFactors = new LevelFactorPass();
        readonly DrawMaterialCopy _drawCopy = new DrawMaterialCopy();
        readonly List<int> _setLastPrepare = new List<int>(16);
        readonly Vector4[] _levelVectors = new Vector4[LodTiles.MaxLevels];   // SetVectorArray's copy of the plan's levels
        int _gridStamp;   // bumped on every upload: the cache and the snow see new grid buffers

        static bool s_FallbackLogged, s_DeviceChecked;
        static string s_DeviceError;

        /// <summary>
        /// SubShader tag of GregoryTerrain.shader: "Tessellated" or "Fallback", the draw the SubShader
        /// expects (4-control-point tile patches, or the instanced vertex grid).
        /// </summary>
        const string DrawTag = "GregoryTerrainDraw";

        // The Profiler's names for the per-camera work (a struct scope: nothing allocated).
        static readonly ProfilerMarker s_DrawMarker = new ProfilerMarker("GregoryTerrainRenderer.Draw");
        static readonly ProfilerMarker s_PrepareMarker = new ProfilerMarker("GregoryTerrainRenderer.Prepare");
        static readonly ProfilerMarker s_VertexCacheMarker = new ProfilerMarker("GregoryTerrainRenderer.VertexCache");

        public TerrainFrameDriver(GregoryTerrainRenderer renderer) => _r = renderer;

        public FrameState State => _state;
        public TerrainGpuBuffers Gpu => _gpu;
        public int GridStamp => _gridStamp;
        public long CacheAllocatedBytes => _cache.AllocatedBytes + _levelFactors.AllocatedBytes;
        public static string DeviceError => s_DeviceError;
        FrameResources _keys => _state.resources;
        TerrainParams _params => _state.parameters;

        public int UploadCount { get; private set; }

        public IReadOnlyList<int> PropertiesSetLastPrepare => _setLastPrepare;

        public Material DrawMaterial => _drawCopy.Current != null ? _drawCopy.Current : _r.Material;

        public Material UpdateDrawMaterial(FrameKeywords keywords) => _drawCopy.Update(_r.Material, keywords, _keys);

        public void InvalidateCache() => _cache.Invalidate();

        public void ReleaseGpuResources()
        {
            _gpu.Release();
            _cache.Release();
            _levelFactors.Release();
            _keys.Released();   // uploaded again, the estimate's CPU copy dropped, the SubShader's tag read again, the cache off
            ClearPropertyBlock();
        }

        public void ReleaseAll()
        {
            ReleaseGpuResources();
            _drawCopy.Release(_keys);
        }

        /// <summary>Empties the property block and forgets what it held: the one place the block is cleared.</summary>
        void ClearPropertyBlock()
        {
            _props?.Clear();
            _state.Forget();   // the bindings set only on change too
        }

        // ---- one camera -----------------------------------------------------------------------------

        /// <summary>One draw: <c>_Range</c> and, on change only, the rest (<see cref="Prepare"/>), in one RenderPrimitives call only <paramref name="cam"/> renders.</summary>
        public void DrawFor(Camera cam)
        {
            if (cam == null || !DrawsIn(cam)) return;
            using (s_DrawMarker.Auto())
                Draw(cam);
        }

        void Draw(Camera cam)
        {
            bool prepared;
            using (s_PrepareMarker.Auto())
                prepared = Prepare(cam);
            if (!prepared) return;

            var rp = new RenderParams(DrawMaterial)
            {
                camera = cam,
                worldBounds = WorldBounds(),
                matProps = _props,
                shadowCastingMode = _r.ShadowCasting,
                receiveShadows = _r.ReceivesShadows,
                layer = _r.gameObject.layer,
            };
            int across = TileLattice.TilesAcross(_params), tileCount = across * across;
            bool fallback = _keys.LastDrawFallback;
            if (_r.LevelsOn(fallback)) tileCount = _state.levelCount * _r.Tiles * _r.Tiles;   // L x M^2 tiles, laid out around cam by Prepare(cam)
            if (fallback)
                Graphics.RenderPrimitivesIndexed(rp, MeshTopology.Triangles, _gpu.FallbackIndices,
                    _gpu.FallbackIndices.count, 0, tileCount);
            else
                // One 4-control-point patch per tile; the vertex stage derives tile and corner from
                // SV_VertexID, so there is no vertex buffer.
                Graphics.RenderPrimitives(rp, MeshTopology.Quads, 4 * tileCount, 1);
        }

        /// <summary>Never a preview camera; in the editor one whose scene culling mask shares a bit with ours (Prefab stages).</summary>
        bool DrawsIn(Camera cam)
        {
            if (cam.cameraType == CameraType.Preview) return false;
#if UNITY_EDITOR
            return CameraSceneFilter.Draws(_r.gameObject.sceneCullingMask, SceneCullingMaskOf(cam));
#else
            return true;
#endif
        }

#if UNITY_EDITOR
        static ulong SceneCullingMaskOf(Camera cam)
        {
            bool hasScene = cam.scene.IsValid();
            return CameraSceneFilter.CameraMask(cam.overrideSceneCullingMask, hasScene,
                hasScene ? EditorSceneManager.GetSceneCullingMask(cam.scene) : 0UL,
                cam.cameraType == CameraType.SceneView);
        }
#endif

        /// <summary>
        /// <paramref name="cam"/>'s object -> clip and pixel size, from which every pass of its draw takes
        /// the factors; set only when they differ from what the property block holds.
        /// </summary>
        void PushTessellationView(Camera cam)
        {
            if (cam == null) return;
            int w = cam.pixelWidth, h = cam.pixelHeight;
            if (w <= 0 || h <= 0) return;   // renders nothing
            Matrix4x4 m = ObjectToClip(cam, _state.objectToWorld);
            var size = new Vector4(w, h, 1f / w, 1f / h);
            if (_props.HasMatrix(ShaderIds.TessObjectToClip) && VertexCachePass.SameMatrix(m, _props.GetMatrix(ShaderIds.TessObjectToClip))
                && VertexCachePass.SameVector(size, _props.GetVector(ShaderIds.TessScreenSize)))
                return;
            SetMatrix(ShaderIds.TessObjectToClip, m);
            SetVector(ShaderIds.TessScreenSize, size);
        }

        /// <summary>Uploads, the plan sent, the vertex cache, the material. False when nothing can be drawn.</summary>
        bool Prepare(Camera cam = null)
        {
            _setLastPrepare.Clear();
            Material material = _r.Material;
            PatchGridAsset grid = _r.Grid;
            if (material == null || grid == null || !grid.IsValid) return false;
            if (!DeviceCanDraw()) return false;
            if (!EnsureUploaded(grid)) return false;

            bool fallback = ReadDrawMode();
            if (fallback && !EnsureFallbackIndices()) return false;

            FrameChange change = FramePlanner.Plan(_state, FrameInputsFor(cam, fallback));
            if ((change & FrameChange.Error) != 0) Debug.LogError($"{_r.name}: cannot draw with these settings: {_state.error}", _r);
            if (_state.error != null) return false;   // logged once; drawn again after the next valid change
            UpdateNoiseTableBinding();   // before the kernels: they read the same table
            if (_levelFactors.UpdateFrame(_r, cam, fallback, _state, _gpu, _props))
                change |= FrameChange.Levels | FrameChange.LevelCount;   // the hull's switch or the records' count in _LodLevels changed
            Send(change);
            PushTessellationView(cam);
            bool cacheReady;
            using (s_VertexCacheMarker.Auto())
                cacheReady = _cache.UpdateFrame(_r, fallback, _state, _gpu, _gridStamp, _props);
            if (!cacheReady) return false;
            UpdateSnowBinding();
            return UpdateDrawMaterial(FramePlanner.Keywords(_state, _keys.UsesCache, _r.SnowOn())) != null;
        }

        /// <summary>What the planner reads this frame.</summary>
        FrameInputs FrameInputsFor(Camera cam, bool fallback)
        {
            var f = new FrameInputs
            {
                grid = _gpu.Grid,
                settings = _r.Settings(fallback),
                range = _r.Range,
                noiseKeywords = _r.NoiseKeywords(),
                localToWorld = ToFloat4x4(_r.transform.localToWorldMatrix), terrainSize = _r.ValidSize(), heightScale = _r.ValidHeightScale(),
                worldOffset = _r.WorldOffset,
                hasCamera = cam != null,
            };
            if (cam == null || !f.settings.levels) return f;
            f.camera = cam.GetInstanceID();   // each camera keeps its own range origin
            Double3 local = _r.WorldToTerrainObject(cam.transform.position);   // object space: (x, height, y)
            f.ground = new Double2(local.x, local.z);
            f.finestExponent = _r.FinestExponent();
            return f;
        }

        /// <summary>Sets what the plan changed: steady, <c>_Range</c> alone (and the levels' <c>_Ranges</c>).</summary>
        void Send(FrameChange change)
        {
            TerrainParams p = _params;
            if ((change & FrameChange.Params) != 0)
                for (int k = 0; k < TerrainParams.Float4Count; k++) SetVector(ShaderIds.Params[k], ToVector(p[k]));
            if ((change & (FrameChange.Params | FrameChange.Range)) == FrameChange.Range) SetVector(ShaderIds.Range, ToVector(p.range));
            if ((change & (FrameChange.Params | FrameChange.RangeOrigin)) == FrameChange.RangeOrigin) SetVector(ShaderIds.RangeOrigin, ToVector(p.rangeOrigin));
            if ((change & FrameChange.TileLattice) != 0) SetVector(ShaderIds.TileLattice, ToVector(p.tileLattice));
            if ((change & FrameChange.Matrices) != 0)
            {
                SetMatrix(ShaderIds.ObjectToWorld, ToMatrix4x4(_state.objectToWorld));
                SetMatrix(ShaderIds.WorldToObject, ToMatrix4x4(_state.worldToObject));
            }
            if ((change & FrameChange.Levels) != 0) SendLevels((change & FrameChange.LevelCount) != 0);
        }

        /// <summary>The plan's levels, one float4 each; <c>_LodLevels</c> when the count changed.</summary>
        void SendLevels(bool count)
        {
            for (int k = 0; k < _state.levelCount; k++) _levelVectors[k] = ToVector(_state.levelVectors[k]);
            _props.SetVectorArray(ShaderIds.Ranges, _levelVectors);
            _setLastPrepare.Add(ShaderIds.Ranges);
            if (count) SetVector(ShaderIds.LodLevels, new Vector4(_state.levelCount, _keys.UsesLevelKernels ? 1f : 0f, _levelFactors.CacheRecords, 0f));
        }

        // Every value put on the property block goes through these: PropertiesSetLastPrepare.
        void SetVector(int id, Vector4 v) { _props.SetVector(id, v); _setLastPrepare.Add(id); }
        void SetMatrix(int id, Matrix4x4 m) { _props.SetMatrix(id, m); _setLastPrepare.Add(id); }
        void SetBuffer(int id, GraphicsBuffer b) { _props.SetBuffer(id, b); _setLastPrepare.Add(id); }

        /// <summary>The SubShader's draw, read again when what Unity picks it by changes (<see cref="DrawModeKey"/>; GetTag allocates).</summary>
        public bool ReadDrawMode()
        {
            Material material = _r.Material;
            Shader shader = material.shader;
            var key = new DrawModeKey(material.GetInstanceID(), IdOf(shader), Shader.globalMaximumLOD, shader != null ? shader.maximumLOD : 0,
                IdOf(GraphicsSettings.currentRenderPipeline));
            if (_keys.TryDrawMode(key, out bool fallback)) return fallback;
            string tag = material.GetTag(DrawTag, false, "");
            fallback = tag == "Fallback" || (tag.Length == 0 && GregoryTerrainRenderer.UsesFallback);
            _keys.DrawModeRead(key, fallback);
            return fallback;
        }

        static int IdOf(UnityEngine.Object o) => o != null ? o.GetInstanceID() : 0;

        /// <summary>
        /// World bounds of the drawn range: height between the lowest and highest control point,
        /// widened by the largest noise and raised by the snow cap (what the shader's culling keeps).
        /// </summary>
        public Bounds WorldBounds()
        {
            float noise = _r.NoiseMargin();
            float snow = _r.SnowDepthCap();   // the shader's tile culling raises a tile's box by it (TileCulled)
            TerrainRange drawn = _r.LevelsOn(_keys.LastDrawFallback) ? TerrainRange.full : _r.Range;   // the levels end with the whole terrain
            Vector3 min = new Vector3((float)drawn.c, _keys.GridMinZ - noise, (float)drawn.d);
            Vector3 max = new Vector3((float)drawn.g, _keys.GridMaxZ + noise + snow, (float)drawn.h);
            Matrix4x4 m = ToMatrix4x4(_state.objectToWorld);   // size, height scale and offset included (t is added to the object points below)
            Double3 t = TerrainVertex.TerrainToObject(_state.outputOffset);
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

        // ---- GPU objects: made, bound and released as FrameResources decides ------------------------

        /// <summary>
        /// False where Unity cannot make structured buffers (GraphicsBuffer throws for Target.Structured
        /// unless SystemInfo.supportsComputeShaders), which every pass reads. Logged once a run.
        /// </summary>
        bool DeviceCanDraw()
        {
            if (!s_DeviceChecked)
            {
                s_DeviceChecked = true;
                if (!SystemInfo.supportsComputeShaders)
                {
                    s_DeviceError = "no compute support on this device (SystemInfo.supportsComputeShaders = false), so no structured buffers, which every pass reads: not drawn";
                    Debug.LogError($"Gregory Terrain: {s_DeviceError}.", _r);
                }
            }
            return s_DeviceError == null;
        }

        /// <summary>Uploads the grid when it is new or changed; false when it cannot be drawn.</summary>
        bool EnsureUploaded(PatchGridAsset grid)
        {
            var key = new GridVersionKey(grid.GetInstanceID(), grid.Version);
            UploadAction action = _keys.Upload(key, _gpu.ControlPoints != null);
            if (action != UploadAction.Upload) return action == UploadAction.Keep;   // Skip: logged once; retried on the next version
            if (TryUploadEditedPatches(grid, key)) return true;
            ReleaseGpuResources();
            string error = null;
            PatchGrid g = null;
            try { g = grid.ToPatchGrid(); }
            catch (ArgumentException e) { error = e.Message; }
            error ??= _gpu.Upload(g);
            if (error != null)
            {
                Debug.LogError($"{_r.name}: patch grid '{grid.name}' cannot be drawn: {error}", _r);
                _keys.UploadFailed(key);   // do not retry every frame
                return false;
            }

            _props ??= new MaterialPropertyBlock();
            SetBuffer(ShaderIds.ControlPoints, _gpu.ControlPoints);
            SetBuffer(ShaderIds.Regions, _gpu.Regions);
            SetBuffer(ShaderIds.GridLines, _gpu.GridLines);
            // _GridSize is part of TerrainParams: the block was cleared above, so the next plan sends it.
            grid.GetHeightRange(out float minZ, out float maxZ);

            _keys.Uploaded(key, minZ, maxZ);
            _gridStamp++;
            UploadCount++;
            _state.ResetOrigins();
            return true;
        }

        /// <summary>
        /// Uploads only the patches edited (PatchGridAsset.ApplyEdit: a sculpt stroke's dabs) since the version in
        /// the buffers; false when that cannot be told (another grid, a whole-grid change, an undo): then the whole grid.
        /// </summary>
        bool TryUploadEditedPatches(PatchGridAsset grid, GridVersionKey key)
        {
            GridVersionKey held = _keys.HeldGrid;
            if (held.grid != key.grid || _gpu.ControlPoints == null) return false;
            PatchGrid g = grid.UpdatedPatchGrid(_gpu.Grid, held.version, out int[] changed);
            if (g == null) return false;
            _gpu.UploadPatches(g, changed);
            _keys.PatchesUploaded(key, g, changed);   // the height range widens by the edited patches
            _gridStamp++;   // the vertex cache evaluates its tiles again; the settings block holds only the grid's size
            return true;
        }

        /// <summary>The fallback's index grid, built when F changes; its use logged once a run.</summary>
        bool EnsureFallbackIndices()
        {
            if (!s_FallbackLogged)
            {
                s_FallbackLogged = true;
                Debug.Log("Gregory Terrain: the shader's tessellated SubShader is not used on this device " +
                          $"(SystemInfo.supportsTessellationShaders = {SystemInfo.supportsTessellationShaders}); " +
                          "drawing the vertex-shader fallback (a fixed grid per tile).", _r);
            }
            int f = _r.FallbackGridFactor;
            if (_keys.RebuildFallbackIndices(f, _gpu.FallbackIndices != null)) _gpu.BuildFallbackIndices(f);
            return true;
        }

        /// <summary>
        /// True when the material's noise is tiled: GT_NOISE_TABLE with GT_NOISE or GT_HEIGHT_COLOR
        /// (the table alone changes nothing: no noise reads it).
        /// </summary>
        bool NoiseTableOn()
        {
            Material material = _r.Material;
            return material != null && material.IsKeywordEnabled(ShaderKeywords.NoiseTable)
                && (material.IsKeywordEnabled(ShaderKeywords.Noise) || material.IsKeywordEnabled(ShaderKeywords.HeightColor));
        }

        /// <summary>The table while the noise is tiled, else released and null: the default (hashed) noise holds none.</summary>
        public GraphicsBuffer EnsureNoiseTable()
        {
            if (NoiseTableOn()) return _gpu.EnsureNoiseTable();
            _gpu.ReleaseNoiseTable();
            return null;
        }

        /// <summary>The table on the property block when new or the block was cleared.</summary>
        void UpdateNoiseTableBinding()
        {
            GraphicsBuffer table = EnsureNoiseTable();
            if (_state.BindNoiseCells(table)) SetBuffer(ShaderIds.NoiseCells, table);
        }

        /// <summary>The snow map on the property block: set when the simulator's buffer or size changes, not per frame.</summary>
        void UpdateSnowBinding()
        {
            if (!_r.SnowOn()) return;   // GT_SNOW off: whatever the block holds is not read
            SnowSimulator snow = _r.SnowSimulator;
            GraphicsBuffer depth = snow.DepthBuffer;
            Vector4 size = snow.MapSize;
            if (!_state.BindSnow(depth, new Float3(size.x, size.y, size.z))) return;
            SetBuffer(ShaderIds.SnowDepth, depth);
            SetVector(ShaderIds.SnowMapSize, size);
        }
    }
}
