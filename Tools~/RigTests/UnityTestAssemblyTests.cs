using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.Json;
using System.Xml.Linq;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>
    /// The Unity-side test assemblies (Tests/Runtime, Tests/Editor) are declared the way Unity's Test
    /// Runner finds them: only with UNITY_INCLUDE_TESTS (a project lists the package under
    /// "testables"), NUnit as the precompiled nunit.framework.dll, the two TestRunner assemblies, not
    /// referenced by user code; editor tests for the Editor only. The check projects in
    /// Tools~/UnityApiCheck compile them under the same assembly names (InternalsVisibleTo depends on it).
    /// </summary>
    [TestFixture]
    public class UnityTestAssemblyTests
    {
        /// <summary>What is wrong with one test asmdef, empty when nothing is.</summary>
        internal static List<string> Problems(string json, bool editorOnly)
        {
            var p = new List<string>();
            using var doc = JsonDocument.Parse(json);
            JsonElement root = doc.RootElement;
            string[] Strings(string key) => root.TryGetProperty(key, out JsonElement e) && e.ValueKind == JsonValueKind.Array
                ? e.EnumerateArray().Select(x => x.GetString()).ToArray() : new string[0];
            bool Flag(string key) => root.TryGetProperty(key, out JsonElement e) && e.ValueKind == JsonValueKind.True;

            if (!Strings("defineConstraints").Contains("UNITY_INCLUDE_TESTS")) p.Add("defineConstraints lacks UNITY_INCLUDE_TESTS");
            foreach (string r in new[] { "UnityEngine.TestRunner", "UnityEditor.TestRunner", "GregoryTerrain.Runtime" })
                if (!Strings("references").Contains(r)) p.Add($"references lacks {r}");
            if (!Flag("overrideReferences")) p.Add("overrideReferences must be true (for the precompiled NUnit)");
            if (!Strings("precompiledReferences").Contains("nunit.framework.dll")) p.Add("precompiledReferences lacks nunit.framework.dll");
            if (!root.TryGetProperty("autoReferenced", out JsonElement auto) || auto.ValueKind != JsonValueKind.False) p.Add("autoReferenced must be false");
            string[] platforms = Strings("includePlatforms");
            if (editorOnly && !(platforms.Length == 1 && platforms[0] == "Editor")) p.Add("includePlatforms must be [\"Editor\"]");
            if (!editorOnly && platforms.Length != 0) p.Add("includePlatforms must be empty (Edit Mode and Play Mode)");
            return p;
        }

        static string AsmdefName(string json)
        {
            using var doc = JsonDocument.Parse(json);
            return doc.RootElement.GetProperty("name").GetString();
        }

        [TestCase("Runtime", false, "TestsRuntimeCheck")]
        [TestCase("Editor", true, "TestsEditorCheck")]
        public void TestAssemblyIsDeclaredForTheTestRunner(string folder, bool editorOnly, string checkProject)
        {
            string[] asmdefs = Directory.GetFiles(PackageRoot.Combine("Tests", folder), "*.asmdef");
            Assert.That(asmdefs.Length, Is.EqualTo(1), $"one asmdef in Tests/{folder}");
            string json = File.ReadAllText(asmdefs[0]);
            Assert.That(Problems(json, editorOnly), Is.Empty, asmdefs[0]);

            string project = PackageRoot.Combine("Tools~", "UnityApiCheck", checkProject, checkProject + ".csproj");
            XDocument x = XDocument.Load(project);
            Assert.That(x.Descendants("AssemblyName").Single().Value, Is.EqualTo(AsmdefName(json)), "the check compiles it under the asmdef's name");
            Assert.That(x.Descendants("Compile").Select(c => c.Attribute("Include").Value), Does.Contain($"$(PkgRoot)Tests/{folder}/**/*.cs"));
            Assert.That(File.ReadAllText(PackageRoot.Combine("Tools~", "UnityApiCheck", "UnityApiCheck.csproj")), Does.Contain("TestsEditorCheck/TestsEditorCheck.csproj"),
                "the API check builds the test projects");
            Assert.That(File.ReadAllText(PackageRoot.Combine("Runtime", "AssemblyInfo.cs")), Does.Contain($"InternalsVisibleTo(\"{AsmdefName(json)}\")"));
        }

        /// <summary>
        /// Tests/Runtime fixtures that can fail in a player for want of the shader: a Shader.Find
        /// anywhere in the assembly (a player finds only shaders its content or Always Included
        /// Shaders hold), or a fixture that makes a TestTerrain without [EditorOnly].
        /// </summary>
        internal static List<string> PlayerShaderProblems(IDictionary<string, string> files)
        {
            var p = new List<string>();
            foreach (var f in files)
            {
                string code = System.Text.RegularExpressions.Regex.Replace(f.Value, @"//[^\n]*", "");
                if (code.Contains("Shader.Find(")) p.Add($"{f.Key}: Shader.Find");
                if (code.Contains("new TestTerrain(") && !System.Text.RegularExpressions.Regex.IsMatch(code, @"\[EditorOnly\]\s*(?:public\s+)?class"))
                    p.Add($"{f.Key}: a fixture making a TestTerrain is not [EditorOnly]");
            }
            return p;
        }

        [Test]
        public void RuntimeTestsFindTheShaderWhereTheyRun()
        {
            var files = Directory.GetFiles(PackageRoot.Combine("Tests", "Runtime"), "*.cs").ToDictionary(Path.GetFileName, File.ReadAllText);
            Assert.That(PlayerShaderProblems(files), Is.Empty);
            string testTerrain = files["TestTerrain.cs"];
            string guid = File.ReadAllLines(PackageRoot.Combine("Shaders", "GregoryTerrain.shader.meta")).Single(l => l.StartsWith("guid:")).Substring(5).Trim();
            Assert.That(testTerrain, Does.Contain($"\"{guid}\""), "TestTerrain loads Shaders/GregoryTerrain.shader by its GUID");
            Assert.That(testTerrain, Does.Match(@"EditorOnlyAttribute\s*:\s*UnityEngine\.TestTools\.UnityPlatformAttribute"));
            Assert.That(testTerrain, Does.Contain("RuntimePlatform.WindowsEditor, RuntimePlatform.OSXEditor, RuntimePlatform.LinuxEditor"));
        }

        [Test]
        public void PlayerShaderCheckRejectsShaderFind()
        {
            var old = new Dictionary<string, string>
            {
                ["TestTerrain.cs"] = "public TestTerrain() { Shader shader = Shader.Find(\"GregoryTerrain/Terrain\"); }",
                ["RendererQueryTests.cs"] = "public class RendererQueryTests { [SetUp] public void SetUp() { _t = new TestTerrain(); } }",
            };
            Assert.That(PlayerShaderProblems(old), Is.EqualTo(new[] { "TestTerrain.cs: Shader.Find", "RendererQueryTests.cs: a fixture making a TestTerrain is not [EditorOnly]" }));
            Assert.That(PlayerShaderProblems(new Dictionary<string, string> { ["A.cs"] = "[EditorOnly] // why\n    public class A { void S() { _t = new TestTerrain(); } }" }), Is.Empty);
        }

        [Test]
        public void AsmdefCheckRejectsAPlainAssembly()
        {
            // A test asmdef written like a runtime one: always compiled, no NUnit, on every platform.
            string plain = "{ \"name\": \"X.Tests\", \"references\": [\"GregoryTerrain.Runtime\"], \"includePlatforms\": [], " +
                           "\"overrideReferences\": false, \"autoReferenced\": true, \"defineConstraints\": [] }";
            Assert.That(Problems(plain, editorOnly: true).Count, Is.EqualTo(7), string.Join("; ", Problems(plain, true)));
        }
    }
}
