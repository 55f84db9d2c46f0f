using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>
    /// The limits and defaults the manual quotes are the code's: each quote is read from its page
    /// (api.md, index.md, troubleshooting.md) and the value it names from the C# that holds it (a
    /// field's [Range] or [Min], its initialiser, a setter's Mathf.Clamp, a constant), and the two
    /// must be equal. Each pattern must match exactly once on both sides, so a quote reworded or a
    /// field renamed fails here instead of passing unchecked.
    /// </summary>
    [TestFixture]
    public class ManualQuotesTests
    {
        /// <summary>One quoted fact: its page and pattern, the source and pattern that hold it; the groups are the values, in order.</summary>
        public sealed class Quote
        {
            public string Name, Page, PagePattern, Source, SourcePattern;
            public override string ToString() => Name;
        }

        const string Renderer = "Runtime/GregoryTerrainRenderer.cs";
        const string Fields = "Editor/Authoring/SettingFields.cs";   // the settings structs' sliders
        static string Slider(string field, string bound) => @"new SettingField\(""" + field + @""", ""[^""]*"", ""[^""]*"", " + bound + ", " + bound + @"\b";
        const string Number = @"(-?\d+(?:\.\d+)?)";
        const string Float = @"(-?\d+(?:\.\d+)?)f";

        internal static readonly Quote[] Quotes =
        {
            new Quote { Name = "Tiles range (api.md)", Page = "Documentation~/api.md", PagePattern = @"\| `Tiles` \| Tiles per side M \(" + Number + " to " + Number + @"\)",
                        Source = Fields, SourcePattern = Slider("tiles", Number) },
            new Quote { Name = "Tiles setter clamp (api.md)", Page = "Documentation~/api.md", PagePattern = @"\| `Tiles` \| Tiles per side M \(" + Number + " to " + Number + @"\)",
                        Source = Renderer, SourcePattern = @"public int Tiles \{[^\n]*Mathf\.Clamp\(value, " + Number + ", " + Number + @"\)" },
            new Quote { Name = "Tiles range (troubleshooting.md)", Page = "Documentation~/troubleshooting.md", PagePattern = @"\| renderer settings \| tiles " + Number + @"\.\." + Number,
                        Source = Fields, SourcePattern = Slider("tiles", Number) },
            new Quote { Name = "Uniform factor range (api.md)", Page = "Documentation~/api.md", PagePattern = @"\| `UniformFactor` \| [^|\n]*\(" + Number + " to " + Number + @"\)",
                        Source = Fields, SourcePattern = Slider("uniformFactor", Number) },
            new Quote { Name = "Max factor range (index.md)", Page = "Documentation~/index.md", PagePattern = @"cap on a tile edge's tessellation factor \(" + Number + "-" + Number + @"\)",
                        Source = Fields, SourcePattern = Slider("maxFactor", Float) },
            new Quote { Name = "Target pixel error range (index.md)", Page = "Documentation~/index.md", PagePattern = @"\| Target pixel error \| [^|\n]*?, " + Number + " to " + Number + ", default [-0-9.]+;",
                        Source = Fields, SourcePattern = Slider("targetPixels", Float) },
            new Quote { Name = "Target pixel error default (index.md)", Page = "Documentation~/index.md", PagePattern = @"\| Target pixel error \| [^|\n]*?, [-0-9.]+ to [-0-9.]+, default " + Number + ";",
                        Source = "Runtime/Core/Terrain/TessellationSettings.cs", SourcePattern = @"TessellationSettings Default => new TessellationSettings\([^,]+, [^,]+, " + Float + ", " },
            new Quote { Name = "Terrain Size default (index.md)", Page = "Documentation~/index.md", PagePattern = @"\| Content \| Terrain Size \| [^|\n]*Default \(" + Number + ", " + Number + @"\)",
                        Source = Renderer, SourcePattern = @"Vector2 terrainSize = new Vector2\(" + Float + ", " + Float + @"\);" },
            new Quote { Name = "Height Scale default (index.md)", Page = "Documentation~/index.md", PagePattern = @"\| Content \| Height Scale \| metres per terrain height unit \(Unity y\); default " + Number,
                        Source = Renderer, SourcePattern = @"float heightScale = " + Float + ";" },
            new Quote { Name = "Noise first octave default (index.md)", Page = "Documentation~/index.md", PagePattern = @"the renderer's default first octave, " + Number + " cells across",
                        Source = Renderer, SourcePattern = @"NoiseSettings noise = new NoiseSettings\([^,]+, " + Float + ", " },
            new Quote { Name = "Collider samples range and default (api.md)", Page = "Documentation~/api.md", PagePattern = @"\| `Samples` \| Samples per side, " + Number + " to " + Number + @" \(default " + Number + @"\)",
                        Source = "Runtime/GregoryTerrainCollider.cs", SourcePattern = @"Range\(" + Number + ", " + Number + @"\)\] int samples = " + Number + ";" },
            new Quote { Name = "Collider spacing minimum and default (api.md)", Page = "Documentation~/api.md", PagePattern = @"\| `Spacing` \| [^|\n]*\(at least " + Number + "; default " + Number + @"\)",
                        Source = "Runtime/GregoryTerrainCollider.cs", SourcePattern = @"Min\(" + Float + @"\)\] float spacing = " + Float + ";" },
            new Quote { Name = "Patch Grid window side (index.md)", Page = "Documentation~/index.md", PagePattern = @"\| Columns, rows \| grid size n x m used by the buttons \(" + Number + " to " + Number + " a side",
                        Source = "Editor/PatchGridWindow.cs", SourcePattern = @"Columns \(n\)"", ""Patches along x \(" + Number + " to " + Number + @"\)" },
            new Quote { Name = "Patch Grid window side constant (index.md)", Page = "Documentation~/index.md", PagePattern = @"\| Columns, rows \| grid size n x m used by the buttons \(1 to " + Number + " a side",
                        Source = "Editor/PatchGridWindow.cs", SourcePattern = @"const int MaxSide = " + Number + ";" },
            new Quote { Name = "Patch Grid window metres per height unit default (index.md)", Page = "Documentation~/index.md", PagePattern = @"\| Metres per height unit \| [^|\n]*\(default " + Number,
                        Source = "Editor/PatchGridWindow.cs", SourcePattern = @"float metresPerHeightUnit = " + Float + ";" },
            new Quote { Name = "Anchor tiles default (index.md)", Page = "Documentation~/index.md", PagePattern = @"\| Tessellation \| Anchor tiles \| (on|off) \(default\)",
                        Source = Renderer, SourcePattern = @"bool anchorTiles = (true|false);" },
            new Quote { Name = "Horizon levels default (index.md)", Page = "Documentation~/index.md", PagePattern = @"\| Tessellation \| Horizon levels \| (on|off) \(default\)",
                        Source = Renderer, SourcePattern = @"bool horizonLevels( = true| = false)?;" },
            new Quote { Name = "Vertex evaluation default (index.md)", Page = "Documentation~/index.md", PagePattern = @"^- \*\*(Domain stage|Compute cache)\*\* \(default\)",
                        Source = Renderer, SourcePattern = @"VertexEvaluation vertexEvaluation = VertexEvaluation\.(\w+);" },
        };

        static string Read(string relative) => File.ReadAllText(PackageRoot.Combine(relative.Split('/'))).Replace("\r\n", "\n");

        /// <summary>The groups of the pattern's one match in <paramref name="text"/>; fails unless it matches exactly once.</summary>
        internal static string[] Values(string text, string pattern, string where)
        {
            var matches = Regex.Matches(text, pattern, RegexOptions.Multiline);
            Assert.That(matches.Count, Is.EqualTo(1), $"{where}: /{pattern}/ must match once (reworded? then update {nameof(ManualQuotesTests)})");
            return matches[0].Groups.Cast<Group>().Skip(1).Select(g => Normalise(g.Value)).ToArray();
        }

        /// <summary>One spelling per value: numbers as invariant decimals; on/true, off/false/none; "Domain stage" and DomainStage alike.</summary>
        internal static string Normalise(string v)
        {
            v = v.Trim();
            if (v.StartsWith("=", StringComparison.Ordinal)) v = v.Substring(1).Trim();
            if (double.TryParse(v, NumberStyles.Float, CultureInfo.InvariantCulture, out double d)) return d.ToString("R", CultureInfo.InvariantCulture);
            switch (v)
            {
                case "on": case "true": return "true";
                case "off": case "false": case "": return "false";
            }
            return v.Replace(" ", "").ToLowerInvariant();
        }

        [TestCaseSource(nameof(Quotes))]
        public void TheManualQuotesTheCodesValue(Quote q)
        {
            string[] quoted = Values(Read(q.Page), q.PagePattern, q.Page);
            string[] code = Values(Read(q.Source), q.SourcePattern, q.Source);
            Assert.That(quoted, Is.EqualTo(code), $"{q.Name}: {q.Page} quotes ({string.Join(", ", quoted)}), {q.Source} holds ({string.Join(", ", code)})");
        }

        /// <summary>No page calls a vertex evaluation "the default" other than the renderer's initialiser.</summary>
        [Test]
        public void NoPageCallsAnotherVertexEvaluationTheDefault()
        {
            string code = Values(Read(Renderer), @"VertexEvaluation vertexEvaluation = VertexEvaluation\.(\w+);", Renderer)[0];
            var wrong = new List<string>();
            foreach (string page in Directory.GetFiles(PackageRoot.Combine("Documentation~"), "*.md").Append(PackageRoot.Combine("README.md")))
                foreach (Match m in Regex.Matches(File.ReadAllText(page), @"(?i)\b(domain stage|compute cache)\b[^.|(\n]{0,40}\((the )?default\)"))
                    if (Normalise(m.Groups[1].Value) != code) wrong.Add($"{Path.GetFileName(page)}: \"{m.Value}\"");
            Assert.That(wrong, Is.Empty, $"the renderer's default vertex evaluation is {code}");
        }

        [Test]
        public void AChangedQuoteIsFound()
        {
            Quote tiles = Quotes[0];
            string page = "| `Tiles` | Tiles per side M (1 to 1024). |";
            Assert.That(Values(page, tiles.PagePattern, "edited"), Is.EqualTo(new[] { "1", "1024" }));
            Assert.That(Values("new SettingField(\"tiles\", \"Tiles\", \"Tiles per side.\", 1, 64, whole: true),", tiles.SourcePattern, "edited"), Is.EqualTo(new[] { "1", "64" }));
            Assert.That(Normalise("0.25"), Is.EqualTo(Normalise("0.250")));
            Assert.That(Normalise("Domain stage"), Is.EqualTo(Normalise("DomainStage")));
            Assert.That(Regex.Matches("| `Tiles` | Tiles per side M. |", tiles.PagePattern).Count, Is.EqualTo(0), "a reworded quote matches nothing (Values then fails)");
        }
    }
}
