using System;
using System.Collections.Generic;

namespace GregoryTerrain
{
    /// <summary>The inspector's View mode: Horizon levels, one range, or one range a Zoom Range Controller sets.</summary>
    internal enum TerrainViewMode { OpenWorld, SingleRange, Zoom }

    internal enum QualityPreset { Low, Medium, High, Ultra }

    /// <summary>Heights are times the Height Scale; cells across become a cell's width; a part of the width its metres.</summary>
    internal enum TerrainLength { Height, CellsAcross, Width }

    /// <summary>What a quality preset writes (vertexEvaluation: 0 domain stage, 1 compute cache).</summary>
    internal readonly struct QualityValues : IEquatable<QualityValues>
    {
        public readonly float targetPixelError, maxFactor;
        public readonly int tiles, noiseOctaves, vertexEvaluation;

        public QualityValues(float targetPixelError, float maxFactor, int tiles, int noiseOctaves, int vertexEvaluation)
        {
            this.targetPixelError = targetPixelError; this.maxFactor = maxFactor;
            this.tiles = tiles; this.noiseOctaves = noiseOctaves; this.vertexEvaluation = vertexEvaluation;
        }

        public QualityValues WithVertexEvaluation(int v) => new QualityValues(targetPixelError, maxFactor, tiles, noiseOctaves, v);

        public bool Equals(QualityValues o) => targetPixelError == o.targetPixelError && maxFactor == o.maxFactor
            && tiles == o.tiles && noiseOctaves == o.noiseOctaves && vertexEvaluation == o.vertexEvaluation;

        public override bool Equals(object obj) => obj is QualityValues o && Equals(o);

        public override int GetHashCode() => HashCode.Combine(targetPixelError, maxFactor, tiles, noiseOctaves, vertexEvaluation);
    }

    /// <summary>What decides which fields take effect for one renderer (adaptive: uniform factor 0; fallback: no tessellator).</summary>
    internal readonly struct InspectorContext
    {
        public readonly TerrainViewMode mode;
        public readonly bool adaptive, computeCache, fallback;

        public InspectorContext(TerrainViewMode mode, bool adaptive, bool computeCache, bool fallback)
        {
            this.mode = mode; this.adaptive = adaptive; this.computeCache = computeCache; this.fallback = fallback;
        }
    }

    /// <summary>The renderer inspector apart from drawing: every serialized field once, where each takes effect, presets, metres.</summary>
    internal static class RendererInspectorLayout
    {
        /// <summary>Drawn as the View mode popup.</summary>
        public const string ViewModeField = "horizonLevels";

        public static readonly (string title, bool open, string[] fields)[] Sections =
        {
            ("Content", true, new[] { "grid", "material", "terrainSize", "heightScale", "range" }),
            ("Tessellation", true, new[] { ViewModeField, "tessellation.tiles", "tessellation.uniformFactor", "tessellation.maxFactor", "tessellation.targetPixels", "anchorTiles", "fallbackGridFactor" }),
            ("Vertex evaluation", true, new[] { "vertexEvaluation", "cacheShader", "lodCamera" }),
            ("Noise and colour", false, new[] { "noise.amplitude", "noise.frequency", "noise.alpha", "noise.beta", "noise.octaves", "noiseVerticesAcross",
                                                "heightColor.gamma", "heightColor.noiseAmplitude", "heightColor.noiseFrequency", "colorLow", "colorHigh" }),
            ("Lighting", false, new[] { "shadowCasting", "receiveShadows" }),
            ("Debug", false, new[] { "debugShowControlPoints", "debugShowPatchWireframe" }),
        };

        /// <summary>The renderer's settings structs: its field name, the struct's fields (a section lists them as "field.name").</summary>
        public static readonly (string field, SettingField[] fields)[] Structs =
        {
            ("tessellation", SettingFields.Tessellation), ("noise", SettingFields.Noise), ("heightColor", SettingFields.HeightColor),
        };

        /// <summary>The struct field a path such as "tessellation.tiles" names, or null for a plain renderer field.</summary>
        public static SettingField? Find(string path)
        {
            int dot = path.IndexOf('.');
            if (dot < 0) return null;
            string head = path.Substring(0, dot), tail = path.Substring(dot + 1);
            foreach (var (field, fields) in Structs)
                if (field == head)
                    foreach (SettingField f in fields)
                        if (f.name == tail) return f;
            return null;
        }

        /// <summary>Whether <paramref name="field"/> changes what is drawn (the renderer's LevelsOn, AnchorsTiles, VertexCachePass.UpdateFrame).</summary>
        public static bool Shows(string field, InspectorContext c)
        {
            bool tessellates = !c.fallback, levels = c.mode == TerrainViewMode.OpenWorld && tessellates;
            switch (field)
            {
                case "range": return c.mode == TerrainViewMode.SingleRange || (c.mode == TerrainViewMode.OpenWorld && c.fallback);
                case "tessellation.uniformFactor": return tessellates;
                case "tessellation.maxFactor": case "tessellation.targetPixels": return tessellates && c.adaptive;
                case "anchorTiles": return tessellates && c.adaptive && !levels;
                case "fallbackGridFactor": return c.fallback;
                case "vertexEvaluation": return tessellates && !levels;
                case "cacheShader": case "lodCamera": return tessellates && !levels && c.computeCache;
                default: return true;
            }
        }

