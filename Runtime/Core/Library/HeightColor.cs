using System;

namespace GregoryTerrain
{
    /// <summary>
    /// Height colour, eq. 14-15: <c>s = saturate(l + z / gamma)</c>, <c>colour = high * s + low * (1 - s)</c>
    /// (B and C of the paper, linear RGB), with l the colour noise from <see cref="ColorNoise(TerrainPoint, HeightColorSettings, TerrainKeywords)"/>.
    /// Mirrored by Shaders/Library/HeightColor.hlsl (<c>HeightColor.Weight</c> is HLSL <c>HeightColorWeight</c>, etc.).
    /// </summary>
    internal static class HeightColor
    {
        /// <summary>The noise stream of the colour noise: distinct from every octave's (0 .. 15).</summary>
        public const uint ColorStream = 0x436F6C72u;

        /// <summary>Eq. 14: <c>s = saturate(l + z / gamma)</c>. Gamma is a height: z = gamma moves s by 1.</summary>
        public static float Weight(float l, float z, float gamma)
        {
            CheckGamma(gamma);
            return GMath.saturate(l + z / gamma);
        }

        /// <summary>Eq. 15: <c>high * s + low * (1 - s)</c>, with s from <see cref="Weight"/>.</summary>
        public static Float3 Blend(float l, float z, float gamma, Float3 low, Float3 high)
        {
            return OfWeight(Weight(l, z, gamma), low, high);
        }

        /// <summary>
        /// Eq. 15 alone: the colour of a weight s already computed. The shader computes s per vertex and
        /// interpolates it (one interpolant with the normal, internals.md "Varyings").
        /// </summary>
        public static Float3 OfWeight(float s, Float3 low, Float3 high)
        {
            return high * s + low * (1f - s);
        }

        /// <summary>
        /// The colour noise l: one octave of <see cref="GradientNoise"/> at its own frequency and offset,
        /// times its own amplitude (internals.md <c>_HeightColor</c>). Deep-zoom safe like the height noise.
        /// </summary>
        public static float ColorNoise(TerrainPoint p, HeightColorSettings settings, TerrainKeywords keywords = TerrainKeywords.None)
        {
            settings.Validate(nameof(settings));
            return settings.noiseAmplitude * GradientNoise.AtPoint(p, settings.noiseFrequency, GradientNoise.StreamOffset(ColorStream), out _, keywords);
        }

        /// <summary>
        /// HLSL <c>HeightColorNoiseAtLocal</c>: <see cref="ColorNoise(TerrainPoint, HeightColorSettings, TerrainKeywords)"/>
        /// of a point whose originHi is 0, bit for bit, without TwoProduct (what the tessellated stages
        /// draw without the range origin's code).
        /// </summary>
        public static float ColorNoiseAtLocal(Float2 local, HeightColorSettings settings, TerrainKeywords keywords = TerrainKeywords.None)
        {
            settings.Validate(nameof(settings));
            return settings.noiseAmplitude * GradientNoise.AtLocal(local, settings.noiseFrequency, GradientNoise.StreamOffset(ColorStream), out _, keywords);
        }

        /// <summary>The double reference of <see cref="ColorNoise(TerrainPoint, HeightColorSettings, TerrainKeywords)"/>.</summary>
        public static double ColorNoise(double x, double y, HeightColorSettings settings, TerrainKeywords keywords = TerrainKeywords.None)
        {
            settings.Validate(nameof(settings));
            Double2 off = GradientNoise.StreamOffset(ColorStream);
            double f = settings.noiseFrequency;
            return settings.noiseAmplitude * GradientNoise.Evaluate(f * x + off.x, f * y + off.y, out _, keywords);
        }

        static void CheckGamma(float gamma)
        {
            if (!GMath.isfinite(gamma) || gamma == 0f)
                throw new ArgumentException(FormattableString.Invariant($"gamma ({gamma:R}) must be finite and not 0"), nameof(gamma));
        }
    }
}
