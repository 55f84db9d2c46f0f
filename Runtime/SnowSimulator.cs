using System;
using UnityEngine;

namespace GregoryTerrain
{
    /// <summary>
    /// Wind-driven snow on the terrain (Moriya and Takahashi, eq. 1), simulated on the GPU with
    /// Shaders/Snow/SnowSimulation.compute. Add it only to scenes that want snow: while it is disabled or
    /// absent there is no snow buffer, no dispatch and the terrain material's <c>GT_SNOW</c> keyword is
    /// off, so the terrain shader compiles the snow code out.
    /// <para>
    /// While enabled it owns three buffers over the R x R snow map (<c>_SnowField</c> float4,
    /// <c>_SnowExposure</c> float, <c>_SnowDepth</c> float), runs the exposure kernel only when the wind,
    /// the march settings or the terrain field changed (<see cref="SnowSettings.ExposureEquals"/>,
    /// the field version), and one accumulation step per frame. The depth map is bound to the terrain
    /// material as <c>_SnowDepth</c> with <c>_SnowMapSize = (R, 1/R, depthCap, 0)</c>.
    /// </para>
    /// <para>
    /// The field (detail normal and height per cell) normally comes from the terrain itself:
    /// <see cref="SetTerrain"/> hands over the renderer's buffers and constants, and
    /// Shaders/Snow/SnowField.compute (<c>SnowFieldKernel</c>, the terrain's own vertex path at the cell
    /// centres) fills it on the GPU, once per terrain change (<see cref="MarkTerrainChanged"/>); the
    /// exposure follows, since it is recomputed whenever the field changed. Alternatives for tests and
    /// custom terrains: a CPU <see cref="Field"/> or a ready GPU buffer (<see cref="SetFieldBuffer"/>).
    /// </para>
    /// </summary>
    [DisallowMultipleComponent]
    public sealed class SnowSimulator : MonoBehaviour
    {
        /// <summary>The terrain material keyword this component turns on while it runs.</summary>
        public const string Keyword = "GT_SNOW";

        static class Ids
        {
            public static readonly int Grid = Shader.PropertyToID("_SnowGrid");
            public static readonly int Fall = Shader.PropertyToID("_SnowFall");
            public static readonly int Catch = Shader.PropertyToID("_SnowCatch");
            public static readonly int Edge = Shader.PropertyToID("_SnowEdge");
            public static readonly int Step = Shader.PropertyToID("_SnowStep");
            public static readonly int Field = Shader.PropertyToID("_SnowField");
            public static readonly int Exposure = Shader.PropertyToID("_SnowExposure");
            public static readonly int Depth = Shader.PropertyToID("_SnowDepth");
            public static readonly int MapSize = Shader.PropertyToID("_SnowMapSize");
            public static readonly int ControlPoints = Shader.PropertyToID("_ControlPoints");
            public static readonly int Regions = Shader.PropertyToID("_Regions");
            public static readonly int GridLines = Shader.PropertyToID("_GridLines");
            public static readonly int[] TerrainParams = Array.ConvertAll(GregoryTerrain.TerrainParams.PropertyNames, Shader.PropertyToID);
        }

        const string NoiseKeyword = "GT_NOISE";

        [Tooltip("Shaders/Snow/SnowSimulation.compute")]
        [SerializeField] ComputeShader simulation;
        [Tooltip("Shaders/Snow/SnowField.compute: evaluates the terrain field from the terrain (SetTerrain)")]
        [SerializeField] ComputeShader fieldShader;
        [Tooltip("The terrain material (the renderer's): gets GT_SNOW and the depth map while snow is on.")]
        [SerializeField] Material terrainMaterial;
        [SerializeField] SnowSettings settings = SnowSettings.Default;
        [Tooltip("Simulated seconds per real second.")]
        [SerializeField, Min(0f)] float timeScale = 1f;
        [Tooltip("Longest simulated step (s): a long frame is not one huge step.")]
        [SerializeField, Min(0.001f)] float maxStep = 0.1f;

        ComputeBuffer _field, _exposure, _depth;
        bool _ownsField;
        int _exposureKernel = -1, _accumulateKernel = -1;
        bool _exposureValid;
        SnowSettings _exposureSettings;
        int _exposureFieldVersion;
        SnowField _cpuField;
        int _uploadedCpuVersion = -1;
        ComputeBuffer _externalField;
        int _externalVersion;
        int _fieldKernel = -1;
        ComputeBuffer _terrainControlPoints, _terrainRegions, _terrainGridLines;
        TerrainParams _terrainParams;
        bool _terrainNoise;
        int _terrainVersion, _fieldTerrainVersion = -1;

