using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>
    /// Inspector tooltips are plain words of one or two lines: no longer than <see cref="MaxLength"/>
    /// characters, no equation numbers and no symbols of the paper's notation (Greek letter names,
    /// single-letter quantities, powers, index ranges). That detail belongs in Documentation~/index.md.
    /// </summary>
    [TestFixture]
    public class TooltipTextTests
    {
        /// <summary>About two lines of Unity's tooltip box.</summary>
        public const int MaxLength = 160;

        static readonly (string rule, Regex pattern)[] Notation =
        {
            ("equation number", new Regex(@"\beq\.|\bequations?\b", RegexOptions.IgnoreCase)),
            ("Greek letter", new Regex(@"\b(alpha|beta|gamma|delta|epsilon|zeta|eta|theta|kappa|lambda|mu|nu|xi|pi|rho|sigma|tau|phi|chi|psi|omega)\b|[\u0370-\u03FF]", RegexOptions.IgnoreCase)),
            ("power", new Regex(@"\^")),
            ("index range or interval", new Regex(@"\[\s*\w\s*,\s*\w\s*\]|\[\s*\w+\s*\.\.\s*\w+\s*\]")),
            // A lone capital letter standing for a quantity (M tiles, F the factor); "shortcut G" and
            // "Shift+G" name keys, "A" and "I" are words.
            ("single-letter symbol", new Regex(@"(?<!\b(?:key|shortcut) )(?<![\w.'/+-])[B-HJ-Z](?![\w'])")),
        };

        static readonly Regex TooltipAttribute = new Regex(@"\[\s*(?:[\w.]+(?:\([^)]*\))?\s*,\s*)*Tooltip\s*\(\s*""((?:[^""\\]|\\.)*)""\s*\)");

        /// <summary>The tooltip of a Core settings struct's field (Editor/Authoring/SettingFields.cs: Core cannot name [Tooltip]).</summary>
        static readonly Regex SettingFieldTooltip = new Regex(@"new\s+SettingField\(\s*""[^""]*""\s*,\s*""[^""]*""\s*,\s*""((?:[^""\\]|\\.)*)""");

        /// <summary>Every [Tooltip("...")] text and SettingField tooltip in Runtime/ and Editor/, with its file.</summary>
        static List<(string file, string text)> PackageTooltips()
        {
            var found = new List<(string, string)>();
            foreach (string folder in new[] { "Runtime", "Editor" })
            foreach (string path in Directory.GetFiles(PackageRoot.Combine(folder), "*.cs", SearchOption.AllDirectories))
            {
                string code = File.ReadAllText(path);
                var texts = TooltipAttribute.Matches(code).Select(m => m.Groups[1].Value).ToList();
                // Every Tooltip attribute must be read: one written another way would escape the checks.
                int written = Regex.Matches(code, @"\bTooltip\s*\(").Count;
                Assert.That(texts.Count, Is.EqualTo(written), $"{path}: {written} Tooltip attributes, {texts.Count} read as a plain string");
                var fieldTexts = SettingFieldTooltip.Matches(code).Select(m => m.Groups[1].Value).ToList();
                int fieldsWritten = Regex.Matches(code, @"\bnew\s+SettingField\(").Count;
                Assert.That(fieldTexts.Count, Is.EqualTo(fieldsWritten), $"{path}: {fieldsWritten} SettingFields, {fieldTexts.Count} tooltips read as a plain string");
                found.AddRange(texts.Concat(fieldTexts).Select(t => (Path.GetRelativePath(PackageRoot.Path, path), t)));
            }
            return found;
        }

        /// <summary>What is wrong with one tooltip text, or an empty list.</summary>
        public static List<string> Problems(string text)
        {
            var problems = new List<string>();
            if (text.Length > MaxLength) problems.Add($"{text.Length} characters (at most {MaxLength})");
            foreach (var (rule, pattern) in Notation)
            {
                Match m = pattern.Match(text);
                if (m.Success) problems.Add($"{rule} \"{m.Value}\"");
            }
            return problems;
        }

        [Test]
        public void TooltipsAreShortAndInPlainWords()
        {
            var tooltips = PackageTooltips();
            Assert.That(tooltips.Count, Is.GreaterThanOrEqualTo(50), "too few tooltips found: is the scan still reading the sources?");
            var bad = tooltips.Select(t => (t.file, t.text, problems: Problems(t.text)))
                .Where(t => t.problems.Count > 0)
                .Select(t => $"{t.file}: {string.Join("; ", t.problems)}: \"{t.text}\"").ToList();
            Assert.That(bad, Is.Empty, string.Join("\n", bad));
        }

        // The rules on texts the old inspector had: each must be caught.
        [TestCase("alpha (eq. 12): frequency ratio between octaves.")]
        [TestCase("Part of the terrain drawn: [c, g] x [d, h] inside [0, 1]^2.")]
        [TestCase("C (eq. 15): colour at low heights.")]
        [TestCase("Fallback only: each tile is a fixed (F+1) x (F+1) vertex grid.")]
        [TestCase("Vertical grid lines x[0..n], strictly increasing from 0 to 1.")]
        public void NotationIsCaught(string text) =>
            Assert.That(Problems(text), Is.Not.Empty, text);

        [TestCase("Draw the patch boundaries in the Scene view (shortcut Shift+G in the Scene view by default).")]
        [TestCase("Draw the control points in the Scene view (shortcut G in the Scene view by default).")]
        [TestCase("How far, in pixels, the drawn triangles may stray from the surface (like Unity Terrain's Pixel Error).")]
        public void PlainWordsPass(string text) =>
            Assert.That(Problems(text), Is.Empty, string.Join("; ", Problems(text)));

        [Test]
        public void LengthIsCaught() =>
            Assert.That(Problems(new string('a', MaxLength + 1)), Has.Some.Contains("characters"));
    }
}
