using System;
using System.Collections.Generic;

namespace GregoryTerrain
{
    /// <summary>A Core settings struct's field in the Inspector: Core cannot name Unity's [Tooltip] or [Range].</summary>
    internal readonly struct SettingField
    {
        public readonly string name;
        public readonly string label, tooltip;
        /// <summary>The slider's limits, inside what Validate accepts; whole: an int slider.</summary>
        public readonly float min, max;
        public readonly bool whole;

        public SettingField(string name, string label, string tooltip, float min, float max, bool whole = false)
        {
            this.name = name; this.label = label; this.tooltip = tooltip; this.min = min; this.max = max; this.whole = whole;
        }
    }

    /// <summary>The fields of the renderer's settings structs, and their Validate messages.</summary>
    internal static class SettingFields
    {
        public static readonly SettingField[] Tessellation =
        {
            new SettingField("tiles", "Tiles", "Tiles per side of the drawn area. More tiles draw more detail at the same max factor; fewer, larger tiles draw the same triangles faster.", 1, 64, whole: true),
            new SettingField("maxFactor", "Max Factor", "Most subdivisions of a tile edge (at most 64). Caps the triangle count.", 1f, 64f),
            new SettingField("targetPixels", "Target Pixel Error", "How far, in pixels, the drawn triangles may stray from the surface (like Unity Terrain's Pixel Error). Halving it about doubles the triangles.", 0.25f, 64f),
            new SettingField("uniformFactor", "Uniform Factor", "0: subdivide each tile edge by its size on screen. Above 0: subdivide every edge this many times (for testing and measuring).", 0, 64, whole: true),
        };

        public static readonly SettingField[] Noise =
        {
            new SettingField("amplitude", "Noise Amplitude", "Height of the largest noise layer, in terrain height units (the inspector shows metres: times Height Scale).", 0f, 0.5f),
            new SettingField("frequency", "Noise Frequency", "Noise cells across the whole terrain in the largest noise layer (the inspector shows one cell's width in metres).", 0.5f, 4096f),
            new SettingField("alpha", "Noise Alpha", "How much finer each noise layer is than the one before it (2: twice as fine).", 1.1f, 8f),
            new SettingField("beta", "Noise Beta", "How much weaker each noise layer is than the one before it (2: half the height).", 1.1f, 8f),
            new SettingField("octaves", "Noise Octaves", "Most noise layers added. Layers finer than the mesh can show are left out.", 0, 16, whole: true),
        };

        public static readonly SettingField[] HeightColor =
        {
            new SettingField("gamma", "Color Gamma", "Height over which the colour blends from the low colour to the high colour, in terrain height units (the inspector shows metres).", 0.001f, 4f),
            new SettingField("noiseAmplitude", "Color Noise Amplitude", "How strongly noise breaks up the boundary between the low and high colours.", 0f, 1f),
            new SettingField("noiseFrequency", "Color Noise Frequency", "Noise cells across the whole terrain for the colour noise (the inspector shows one cell's width in metres).", 0.5f, 4096f),
        };

        /// <summary>The first selected object's whose settings Validate refuses, named when more than one is selected; null when all are valid.</summary>
        public static string Problem(IReadOnlyList<(string name, object settings)> selected)
        {
            foreach (var (name, settings) in selected)
                if (Problem(settings) is string problem) return selected.Count > 1 ? $"{name}: {problem}" : problem;
            return null;
        }

        /// <summary>Validate's message for a settings struct (naming field and value), or null when valid or another type.</summary>
        public static string Problem(object settings)
        {
            try
            {
                switch (settings)
                {
                    case TessellationSettings t: t.Validate(); break;
                    case NoiseSettings n: n.Validate(); break;
                    case HeightColorSettings h: h.Validate(); break;
                }
                return null;
            }
            catch (ArgumentException e) { return e.Message; }
        }
    }
}
