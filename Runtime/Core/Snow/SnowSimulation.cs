using System;

namespace GregoryTerrain
{
    /// <summary>
    /// The CPU reference of the snow simulation (the compute shader Shaders/Snow/SnowSimulation.compute is
    /// checked against it): an R x R depth map over the terrain's unit square, the cached exposure,
    /// and the rule for when the exposure is stale.
    /// </summary>
    internal sealed class SnowSimulation
    {
        SnowSettings _settings;
        bool _exposureValid;
        SnowSettings _exposureSettings;
        SnowField _exposureField;
        int _exposureFieldVersion;

        /// <summary>Snow depth per cell (terrain height units), index <c>j * R + i</c>, as <c>_SnowDepth</c>.</summary>
        public float[] Depth { get; }
        /// <summary>L per cell, as <c>_SnowExposure</c>; valid after <see cref="UpdateExposure"/>.</summary>
        public float[] Exposure { get; }
        /// <summary>How many times the exposure has been computed (for tests and statistics).</summary>
        public int ExposureUpdates { get; private set; }

        public int Resolution => _settings.resolution;

        public SnowSettings Settings
        {
            get => _settings;
            set
            {
                value.Validate();
                if (value.resolution != _settings.resolution)
                    throw new ArgumentException(FormattableString.Invariant(
                        $"snow.resolution ({value.resolution}) cannot change from {_settings.resolution}: make a new simulation"), "snow.resolution");
                _settings = value;
            }
        }

        public SnowSimulation(SnowSettings settings)
        {
            settings.Validate();
            _settings = settings;
            Depth = new float[settings.resolution * settings.resolution];
            Exposure = new float[settings.resolution * settings.resolution];
        }

        /// <summary>
        /// True when the exposure must be recomputed before the next step: never computed, the snowfall
        /// direction or the march settings changed, or the field is another one or has changed since.
        /// </summary>
        public bool NeedsExposureUpdate(SnowField field)
        {
            CheckField(field);
            return !_exposureValid || !ReferenceEquals(field, _exposureField) || field.Version != _exposureFieldVersion
                || !_settings.ExposureEquals(_exposureSettings);
        }

        /// <summary>Computes L for every cell.</summary>
        public void UpdateExposure(SnowField field)
        {
            CheckField(field);
            SnowParams p = _settings.Params(0f);
            int r = Resolution;
            for (int j = 0; j < r; j++)
                for (int i = 0; i < r; i++)
                    Exposure[j * r + i] = SnowExposure.Evaluate(field.Data, i, j, p.snowGrid, p.snowFall, p.ExposureSoftness);
            _exposureValid = true;
            _exposureSettings = _settings;
            _exposureField = field;
            _exposureFieldVersion = field.Version;
            ExposureUpdates++;
        }

        /// <summary>Advances the depth map by dt seconds (recomputing the exposure first if it is stale).</summary>
        public void Step(SnowField field, float dt)
        {
            CheckField(field);
            SnowParams p = _settings.Params(dt);  // validates dt before anything changes
            if (NeedsExposureUpdate(field)) UpdateExposure(field);
            int r = Resolution;
            for (int j = 0; j < r; j++)
                for (int i = 0; i < r; i++)
                {
                    int k = j * r + i;
                    float rate = SnowAccumulation.RateAt(field.Data, i, j, Exposure[k], p.snowGrid, p.snowCatch, p.snowEdge);
                    Depth[k] = SnowAccumulation.Step(Depth[k], rate, dt, p.DepthCap, p.MeltRate);
                }
        }

        /// <summary>Clears the depth map (the exposure stays valid).</summary>
        public void Clear() => Array.Clear(Depth, 0, Depth.Length);

        void CheckField(SnowField field)
        {
            if (field == null) throw new ArgumentException("field (null) must be a snow field", nameof(field));
            if (field.Resolution != Resolution)
                throw new ArgumentException(FormattableString.Invariant(
                    $"field.Resolution ({field.Resolution}) must equal snow.resolution ({Resolution})"), nameof(field));
        }
    }
}
