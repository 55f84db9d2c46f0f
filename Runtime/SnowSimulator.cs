using System;
using UnityEngine;

namespace GregoryTerrain
{
    /// <summary>
    /// Wind-driven snow (Moriya and Takahashi, eq. 1) simulated on the GPU in Play Mode, drawn by the
    /// <see cref="Terrain"/> renderer (<c>GT_SNOW</c>) while this is enabled; disabled or absent, there is
    /// no snow buffer, dispatch or snow code. The terrain field comes from the renderer, a CPU
    /// <see cref="Field"/> or a GPU buffer (<see cref="SetFieldBuffer"/>). The manual: snow.md.
    /// </summary>
    [DisallowMultipleComponent]
    [AddComponentMenu("Gregory Terrain/Snow Simulator")]
    public sealed class SnowSimulator : MonoBehaviour
    {
        /// <summary>The terrain material keyword this component turns on while it runs.</summary>
        public const string Keyword = ShaderKeywords.Snow;

        [Tooltip("Shaders/Snow/SnowSimulation.compute")]
        [SerializeField] ComputeShader simulation;
        [Tooltip("Shaders/Snow/SnowField.compute: evaluates the snow field (slope and height per cell) from the terrain.")]
        [SerializeField] ComputeShader fieldShader;
        [Tooltip("The Gregory Terrain Renderer that snow falls on: its grid shapes the snow, and it draws the snow while this component is enabled.")]
        [SerializeField] GregoryTerrainRenderer terrain;
        [SerializeField] SnowSettings settings = SnowSettings.Default;
        [Tooltip("Simulated seconds per real second.")]
        [SerializeField, Min(0f)] float timeScale = 1f;
        [Tooltip("Longest simulated step (s): a long frame is not one huge step.")]
        [SerializeField, Min(0.001f)] float maxStep = 0.1f;

        // What the buffers and kernels use: `settings` (which the Inspector writes) once validated.
        SnowSettings? _applied;
        bool _editPending;   // OnValidate found a valid Inspector edit; Update applies it
        SnowSettings Applied => _applied ?? settings;

        GraphicsBuffer _field, _exposure, _depth;
        bool _ownsField;
        int _exposureKernel = -1, _accumulateKernel = -1;
        bool _exposureValid;
        SnowSettings _exposureSettings;
        int _exposureFieldVersion;
        SnowField _cpuField;
        int _uploadedCpuVersion = -1;
        GraphicsBuffer _externalField;
        int _externalVersion;
        int _fieldKernel = -1;
        GregoryTerrainRenderer _attached;      // the renderer this simulator is attached to now
        // What the field was last evaluated from: the renderer's upload, field constants and noise keywords.
        int _fieldGridStamp = -1;
        TerrainParams _fieldParams;
        bool _fieldNoise, _fieldNoiseTable;
        int _terrainVersion, _fieldTerrainVersion = -1;

        /// <summary>
        /// The settings. Setting them validates them (ArgumentException naming field and value); a new
        /// resolution starts a new, empty map. An Inspector edit is validated and applied in the next Update.
        /// </summary>
        public SnowSettings Settings
        {
            get => Applied;   // not an Inspector edit that failed validation and is not used
            set
            {
                value.Validate();
                Apply(value);
                settings = value;
            }
        }

        /// <summary>Puts validated settings in use; a new resolution drops old fields, and a new map while enabled.</summary>
        void Apply(SnowSettings value)
        {
            _editPending = false;
            bool newMap = value.resolution != Applied.resolution;
            _applied = value;   // the renderer reads the new cap from MapSize
            if (!newMap) return;
            DropFieldsOfOtherResolution(value.resolution);
            if (_depth != null)
            {
                Release();
                Allocate();
            }
        }

        void OnValidate()
        {
            // Applied in Update: OnValidate must not make or release GPU buffers.
            try { settings.Validate(); }
            catch (ArgumentException e)
            {
                Debug.LogError($"{name}: Snow Simulator: {e.Message}; the last valid settings stay in use until it is fixed.", this);
                _editPending = false;
                return;
            }
            _editPending = true;
        }

        /// <summary>The renderer snow falls on; while enabled this is attached to it and its grid gives the field.</summary>
        public GregoryTerrainRenderer Terrain
        {
            get => terrain;
            set { terrain = value; if (isActiveAndEnabled) Attach(); }
        }
        /// <summary>Shaders/Snow/SnowSimulation.compute; set it before enabling.</summary>
        public ComputeShader Simulation { get => simulation; set => simulation = value; }
        /// <summary>Shaders/Snow/SnowField.compute; set it before enabling (its kernel is looked up in OnEnable).</summary>
        public ComputeShader FieldShader { get => fieldShader; set => fieldShader = value; }

        /// <summary>The terrain field on the CPU; uploaded whenever its <see cref="SnowField.Version"/> changes.</summary>
        public SnowField Field
        {
            get => _cpuField;
            set
            {
                if (value != null && value.Resolution != Applied.resolution)
                    throw new ArgumentException($"Field.Resolution ({value.Resolution}) must equal snow.resolution ({Applied.resolution})", nameof(value));
                _cpuField = value; _externalField = null; _uploadedCpuVersion = -1;
            }
        }

