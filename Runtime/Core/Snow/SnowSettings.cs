using System;

namespace GregoryTerrain
{
    /// <summary>
    /// The wind-driven snow effect's parameters (Moriya and Takahashi's eq. 1,
    /// <c>D(x) = s L(x, w) (N . Gn) max(1 - E(x), 0)</c>), in terrain space: the unit square in
    /// <c>(x, y)</c>, <c>z</c> up, heights and depths in the same units, time in seconds.
    /// <para>
    /// <b>Sign convention.</b> <see cref="gravity"/> points the way things fall (default
    /// <c>(0, 0, -1)</c>). The paper's <c>Gn</c> is the vector <i>opposite</i> to gravity, so
    /// <c>Gn = -normalize(gravity)</c> (default <c>(0, 0, 1)</c>) and the catch term is
    /// <c>saturate(dot(N, Gn))</c> with <c>N</c> the upward detail normal: 1 on level ground, 0 on a
    /// smooth vertical face or an overhang.
    /// </para>
    /// <para>
    /// <b>Snowfall direction.</b> A flake moves with velocity
    /// <c>V = (wind.x, wind.y, 0) + fallSpeed * normalize(gravity)</c>. It arrives at x from upwind,
    /// along <c>-V</c>; the elevation of that arrival direction above the horizontal is the
    /// <i>fall angle</i> F (<c>sin F = -V.z / |V|</c>, <c>cos F = |V.xy| / |V|</c>). With no wind
    /// F = 90 degrees and nothing shields anything.
    /// </para>
    /// </summary>
    [Serializable]
    public struct SnowSettings : IEquatable<SnowSettings>
    {
        /// <summary>Limits <see cref="Validate"/> enforces: the snow map resolution R (64 to 4096) and the exposure march samples (at most 256).</summary>
        public const int MinResolution = 64, MaxResolution = 4096, MaxRaySteps = 256;

        /// <summary>Snow map cells per side, R (power of two, 64..4096). The map covers the whole unit square.</summary>
        public int resolution;
        /// <summary>s of eq. 1: depth per second on fully exposed level ground (terrain height units / s).</summary>
        public float scale;
        /// <summary>Horizontal wind velocity in terrain (x, y), terrain units per second. Zero: snow falls straight.</summary>
        public Float2 wind;
        /// <summary>How fast a flake falls in still air (terrain units per second, &gt; 0).</summary>
        public float fallSpeed;
        /// <summary>Direction of gravity (any length &gt; 0, normalised here); z must be negative: the height field is z-up.</summary>
        public Float3 gravity;
        /// <summary>Strength of the edge term E at a sharp crest (0 turns it off; above 1 clears crests completely).</summary>
        public float edgeStrength;
        /// <summary>Crest sharpness (drop in slope across one cell, dimensionless) at which E reaches <see cref="edgeStrength"/>.</summary>
        public float edgeWidth;
        /// <summary>Largest snow depth (terrain height units, &gt; 0).</summary>
        public float depthCap;
        /// <summary>Depth lost per second everywhere (&gt;= 0).</summary>
        public float meltRate;
        /// <summary>How far upwind the exposure march looks (terrain units, (0, 2]).</summary>
        public float rayLength;
        /// <summary>Samples along the exposure march (1..256).</summary>
        public int raySteps;
        /// <summary>Width of the shielded-to-exposed transition, in sin(angle) above the fall line ((0, 1]).</summary>
        public float exposureSoftness;

        /// <summary>A light snowfall with a moderate wind along +x on a 512 map.</summary>
        public static SnowSettings Default => new SnowSettings
        {
            resolution = 512, scale = 0.0005f, wind = new Float2(1f, 0f), fallSpeed = 1f,
            gravity = new Float3(0f, 0f, -1f), edgeStrength = 1f, edgeWidth = 0.5f, depthCap = 0.02f,
            meltRate = 0f, rayLength = 0.25f, raySteps = 32, exposureSoftness = 0.1f,
        };

        /// <summary>Gn of eq. 1: the unit vector opposite to gravity.</summary>
        public Float3 Up => -1f * GMath.normalize(gravity);

        /// <summary>Flake velocity V (see the type's summary).</summary>
        public Float3 SnowVelocity => new Float3(wind.x, wind.y, 0f) + fallSpeed * GMath.normalize(gravity);

        /// <summary>
        /// The march as the shaders get it: <c>(upwind.x, upwind.y, cos F, sin F)</c>, upwind the unit
        /// horizontal direction the snow comes from. With no horizontal motion: <c>(0, 0, 0, 1)</c>.
        /// </summary>
        internal Float4 FallLine
        {
            get
            {
                Float3 v = SnowVelocity;
                float horizontal = (float)Math.Sqrt((double)v.x * v.x + (double)v.y * v.y);
                if (!(horizontal > 0f)) return new Float4(0f, 0f, 0f, 1f);
                float speed = GMath.length(v);
                // Never divide by the horizontal speed when it is tiny: cos F is then tiny too and the
                // march still points somewhere finite.
                return new Float4(-v.x / horizontal, -v.y / horizontal, horizontal / speed, -v.z / speed);
            }
        }

