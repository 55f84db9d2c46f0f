using System;

namespace GregoryTerrain
{
    /// <summary>
    /// Eq. 14-15's parameters: gamma (height per unit of colour blend) and the colour noise l
    /// (amplitude, frequency). Uploaded as <c>_HeightColor = (gamma, amplitude, frequency, 0)</c>;
    /// the colours themselves go in <c>_ColorLow</c> (C) and <c>_ColorHigh</c> (B).
    /// </summary>
    [Serializable]
    public struct HeightColorSettings : IEquatable<HeightColorSettings>
    {
        /// <summary>Height over which the colour goes from the low to the high colour (terrain units, not 0).</summary>
        public float gamma;
        /// <summary>Strength of the noise that breaks up the colour boundary (0 turns it off).</summary>
        public float noiseAmplitude;
        /// <summary>Lattice cells of that colour noise across the whole terrain (&gt; 0).</summary>
        public float noiseFrequency;

        /// <summary>Settings with the given values; call <see cref="Validate"/> to check them.</summary>
        public HeightColorSettings(float gamma, float noiseAmplitude, float noiseFrequency)
        {
            this.gamma = gamma; this.noiseAmplitude = noiseAmplitude; this.noiseFrequency = noiseFrequency;
        }

        /// <summary>Throws <see cref="ArgumentException"/> unless gamma is finite and not 0, and the noise
        /// amplitude finite and its frequency finite, positive and below 2^24.</summary>
        public void Validate(string name = "heightColor")
        {
            if (!GMath.isfinite(gamma) || gamma == 0f)
                throw new ArgumentException(FormattableString.Invariant($"{name}.gamma ({gamma:R}) must be finite and not 0"), name + ".gamma");
            if (!GMath.isfinite(noiseAmplitude))
                throw new ArgumentException(FormattableString.Invariant($"{name}.noiseAmplitude ({noiseAmplitude:R}) must be finite"), name + ".noiseAmplitude");
            if (!GMath.isfinite(noiseFrequency) || !(noiseFrequency > 0f) || !(noiseFrequency < 16777216f))
                throw new ArgumentException(FormattableString.Invariant(
                    $"{name}.noiseFrequency ({noiseFrequency:R}) must be finite, greater than 0 and below 2^24"), name + ".noiseFrequency");
        }

        /// <summary><c>_HeightColor = (gamma, noiseAmplitude, noiseFrequency, 0)</c>.</summary>
        internal Float4 ToFloat4() => new Float4(gamma, noiseAmplitude, noiseFrequency, 0f);

        /// <inheritdoc/>
        public bool Equals(HeightColorSettings o) => gamma.Equals(o.gamma) && noiseAmplitude.Equals(o.noiseAmplitude) && noiseFrequency.Equals(o.noiseFrequency);
        /// <inheritdoc/>
        public override bool Equals(object obj) => obj is HeightColorSettings o && Equals(o);
        /// <inheritdoc/>
        public override int GetHashCode() => HashCode.Combine(gamma, noiseAmplitude, noiseFrequency);
        /// <inheritdoc/>
        public override string ToString() => FormattableString.Invariant($"gamma {gamma:R}, noise amplitude {noiseAmplitude:R}, frequency {noiseFrequency:R}");
    }
}