        /// <summary>The simulation settings. Setting them validates them (ArgumentException naming the field and value); a new resolution starts a new, empty snow map.</summary>
        public SnowSettings Settings
        {
            get => settings;
            set
            {
                value.Validate();
                if (_depth != null && value.resolution != settings.resolution)
                {
                    settings = value;
                    Release();
                    Allocate();  // a new resolution starts a new snow map
                }
                else
                {
                    settings = value;
                    Bind();  // the cap in _SnowMapSize may have changed
                }
            }
        }

        /// <summary>The terrain material (the renderer's): it gets the GT_SNOW keyword and the depth map while the simulation runs.</summary>
        public Material TerrainMaterial { get => terrainMaterial; set { DisableKeyword(); terrainMaterial = value; if (isActiveAndEnabled) Bind(); } }
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
                if (value != null && value.Resolution != settings.resolution)
                    throw new ArgumentException($"Field.Resolution ({value.Resolution}) must equal snow.resolution ({settings.resolution})", nameof(value));
                _cpuField = value; _externalField = null; _uploadedCpuVersion = -1;
            }
        }

        /// <summary>
        /// Uses a GPU buffer of R*R float4 (detail normal.xyz, height) as the field; bump
        /// <paramref name="version"/> whenever its contents change so the exposure is recomputed.
        /// </summary>
        public void SetFieldBuffer(ComputeBuffer buffer, int version)
        {
            int cells = settings.resolution * settings.resolution;
            if (buffer == null || buffer.count != cells || buffer.stride != 16)
                throw new ArgumentException($"buffer must hold {cells} float4 (R = {settings.resolution})", nameof(buffer));
            _externalField = buffer; _externalVersion = version; _cpuField = null;
        }

        /// <summary>
        /// The terrain the field is evaluated from on the GPU: the renderer's three buffers
        /// (<c>_ControlPoints</c>, <c>_Regions</c>, <c>_GridLines</c>, as GpuLayout packs them), its
        /// constants (any range: <see cref="SnowFieldTerrain.ParamsFor"/> replaces it) and whether it has
        /// noise (GT_NOISE). Marks the terrain changed. Pass null buffers to stop using a terrain.
        /// </summary>
        internal void SetTerrain(ComputeBuffer controlPoints, ComputeBuffer regions, ComputeBuffer gridLines, TerrainParams parameters, bool noise)
        {
            bool none = controlPoints == null && regions == null && gridLines == null;
            if (!none && (controlPoints == null || regions == null || gridLines == null))
                throw new ArgumentException("controlPoints, regions and gridLines must all be given, or all be null", nameof(controlPoints));
            if (!none && (controlPoints.stride != 16 || regions.stride != 16 || gridLines.stride != 4))
                throw new ArgumentException($"buffer strides ({controlPoints.stride}, {regions.stride}, {gridLines.stride}) must be (16, 16, 4)", nameof(controlPoints));
            _terrainControlPoints = controlPoints; _terrainRegions = regions; _terrainGridLines = gridLines;
            _terrainParams = parameters; _terrainNoise = noise;
            if (!none) { _externalField = null; _cpuField = null; }
            MarkTerrainChanged();
        }

        /// <summary>The terrain's shape or noise changed: the field (and so the exposure) is recomputed at the next step.</summary>
        public void MarkTerrainChanged() => _terrainVersion++;

        bool HasTerrain => _terrainControlPoints != null;

        /// <summary>The depth map (R*R floats) while enabled, else null.</summary>
        public ComputeBuffer DepthBuffer => _depth;

        /// <summary>
        /// Changes whenever the depth map's contents may have changed (a step, a clear, a new map):
        /// readers that cache something derived from it (the renderer's vertex cache) compare it.
        /// </summary>
        public int DepthVersion { get; private set; }

        /// <summary><c>_SnowMapSize = (R, 1/R, depthCap, 0)</c>, as the terrain material gets it.</summary>
        public Vector4 MapSize => new Vector4(settings.resolution, 1f / settings.resolution, settings.depthCap, 0f);

        /// <summary>True when the next step will recompute the exposure.</summary>
        public bool NeedsExposureUpdate => !_exposureValid || !settings.ExposureEquals(_exposureSettings) || FieldVersion != _exposureFieldVersion;

        int FieldVersion => _externalField != null ? _externalVersion
            : HasTerrain ? _fieldTerrainVersion : (_cpuField != null ? _cpuField.Version : 0);

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
            _exposureKernel = simulation.FindKernel("SnowExposureKernel");
            _accumulateKernel = simulation.FindKernel("SnowAccumulateKernel");
            _fieldKernel = fieldShader != null ? fieldShader.FindKernel("SnowFieldKernel") : -1;
            Allocate();
        }

        void OnDisable()
        {
            DisableKeyword();
            Release();
        }

        void Update()
        {
            if (_depth == null) return;
            float dt = Mathf.Min(Time.deltaTime * timeScale, maxStep);
            if (dt > 0f) StepSimulation(dt);
        }

        /// <summary>One simulation step of dt seconds on the GPU (exposure first if it is stale).</summary>
        public void StepSimulation(float dt)
        {
            if (_depth == null) throw new InvalidOperationException("SnowSimulator is not enabled");
            ComputeBuffer field = CurrentField();
            if (field == null) return;  // no terrain field yet: nothing to snow on
            float[] p = settings.PackParams(dt);
            SetParams(p);
            int groups = settings.resolution / 8;  // R is a power of two >= 64
            if (NeedsExposureUpdate)
            {
                simulation.SetBuffer(_exposureKernel, Ids.Field, field);
                simulation.SetBuffer(_exposureKernel, Ids.Exposure, _exposure);
                simulation.Dispatch(_exposureKernel, groups, groups, 1);
                _exposureValid = true;
                _exposureSettings = settings;
                _exposureFieldVersion = FieldVersion;
            }
            simulation.SetBuffer(_accumulateKernel, Ids.Field, field);
            simulation.SetBuffer(_accumulateKernel, Ids.Exposure, _exposure);
            simulation.SetBuffer(_accumulateKernel, Ids.Depth, _depth);
            simulation.Dispatch(_accumulateKernel, groups, groups, 1);
            DepthVersion++;
        }

        /// <summary>Clears the snow (the exposure stays valid).</summary>
        public void ClearSnow()
        {
            _depth?.SetData(new float[settings.resolution * settings.resolution]);
            DepthVersion++;
        }

        ComputeBuffer CurrentField()
        {
            if (_externalField != null) return _externalField;
            if (HasTerrain)
            {
                if (_fieldKernel < 0) return null;   // no SnowField.compute assigned
                if (_fieldTerrainVersion != _terrainVersion) EvaluateField();
                return _field;
            }
            if (_cpuField == null) return null;
            if (_cpuField.Resolution != settings.resolution) return null;
            if (_uploadedCpuVersion != _cpuField.Version)
            {
                _field.SetData(_cpuField.Data);
                _uploadedCpuVersion = _cpuField.Version;
            }
            return _field;
        }

        /// <summary>SnowFieldKernel over the R x R cells: the terrain's vertex path at every cell centre.</summary>
        void EvaluateField()
        {
            TerrainParams p = SnowFieldTerrain.ParamsFor(_terrainParams, settings.resolution);
            for (int i = 0; i < TerrainParams.Float4Count; i++)
            {
                Float4 v = p[i];
                fieldShader.SetVector(Ids.TerrainParams[i], new Vector4(v.x, v.y, v.z, v.w));
            }
            if (_terrainNoise) fieldShader.EnableKeyword(NoiseKeyword); else fieldShader.DisableKeyword(NoiseKeyword);
            fieldShader.SetBuffer(_fieldKernel, Ids.ControlPoints, _terrainControlPoints);
            fieldShader.SetBuffer(_fieldKernel, Ids.Regions, _terrainRegions);
            fieldShader.SetBuffer(_fieldKernel, Ids.GridLines, _terrainGridLines);
            fieldShader.SetBuffer(_fieldKernel, Ids.Field, _field);
            int groups = settings.resolution / 8;
            fieldShader.Dispatch(_fieldKernel, groups, groups, 1);
            _fieldTerrainVersion = _terrainVersion;   // the field's version: the exposure sees the change
        }

        void SetParams(float[] p)
        {
            simulation.SetVector(Ids.Grid, new Vector4(p[0], p[1], p[2], p[3]));
            simulation.SetVector(Ids.Fall, new Vector4(p[4], p[5], p[6], p[7]));
            simulation.SetVector(Ids.Catch, new Vector4(p[8], p[9], p[10], p[11]));
            simulation.SetVector(Ids.Edge, new Vector4(p[12], p[13], p[14], p[15]));
            simulation.SetVector(Ids.Step, new Vector4(p[16], p[17], p[18], p[19]));
        }

        void Allocate()
        {
            int cells = settings.resolution * settings.resolution;
            _field = new ComputeBuffer(cells, 16);
            _ownsField = true;
            _exposure = new ComputeBuffer(cells, 4);
            _depth = new ComputeBuffer(cells, 4);
            _depth.SetData(new float[cells]);
            DepthVersion++;
            _exposureValid = false;
            _uploadedCpuVersion = -1;
            _fieldTerrainVersion = -1;   // a new field buffer: evaluate the terrain again
            Bind();
        }

        void Bind()
        {
            if (terrainMaterial == null || _depth == null) return;
            terrainMaterial.SetBuffer(Ids.Depth, _depth);
            terrainMaterial.SetVector(Ids.MapSize, MapSize);
            terrainMaterial.EnableKeyword(Keyword);
        }

        void DisableKeyword()
        {
            if (terrainMaterial != null) terrainMaterial.DisableKeyword(Keyword);
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
