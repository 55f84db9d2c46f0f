using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>
    /// The renderer's inspector names its fields as strings (SerializedObject.FindProperty), listed
    /// once in RendererInspectorLayout.Sections: a misspelt name is a null property and an exception
    /// in the editor, a field left out is a setting users cannot reach. Every serialized field of
    /// GregoryTerrainRenderer must be listed exactly once, every name listed must be a serialized
    /// field, and the inspector must draw the sections from that list.
    /// </summary>
    [TestFixture]
    public class RendererInspectorTests
    {
        static readonly Regex SerializedField = new Regex(@"\[SerializeField[^\]]*\]\s*[\w<>\[\].]+\s+(\w+)\s*[=;]");
        static readonly Regex PublicField = new Regex(@"^\s*public\s+(?!static\b|const\b|readonly\b|event\b)[\w<>\[\].]+\s+(\w+)\s*(?:=[^;>]*)?;", RegexOptions.Multiline);

        internal static List<string> RendererFields()
        {
            var names = new List<string>();
            foreach (string path in Directory.GetFiles(PackageRoot.Combine("Runtime"), "GregoryTerrainRenderer*.cs"))
            {
                string code = File.ReadAllText(path);
                names.AddRange(SerializedField.Matches(code).Select(m => m.Groups[1].Value));
                names.AddRange(PublicField.Matches(code).Select(m => m.Groups[1].Value));
            }
            return names;
        }

        static List<string> Listed() => RendererInspectorLayout.Sections.SelectMany(s => s.fields).ToList();

        static string EditorSource() => File.ReadAllText(PackageRoot.Combine("Editor", "GregoryTerrainRendererEditor.cs"));

        /// <summary>What is wrong between the fields and the names the inspector draws.</summary>
        public static List<string> Problems(IReadOnlyCollection<string> fields, IReadOnlyList<string> drawn)
        {
            var problems = new List<string>();
            problems.AddRange(fields.Where(f => !drawn.Contains(f)).Select(f => $"field {f} is not drawn"));
            problems.AddRange(drawn.Where(d => !fields.Contains(d)).Distinct().Select(d => $"\"{d}\" is drawn but is no serialized field"));
            problems.AddRange(drawn.GroupBy(d => d).Where(g => g.Count() > 1).Select(g => $"\"{g.Key}\" is drawn {g.Count()} times"));
            return problems;
        }

        [Test]
        public void EveryRendererFieldIsDrawnOnce()
        {
            var fields = RendererFields();
            Assert.That(fields, Has.Count.GreaterThanOrEqualTo(25), "too few serialized fields found: is the scan still reading the renderer?");
            Assert.That(fields, Does.Contain("grid").And.Contain("debugShowPatchWireframe"));
            var problems = Problems(fields, Listed());
            Assert.That(problems, Is.Empty, string.Join("\n", problems));
            // The editor draws the listed sections and names no field of its own (PropertyField by a literal).
            string source = EditorSource();
            Assert.That(source, Does.Contain("RendererInspectorLayout.Sections"));
            Assert.That(Regex.Matches(source, @"FindProperty\(""(\w+)""\)").Select(m => m.Groups[1].Value).Where(n => !fields.Contains(n)), Is.Empty,
                "a FindProperty literal in the editor that is no serialized field");
        }

        [Test]
        public void AMisspeltOrMissingFieldIsCaught()
        {
            var fields = RendererFields();
            var listed = Listed();
            Assert.That(listed, Does.Contain("targetPixelError"));
            Assert.That(Problems(fields, listed.Select(f => f == "targetPixelError" ? "targetPixelErr" : f).ToList()),
                Is.EquivalentTo(new[] { "field targetPixelError is not drawn", "\"targetPixelErr\" is drawn but is no serialized field" }));
            Assert.That(Problems(fields, listed.Where(f => f != "cacheShader").ToList()), Is.EquivalentTo(new[] { "field cacheShader is not drawn" }));
            Assert.That(Problems(fields, listed.Append("grid").ToList()), Is.EquivalentTo(new[] { "\"grid\" is drawn 2 times" }));
        }
    }
}
