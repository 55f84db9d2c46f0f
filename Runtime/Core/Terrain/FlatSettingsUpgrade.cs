namespace GregoryTerrain
{
    /// <summary>
    /// Scenes saved before the renderer's settings were Core structs hold them as flat fields (<c>tiles</c>,
    /// <c>noiseAmplitude</c>, ...). FormerlySerializedAs renames a field at its own level only, so the
    /// renderer keeps the old fields hidden at Unset unless loaded data wrote them, and moves each one set
    /// into its struct after every load.
    /// </summary>
    internal static class FlatSettingsUpgrade
    {
        /// <summary>An old field the loaded data did not hold. Not NaN: Unity compares prefab values, and NaN never equals itself.</summary>
        public const int UnsetInt = int.MinValue;
        public const float UnsetFloat = float.MinValue;

        /// <summary>Each old field's serialized name and its path now, in <see cref="Move"/>'s order: the load and the editor's prefab override upgrade both read it.</summary>
        public static readonly (string old, string now)[] Paths =
        {
            ("tiles", "tessellation.tiles"), ("maxFactor", "tessellation.maxFactor"),
            ("targetPixelError", "tessellation.targetPixels"), ("uniformFactor", "tessellation.uniformFactor"),
            ("noiseAmplitude", "noise.amplitude"), ("noiseFrequency", "noise.frequency"),
            ("noiseAlpha", "noise.alpha"), ("noiseBeta", "noise.beta"), ("noiseOctaves", "noise.octaves"),
            ("colorGamma", "heightColor.gamma"), ("colorNoiseAmplitude", "heightColor.noiseAmplitude"),
            ("colorNoiseFrequency", "heightColor.noiseFrequency"),
        };

        /// <summary>The path now of an old field's serialized <paramref name="path"/>, or null when it is not an old field.</summary>
        public static string PathNow(string path)
        {
            foreach (var (old, now) in Paths)
                if (old == path) return now;
            return null;
        }

        /// <summary>Moves each set old field (named as it was serialized) into its struct field and unsets it; true when any moved.</summary>
        public static bool Move(ref TessellationSettings tessellation, ref NoiseSettings noise, ref HeightColorSettings heightColor,
            ref int tiles, ref float maxFactor, ref float targetPixelError, ref int uniformFactor,
            ref float noiseAmplitude, ref float noiseFrequency, ref float noiseAlpha, ref float noiseBeta, ref int noiseOctaves,
            ref float colorGamma, ref float colorNoiseAmplitude, ref float colorNoiseFrequency)
        {
            bool moved = Take(ref tiles, ref tessellation.tiles) | Take(ref maxFactor, ref tessellation.maxFactor)
                | Take(ref targetPixelError, ref tessellation.targetPixels) | Take(ref uniformFactor, ref tessellation.uniformFactor);
            moved |= Take(ref noiseAmplitude, ref noise.amplitude) | Take(ref noiseFrequency, ref noise.frequency)
                | Take(ref noiseAlpha, ref noise.alpha) | Take(ref noiseBeta, ref noise.beta) | Take(ref noiseOctaves, ref noise.octaves);
            return moved | Take(ref colorGamma, ref heightColor.gamma) | Take(ref colorNoiseAmplitude, ref heightColor.noiseAmplitude)
                | Take(ref colorNoiseFrequency, ref heightColor.noiseFrequency);
        }

        static bool Take(ref int old, ref int now)
        {
            if (old == UnsetInt) return false;
            now = old; old = UnsetInt;
            return true;
        }

        static bool Take(ref int old, ref float now)
        {
            if (old == UnsetInt) return false;
            now = old; old = UnsetInt;
            return true;
        }

        static bool Take(ref float old, ref float now)
        {
            if (old == UnsetFloat) return false;
            now = old; old = UnsetFloat;
            return true;
        }
    }
}
