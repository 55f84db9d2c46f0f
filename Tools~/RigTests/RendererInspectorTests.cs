using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>
    /// The renderer's inspector names its fields as strings (SerializedObject.FindProperty): a
    /// misspelt name is a null property and an exception in the editor, a field left out is a
    /// setting users cannot reach. Every serialized field of GregoryTerrainRenderer must be drawn
    /// exactly once, and every name drawn must be a serialized field.
    /// </summary>
    [TestFixture]
    public class RendererInspectorTests
    {
        static readonly Regex SerializedField = new Regex(@"\[SerializeField[^\]]*\]\s*[\w<>\[\].]+\s+(\w+)\s*[=;]");
        static readonly Regex PublicField = new Regex(@"^\s*public\s+(?!static\b|const\b|readonly\b|event\b)[\w<>\[\].]+\s+(\w+)\s*(?:=[^;>]*)?;", RegexOptions.Multiline);
        static readonly Regex FieldsCall = new Regex(@"\bFields\s*\(([^)]*)\)");
        static readonly Regex Literal = new Regex(@"""(\w+)""");

        static List<string> RendererFields()
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

        static string EditorSource() => File.ReadAllText(PackageRoot.Combine("Editor", "GregoryTerrainRendererEditor.cs"));

        /// <summary>What is wrong between the fields and the editor source's Fields("...") calls.</summary>
        public static List<string> Problems(IReadOnlyCollection<string> fields, string editorSource)
        {
            var drawn = FieldsCall.Matches(editorSource)
                .SelectMany(m => Literal.Matches(m.Groups[1].Value).Select(l => l.Groups[1].Value)).ToList();
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
            var problems = Problems(fields, EditorSource());
            Assert.That(problems, Is.Empty, string.Join("\n", problems));
        }

        [Test]
        public void AMisspeltOrMissingFieldIsCaught()
        {
            var fields = RendererFields();
            string source = EditorSource();
            Assert.That(source, Does.Contain("\"targetPixelError\""));
            Assert.That(Problems(fields, source.Replace("\"targetPixelError\"", "\"targetPixelErr\"")),
                Is.EquivalentTo(new[] { "field targetPixelError is not drawn", "\"targetPixelErr\" is drawn but is no serialized field" }));
            Assert.That(Problems(fields, source.Replace("\"cacheShader\", ", "")), Is.EquivalentTo(new[] { "field cacheShader is not drawn" }));
            Assert.That(Problems(fields, source.Replace("Fields(\"tiles\"", "Fields(\"grid\", \"tiles\"")), Is.EquivalentTo(new[] { "\"grid\" is drawn 2 times" }));
        }
    }
}
