using System;

namespace GregoryTerrain
{
    /// <summary>
    /// How the range is tessellated: M x M tiles, the adaptive policy's limits, or a uniform factor.
    /// Stored as the GPU gets it: <c>_Tess = (tiles, maxFactor, targetPixels (pixel error), uniformFactor)</c>.
    /// </summary>
    [Serializable]
    public struct TessellationSettings : IEquatable<TessellationSettings>
    {
        /// <summary>The hardware's largest tessellation factor (D3D11, Vulkan, Metal).</summary>
        public const float HardwareMaxFactor = 64f;

        /// <summary>M: the range is covered by M x M tile patches.</summary>
        public int tiles;
        /// <summary>The largest edge factor the adaptive policy may pick, in [1, 64].</summary>
        public float maxFactor;
        /// <summary>
        /// The adaptive knob: target screen-space error in pixels (like Unity Terrain's Pixel Error).
        /// Each tile edge gets the factor whose chord error, seen from its worst side, is this many
        /// pixels (<see cref="TessellationPolicy.ErrorTessFactor"/>), at most <see cref="maxFactor"/>.
        /// </summary>
        public float targetPixels;
        /// <summary>When &gt; 0, every edge and inside factor is this (tests, benchmarks, the fallback grid).</summary>
        public float uniformFactor;

        /// <summary>Settings with the given values; call <see cref="Validate"/> to check them.</summary>
        public TessellationSettings(int tiles, float maxFactor, float targetPixels, float uniformFactor)
        {
            this.tiles = tiles; this.maxFactor = maxFactor; this.targetPixels = targetPixels; this.uniformFactor = uniformFactor;
        }

        /// <summary>The renderer's defaults: 16 x 16 tiles, max factor 64, 8 pixels of error, adaptive factors.</summary>
        public static TessellationSettings Default => new TessellationSettings(16, 64f, 8f, 0f);

        /// <summary>A uniform factor F over M x M tiles.</summary>
        public static TessellationSettings Uniform(int tiles, float factor) => new TessellationSettings(tiles, factor, 8f, factor);

        /// <summary>True when every edge gets <see cref="uniformFactor"/> instead of an adaptive factor.</summary>
        public bool IsUniform => uniformFactor > 0f;

        /// <summary>Throws ArgumentException (naming <paramref name="name"/>, the field and its value) unless tiles lie in [1, 1024], maxFactor in [1, 64], targetPixels is finite and positive and uniformFactor is 0 or in [1, 64].</summary>
        public void Validate(string name = "tessellation")
        {
            if (tiles < 1 || tiles > 1024)
                throw new ArgumentException(FormattableString.Invariant($"{name}.tiles ({tiles}) must lie in [1, 1024]"), name + ".tiles");
            if (!(maxFactor >= 1f && maxFactor <= HardwareMaxFactor))
                throw new ArgumentException(FormattableString.Invariant($"{name}.maxFactor ({maxFactor:R}) must lie in [1, 64]"), name + ".maxFactor");
            if (!(targetPixels > 0f) || !GMath.isfinite(targetPixels))
                throw new ArgumentException(FormattableString.Invariant($"{name}.targetPixels ({targetPixels:R}) must be finite and greater than 0"), name + ".targetPixels");
            if (!(uniformFactor == 0f || (uniformFactor >= 1f && uniformFactor <= HardwareMaxFactor)))
                throw new ArgumentException(FormattableString.Invariant($"{name}.uniformFactor ({uniformFactor:R}) must be 0 (adaptive) or lie in [1, 64]"), name + ".uniformFactor");
        }

        internal Float4 ToFloat4() => new Float4(tiles, maxFactor, targetPixels, uniformFactor);

        /// <inheritdoc/>
        public bool Equals(TessellationSettings o) => tiles == o.tiles && maxFactor.Equals(o.maxFactor)
            && targetPixels.Equals(o.targetPixels) && uniformFactor.Equals(o.uniformFactor);
        /// <inheritdoc/>
        public override bool Equals(object obj) => obj is TessellationSettings o && Equals(o);
        /// <inheritdoc/>
        public override int GetHashCode() => HashCode.Combine(tiles, maxFactor, targetPixels, uniformFactor);
    }
}
