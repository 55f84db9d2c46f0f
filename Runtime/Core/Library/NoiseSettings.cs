using System;

namespace GregoryTerrain
{
    /// <summary>
    /// The octave noise of eq. 12-13 generalised to N octaves: amplitude, base frequency (lattice
    /// cells per terrain unit), alpha (frequency ratio between octaves) and beta (amplitude ratio).
    /// Stored as the floats the GPU gets: <c>_Noise = (amplitude, frequency, alpha, beta)</c>,
    /// <c>_NoiseOctaves.x = octaves</c>.
    /// </summary>
    [Serializable]
    public struct NoiseSettings : IEquatable<NoiseSettings>
    {
        /// <summary>The most octaves a shader loop runs.</summary>
        public const int MaxOctaves = 16;

        /// <summary>Height of the first octave, terrain units.</summary>
        public float amplitude;
        /// <summary>Lattice cells of the first octave across the whole terrain (&gt; 0).</summary>
        public float frequency;
        /// <summary>Frequency ratio between one octave and the next (&gt; 1).</summary>
        public float alpha;
        /// <summary>Amplitude divisor between one octave and the next (&gt; 0).</summary>
        public float beta;
        /// <summary>Most octaves evaluated (0 to <see cref="MaxOctaves"/>); fewer are used where the vertices are too sparse to show them.</summary>
        public int octaves;

        /// <summary>Settings with the given values; call <see cref="Validate"/> to check them.</summary>
        public NoiseSettings(float amplitude, float frequency, float alpha, float beta, int octaves)
        {
            this.amplitude = amplitude; this.frequency = frequency; this.alpha = alpha; this.beta = beta; this.octaves = octaves;
        }

        /// <summary>The paper's setting: 4 octaves, each at twice the frequency and half the amplitude.</summary>
        public static NoiseSettings Default => new NoiseSettings(0.01f, 8f, 2f, 2f, 4);

        /// <summary>
        /// Throws <see cref="ArgumentException"/> unless amplitude is finite, frequency finite and
        /// positive, alpha finite and &gt; 1, beta finite and &gt; 0, octaves in [0, 16], and the finest
        /// octave's frequency stays finite and below 2^24 cells per unit (so lattice cells stay exact in float).
        /// </summary>
        public void Validate(string name = "noise")
        {
            if (!GMath.isfinite(amplitude)) throw Bad(name + ".amplitude", amplitude, "must be finite");
            if (!GMath.isfinite(frequency) || !(frequency > 0f)) throw Bad(name + ".frequency", frequency, "must be finite and greater than 0");
            if (!GMath.isfinite(alpha) || !(alpha > 1f)) throw Bad(name + ".alpha", alpha, "must be finite and greater than 1");
            if (!GMath.isfinite(beta) || !(beta > 0f)) throw Bad(name + ".beta", beta, "must be finite and greater than 0");
            if (octaves < 0 || octaves > MaxOctaves)
                throw new ArgumentException(FormattableString.Invariant($"{name}.octaves ({octaves}) must lie in [0, {MaxOctaves}]"), name + ".octaves");
            float f = frequency;
            for (int k = 1; k < octaves; k++) f *= alpha;
            if (octaves > 0 && !(f < 16777216f))
                throw new ArgumentException(FormattableString.Invariant(
                    $"{name}.frequency ({frequency:R}) * {name}.alpha ({alpha:R})^{octaves - 1} = {f:R} must stay below 2^24"), name + ".alpha");
        }

        static ArgumentException Bad(string field, float value, string what) =>
            new ArgumentException(FormattableString.Invariant($"{field} ({value:R}) {what}"), field);

        /// <summary><c>_Noise = (amplitude, frequency, alpha, beta)</c>.</summary>
        internal Float4 ToFloat4() => new Float4(amplitude, frequency, alpha, beta);

        /// <inheritdoc/>
        public bool Equals(NoiseSettings o) => amplitude.Equals(o.amplitude) && frequency.Equals(o.frequency)
            && alpha.Equals(o.alpha) && beta.Equals(o.beta) && octaves == o.octaves;
        /// <inheritdoc/>
        public override bool Equals(object obj) => obj is NoiseSettings o && Equals(o);
        /// <inheritdoc/>
        public override int GetHashCode() => HashCode.Combine(amplitude, frequency, alpha, beta, octaves);
        /// <inheritdoc/>
        public override string ToString() => FormattableString.Invariant(
            $"amplitude {amplitude:R}, frequency {frequency:R}, alpha {alpha:R}, beta {beta:R}, octaves {octaves}");
    }
}