        public static bool ShowsForAny(string field, IReadOnlyList<InspectorContext> contexts)
        {
            foreach (InspectorContext c in contexts)
                if (Shows(field, c)) return true;
            return contexts.Count == 0;
        }

        public static List<string> FieldsShown(InspectorContext c)
        {
            var shown = new List<string>();
            foreach (var s in Sections)
                foreach (string f in s.fields)
                    if (Shows(f, c)) shown.Add(f);
            return shown;
        }

        /// <summary>Medium: a new renderer's defaults; tiles even, at least 8; Ultra's 0.5 px: the manual's advice for about 1 px.</summary>
        public static QualityValues Preset(QualityPreset p)
        {
            switch (p)
            {
                case QualityPreset.Low: return new QualityValues(16f, 32f, 8, 4, 0);
                case QualityPreset.Medium: return new QualityValues(8f, 64f, 16, 6, 0);
                case QualityPreset.High: return new QualityValues(2f, 64f, 16, 8, 0);
                case QualityPreset.Ultra: return new QualityValues(0.5f, 64f, 32, 12, 1);
                default: throw new ArgumentException($"preset ({(int)p}) must be Low, Medium, High or Ultra", nameof(p));
            }
        }

        /// <summary>Vertex evaluation aside (<see cref="PresetToWrite"/>).</summary>
        public static QualityPreset? PresetOf(QualityValues v)
        {
            for (var p = QualityPreset.Low; p <= QualityPreset.Ultra; p++)
                if (Preset(p).WithVertexEvaluation(v.vertexEvaluation).Equals(v)) return p;
            return null;
        }

        /// <summary>Compute cache only with a Cache Shader; Open world's hidden Vertex evaluation kept.</summary>
        public static QualityValues PresetToWrite(QualityPreset p, QualityValues current, bool cacheShaderSet, bool openWorld)
        {
            QualityValues v = Preset(p);
            if (openWorld) return v.WithVertexEvaluation(current.vertexEvaluation);
            return cacheShaderSet ? v : v.WithVertexEvaluation(0);
        }

        /// <summary>Null when they differ.</summary>
        public static TerrainViewMode? CommonMode(IReadOnlyList<TerrainViewMode> modes)
        {
            for (int k = 1; k < modes.Count; k++)
                if (modes[k] != modes[0]) return null;
            return modes.Count > 0 ? modes[0] : (TerrainViewMode?)null;
        }

        public static string LengthProblem(string label, double metres) =>
            metres > 0.0 ? null : $"{label} must be above 0 (typed {metres:G6}); value kept.";

        public static TerrainViewMode ModeOf(bool horizonLevels, bool zoomControlled) =>
            horizonLevels ? TerrainViewMode.OpenWorld : zoomControlled ? TerrainViewMode.Zoom : TerrainViewMode.SingleRange;

        /// <summary>Open world's tiles: even and at least <see cref="LodLevels.MinTiles"/>.</summary>
        public static int TilesForOpenWorld(int tiles) => Math.Max(LodLevels.MinTiles, tiles + (tiles & 1));

        /// <summary>Terrain-unit lengths, their labels in metres and their stored slider limits (SettingFields).</summary>
        public static readonly (string field, TerrainLength kind, string label, float min, float max)[] MetreFields =
        {
            Metres("noise.amplitude", TerrainLength.Height, "Noise amplitude (m)"),
            Metres("noise.frequency", TerrainLength.CellsAcross, "Noise cell size (m)"),
            Metres("heightColor.gamma", TerrainLength.Height, "Colour blend height (m)"),
            Metres("heightColor.noiseFrequency", TerrainLength.CellsAcross, "Colour noise cell size (m)"),
        };

        static (string, TerrainLength, string, float, float) Metres(string path, TerrainLength kind, string label)
        {
            SettingField f = Find(path) ?? throw new ArgumentException($"{path} is no settings struct field", nameof(path));
            return (path, kind, label, f.min, f.max);
        }

        /// <summary>Camera Range Controller's side of the square: a part of the terrain's width, shown in metres.</summary>
        public static readonly (string field, TerrainLength kind, string label, float min, float max) ViewDistanceField =
            ("viewDistance", TerrainLength.Width, "Range side (m)", 0.0001f, 1f);

        public static double ToMetres(TerrainLength kind, double value, double metresPerHeightUnit, double widthMetres) =>
            kind == TerrainLength.Height ? value * metresPerHeightUnit : kind == TerrainLength.Width ? value * widthMetres : widthMetres / value;

        public static double FromMetres(TerrainLength kind, double metres, double metresPerHeightUnit, double widthMetres) =>
            kind == TerrainLength.Height ? metres / metresPerHeightUnit : kind == TerrainLength.Width ? metres / widthMetres : widthMetres / metres;

        /// <summary>The stored value for typed metres, inside [min, max]; a cell size of 0 or less is the finest.</summary>
        public static float ClampedFromMetres(TerrainLength kind, double metres, double metresPerHeightUnit, double widthMetres, float min, float max)
        {
            if (kind == TerrainLength.CellsAcross && !(metres > 0.0)) return max;
            double v = FromMetres(kind, metres, metresPerHeightUnit, widthMetres);
            return double.IsNaN(v) ? min : (float)Math.Min(max, Math.Max(min, v));
        }
    }
}