        /// <summary>True when the exposure computed for <paramref name="o"/> is valid for these settings too.</summary>
        public bool ExposureEquals(SnowSettings o) =>
            resolution == o.resolution && wind.Equals(o.wind) && fallSpeed.Equals(o.fallSpeed) && gravity.Equals(o.gravity) &&
            rayLength.Equals(o.rayLength) && raySteps == o.raySteps && exposureSoftness.Equals(o.exposureSoftness);

        /// <summary>Throws <see cref="ArgumentException"/> naming the field and its value unless every field is in range.</summary>
        public void Validate(string name = "snow")
        {
            if (resolution < MinResolution || resolution > MaxResolution || (resolution & (resolution - 1)) != 0)
                throw Bad(name, "resolution", resolution, "must be a power of two from 64 to 4096");
            if (!GMath.isfinite(scale) || scale < 0f) throw Bad(name, "scale", scale, "must be finite and >= 0");
            if (!wind.IsFinite) throw Bad(name, "wind", wind, "must be finite");
            if (!GMath.isfinite(fallSpeed) || !(fallSpeed > 0f)) throw Bad(name, "fallSpeed", fallSpeed, "must be finite and > 0");
            if (!gravity.IsFinite || !(gravity.z < 0f) || !(GMath.length(gravity) > 0f))
                throw Bad(name, "gravity", gravity, "must be finite with z < 0 (the height field is z-up)");
            if (!GMath.isfinite(edgeStrength) || edgeStrength < 0f) throw Bad(name, "edgeStrength", edgeStrength, "must be finite and >= 0");
            if (!GMath.isfinite(edgeWidth) || !(edgeWidth > 0f)) throw Bad(name, "edgeWidth", edgeWidth, "must be finite and > 0");
            if (!GMath.isfinite(depthCap) || !(depthCap > 0f)) throw Bad(name, "depthCap", depthCap, "must be finite and > 0");
            if (!GMath.isfinite(meltRate) || meltRate < 0f) throw Bad(name, "meltRate", meltRate, "must be finite and >= 0");
            if (!GMath.isfinite(rayLength) || !(rayLength > 0f) || rayLength > 2f) throw Bad(name, "rayLength", rayLength, "must be in (0, 2]");
            if (raySteps < 1 || raySteps > MaxRaySteps) throw Bad(name, "raySteps", raySteps, "must be from 1 to 256");
            if (!GMath.isfinite(exposureSoftness) || !(exposureSoftness > 0f) || exposureSoftness > 1f)
                throw Bad(name, "exposureSoftness", exposureSoftness, "must be in (0, 1]");
            Float3 v = SnowVelocity;
            if (!v.IsFinite || !(v.z < 0f)) throw Bad(name, "fallSpeed", fallSpeed, "with this gravity must make snow fall (velocity z < 0)");
        }

        static ArgumentException Bad(string name, string field, object value, string rule) =>
            new ArgumentException(FormattableString.Invariant($"{name}.{field} ({value}) {rule}"), name + "." + field);

        /// <summary>
        /// The <see cref="SnowParams"/> constants of a step of <paramref name="dt"/> seconds (0 for the
        /// exposure alone). Validates the settings and dt, naming the field and value; allocates nothing.
        /// </summary>
        internal SnowParams Params(float dt)
        {
            Validate();
            if (!GMath.isfinite(dt) || dt < 0f) throw new ArgumentException(FormattableString.Invariant($"dt ({dt:R}) must be finite and >= 0"), nameof(dt));
            Float3 up = Up;
            return new SnowParams
            {
                snowGrid = new Float4(resolution, 1f / resolution, rayLength, raySteps),
                snowFall = FallLine,
                snowCatch = new Float4(up.x, up.y, up.z, scale),
                snowEdge = new Float4(edgeStrength, edgeWidth, exposureSoftness, 0f),
                snowStep = new Float4(dt, depthCap, meltRate, 0f),
            };
        }

        /// <inheritdoc/>
        public bool Equals(SnowSettings o) => ExposureEquals(o) && scale.Equals(o.scale) && edgeStrength.Equals(o.edgeStrength) &&
            edgeWidth.Equals(o.edgeWidth) && depthCap.Equals(o.depthCap) && meltRate.Equals(o.meltRate);
        /// <inheritdoc/>
        public override bool Equals(object obj) => obj is SnowSettings o && Equals(o);
        /// <inheritdoc/>
        public override int GetHashCode() => HashCode.Combine(resolution, wind, fallSpeed, gravity, scale, depthCap, rayLength, raySteps);
        /// <inheritdoc/>
        public override string ToString() => FormattableString.Invariant(
            $"snow R {resolution}, s {scale:R}, wind {wind}, fall {fallSpeed:R}, cap {depthCap:R}, melt {meltRate:R}");
    }
}