        /// <summary>
        /// Uses a GPU buffer of R*R float4 (detail normal.xyz, height) as the field; bump
        /// <paramref name="version"/> whenever its contents change so the exposure is recomputed.
        /// </summary>
        public void SetFieldBuffer(GraphicsBuffer buffer, int version)
        {
            int r = Applied.resolution, cells = r * r;
            if (buffer == null || buffer.count != cells || buffer.stride != 16)
                throw new ArgumentException($"buffer must hold {cells} float4 (R = {r})", nameof(buffer));
            _externalField = buffer; _externalVersion = version; _cpuField = null;
        }

        // A field for the old resolution would be read past its end: a new resolution forgets it.
        void DropFieldsOfOtherResolution(int resolution)
        {
            if (_externalField != null && _externalField.count != resolution * resolution) _externalField = null;
            if (_cpuField != null && _cpuField.Resolution != resolution) { _cpuField = null; _uploadedCpuVersion = -1; }
        }

        /// <summary>Whether a buffer set by <see cref="SetFieldBuffer"/> is in use (tests).</summary>
        internal bool UsesFieldBuffer => _externalField != null;

        /// <summary>
        /// Evaluates the field from the terrain again at the next step; call it after changing something
        /// the renderer does not know of.
        /// </summary>
        public void MarkTerrainChanged() => _terrainVersion++;

        bool UsesTerrainField => _externalField == null && _cpuField == null && terrain != null;

        /// <summary>The depth map (R*R floats) while enabled, else null.</summary>
        public GraphicsBuffer DepthBuffer => _depth;

        /// <summary>Changes whenever the depth map's contents may have changed; caches derived from it compare it.</summary>
        public int DepthVersion { get; private set; }

        /// <summary><c>_SnowMapSize = (R, 1/R, depthCap, 0)</c>, as the terrain material gets it.</summary>
        public Vector4 MapSize => new Vector4(Applied.resolution, 1f / Applied.resolution, Applied.depthCap, 0f);

        /// <summary>True when the next step will recompute the exposure.</summary>
        public bool NeedsExposureUpdate => !_exposureValid || !Applied.ExposureEquals(_exposureSettings) || FieldVersion != _exposureFieldVersion;

        int FieldVersion => _externalField != null ? _externalVersion
            : _cpuField != null ? _cpuField.Version : _fieldTerrainVersion;

        void OnEnable()
        {
            if (!SystemInfo.supportsComputeShaders || simulation == null)
            {
                Debug.LogWarning("SnowSimulator: no compute shaders or no simulation shader assigned; snow stays off.", this);
                enabled = false;
                return;
            }
            try { settings.Validate(); }
            catch (ArgumentException e) { Debug.LogError("SnowSimulator: " + e.Message, this); enabled = false; return; }
            _applied = settings;
            _editPending = false;
            DropFieldsOfOtherResolution(settings.resolution);
            _exposureKernel = simulation.FindKernel(ShaderIds.SnowExposureKernel);
            _accumulateKernel = simulation.FindKernel(ShaderIds.SnowAccumulateKernel);
            _fieldKernel = fieldShader != null ? fieldShader.FindKernel(ShaderIds.SnowFieldKernel) : -1;
            if (terrain == null)
                Debug.LogWarning("SnowSimulator: Terrain is empty; assign the Gregory Terrain Renderer the snow falls on (or give it a Field from code).", this);
            else if (fieldShader == null)
                Debug.LogWarning("SnowSimulator: Field Shader is empty (Shaders/Snow/SnowField.compute); the terrain's snow field cannot be evaluated, so no snow falls.", this);
            Allocate();
            Attach();
        }

        void OnDisable()
        {
            Detach();
            Release();
        }

        void Update()
        {
            if (_editPending) Apply(settings);   // validated by OnValidate
            if (_depth == null) return;
            if (terrain != _attached) Attach();   // retargeted in the inspector
            float dt = Mathf.Min(Time.deltaTime * timeScale, maxStep);
            if (dt > 0f) StepSimulation(dt);
        }

        /// <summary>One simulation step of dt seconds on the GPU (exposure first if it is stale).</summary>
        public void StepSimulation(float dt)
        {
            if (_depth == null) throw new InvalidOperationException("SnowSimulator is not enabled");
            GraphicsBuffer field = CurrentField();
            if (field == null) return;  // no terrain field yet: nothing to snow on
            SnowSettings applied = Applied;
            SetParams(applied.Params(dt));
            int groups = applied.resolution / 8;  // R is a power of two >= 64
            if (NeedsExposureUpdate)
            {
                simulation.SetBuffer(_exposureKernel, ShaderIds.SnowField, field);
                simulation.SetBuffer(_exposureKernel, ShaderIds.SnowExposure, _exposure);
                simulation.Dispatch(_exposureKernel, groups, groups, 1);
                _exposureValid = true;
                _exposureSettings = applied;
                _exposureFieldVersion = FieldVersion;
            }
            simulation.SetBuffer(_accumulateKernel, ShaderIds.SnowField, field);
            simulation.SetBuffer(_accumulateKernel, ShaderIds.SnowExposure, _exposure);
            simulation.SetBuffer(_accumulateKernel, ShaderIds.SnowDepth, _depth);
            simulation.Dispatch(_accumulateKernel, groups, groups, 1);
            DepthVersion++;
        }

        /// <summary>Clears the snow (the exposure stays valid).</summary>
        public void ClearSnow()
        {
            _depth?.SetData(new float[Applied.resolution * Applied.resolution]);
            DepthVersion++;
        }

        GraphicsBuffer CurrentField()
        {
            if (_externalField != null) return _externalField;
            if (UsesTerrainField)
            {
                if (_fieldKernel < 0) return null;   // no SnowField.compute assigned
                if (!terrain.TryGetSnowTerrain(out TerrainGpuBuffers buffers, out TerrainParams parameters, out bool noise,
                        out GraphicsBuffer noiseCells, out int gridStamp))
                    return null;   // nothing uploaded yet, or settings the renderer cannot draw
                TerrainParams p = SnowFieldTerrain.ParamsFor(parameters, Applied.resolution);
                bool tiled = noiseCells != null;   // tiled noise is another height field
                if (gridStamp != _fieldGridStamp || noise != _fieldNoise || tiled != _fieldNoiseTable || !SameParams(p, _fieldParams))
                {
                    _fieldGridStamp = gridStamp; _fieldNoise = noise; _fieldNoiseTable = tiled; _fieldParams = p;
                    _terrainVersion++;
                }
                if (_fieldTerrainVersion != _terrainVersion) EvaluateField(buffers, noiseCells);
                return _field;
            }
            if (_cpuField == null) return null;
            if (_cpuField.Resolution != Applied.resolution) return null;
            if (_uploadedCpuVersion != _cpuField.Version)
            {
                _field.SetData(_cpuField.Data);
                _uploadedCpuVersion = _cpuField.Version;
            }
            return _field;
        }

        /// <summary>SnowFieldKernel over the R x R cells: the terrain's vertex path at every cell centre.</summary>
        void EvaluateField(TerrainGpuBuffers buffers, GraphicsBuffer noiseCells)
        {
            TerrainParams p = _fieldParams;
            ShaderIds.SetParams(fieldShader, p);
            if (_fieldNoise) fieldShader.EnableKeyword(ShaderKeywords.Noise); else fieldShader.DisableKeyword(ShaderKeywords.Noise);
            if (_fieldNoiseTable) fieldShader.EnableKeyword(ShaderKeywords.NoiseTable); else fieldShader.DisableKeyword(ShaderKeywords.NoiseTable);
            if (_fieldNoiseTable) fieldShader.SetBuffer(_fieldKernel, ShaderIds.NoiseCells, noiseCells);
            fieldShader.SetBuffer(_fieldKernel, ShaderIds.ControlPoints, buffers.ControlPoints);
            fieldShader.SetBuffer(_fieldKernel, ShaderIds.Regions, buffers.Regions);
            fieldShader.SetBuffer(_fieldKernel, ShaderIds.GridLines, buffers.GridLines);
            fieldShader.SetBuffer(_fieldKernel, ShaderIds.SnowField, _field);
            int groups = Applied.resolution / 8;
            fieldShader.Dispatch(_fieldKernel, groups, groups, 1);
            _fieldTerrainVersion = _terrainVersion;   // the field's version: the exposure sees the change
        }

        static bool SameParams(TerrainParams a, TerrainParams b)
        {
            for (int i = 0; i < TerrainParams.Float4Count; i++)
                if (!a[i].Equals(b[i])) return false;
            return true;
        }

        void SetParams(in SnowParams p) => ShaderIds.SetFloat4s(simulation, ShaderIds.SnowParams, p);

        void Allocate()
        {
            int cells = Applied.resolution * Applied.resolution;
            _field = new GraphicsBuffer(GraphicsBuffer.Target.Structured, cells, 16);
            _ownsField = true;
            _exposure = new GraphicsBuffer(GraphicsBuffer.Target.Structured, cells, 4);
            _depth = new GraphicsBuffer(GraphicsBuffer.Target.Structured, cells, 4);
            _depth.SetData(new float[cells]);
            DepthVersion++;
            _exposureValid = false;
            _uploadedCpuVersion = -1;
            _fieldTerrainVersion = -1;   // a new field buffer: evaluate the terrain again
        }

        /// <summary>Attaches to <see cref="Terrain"/> (detaching from a previous renderer): it draws GT_SNOW from now on.</summary>
        void Attach()
        {
            if (_attached == terrain) return;
            Detach();
            if (terrain == null) return;
            terrain.AttachSnow(this);
            _attached = terrain;
            _fieldGridStamp = -1;   // a new terrain: evaluate its field
        }

        void Detach()
        {
            if (_attached != null) _attached.DetachSnow(this);
            _attached = null;
        }

        void Release()
        {
            if (_ownsField) _field?.Release();
            _exposure?.Release();
            _depth?.Release();
            _field = _exposure = _depth = null;
            _ownsField = false;
            _exposureValid = false;
        }
    }
}
