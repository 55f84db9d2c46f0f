using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.Json;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>
    /// package.json lists every built-in module whose types the package's C# uses (Runtime, Editor,
    /// Samples~, Tests): a project that has disabled one in the Package Manager would otherwise fail
    /// to compile the package. Each module's types are the ones its folder of UnityCsReference 2022.3
    /// declares (Modules/Physics, Modules/Terrain, Modules/IMGUI, Modules/JSONSerialize,
    /// Modules/ImageConversion).
    /// </summary>
    [TestFixture]
    public class PackageDependencyTests
    {
        /// <summary>Built-in module package -> a pattern matching a use of one of its types.</summary>
        internal static readonly Dictionary<string, string> ModuleUses = new Dictionary<string, string>
        {
            ["com.unity.modules.physics"] = @"\b(?:MeshCollider|MeshColliderCookingOptions|Rigidbody|SphereCollider|BoxCollider|CapsuleCollider|RaycastHit|PhysicMaterial|Physics\s*\.)",
            // Terrain as a type (a local, field or parameter of it), not a member named Terrain.
            ["com.unity.modules.terrain"] = @"(?<![\w.])(?:TerrainData|TerrainCollider|TerrainLayer)\b|(?<![\w.])Terrain(?:\[\])?\s+[a-z_]\w*\s*[=;,)]",
            ["com.unity.modules.imgui"] = @"(?<![\w.])(?:GUILayout|GUIContent|GUIStyle|GUIUtility|GUISkin|GUI\s*\.|Event\s*\.\s*current)\b",
            ["com.unity.modules.jsonserialize"] = @"\bJsonUtility\b",
            ["com.unity.modules.imageconversion"] = @"\b(?:ImageConversion|EncodeToPNG|EncodeToJPG|LoadImage)\b",
        };

        static string StripComments(string code) =>
            Regex.Replace(code, @"//[^\n]*|/\*.*?\*/", "", RegexOptions.Singleline);

        /// <summary>Modules whose types <paramref name="sources"/> use that <paramref name="dependencies"/> lacks, each with a file using it.</summary>
        internal static List<string> MissingModules(IDictionary<string, string> sources, IDictionary<string, string> dependencies)
        {
            var missing = new List<string>();
            foreach (var module in ModuleUses)
            {
                string user = sources.Where(f => Regex.IsMatch(StripComments(f.Value), module.Value)).Select(f => f.Key).FirstOrDefault();
                if (user == null) continue;
                if (!dependencies.TryGetValue(module.Key, out string version)) missing.Add($"{module.Key} (used in {user})");
                else if (version != "1.0.0") missing.Add($"{module.Key}: version {version}, a built-in module is 1.0.0");
            }
            return missing;
        }

        static Dictionary<string, string> PackageSources() =>
            new[] { "Runtime", "Editor", "Samples~", Path.Combine("Tests", "Runtime"), Path.Combine("Tests", "Editor") }
                .SelectMany(d => Directory.GetFiles(PackageRoot.Combine(d), "*.cs", SearchOption.AllDirectories))
                .ToDictionary(f => Path.GetRelativePath(PackageRoot.Path, f), File.ReadAllText);

        static Dictionary<string, string> Dependencies()
        {
            using var doc = JsonDocument.Parse(File.ReadAllText(PackageRoot.Combine("package.json")));
            return doc.RootElement.TryGetProperty("dependencies", out JsonElement d)
                ? d.EnumerateObject().ToDictionary(p => p.Name, p => p.Value.GetString()) : new Dictionary<string, string>();
        }

        [Test]
        public void PackageJsonListsEveryBuiltInModuleTheCodeUses()
        {
            Assert.That(MissingModules(PackageSources(), Dependencies()), Is.Empty, "built-in modules used but not in package.json's dependencies");
        }

        [Test]
        public void ModuleCheckSeesTheUsesAndNotTheLookAlikes()
        {
            var sources = new Dictionary<string, string>
            {
                ["Collider.cs"] = "MeshCollider _collider; void B() { Physics.BakeMesh(id, false, o); }",
                ["Convert.cs"] = "void C() { Terrain terrain = Selected(); TerrainData data = terrain.terrainData; }",
                ["Window.cs"] = "void OnGUI() { GUILayout.Label(new GUIContent(\"x\")); }",
            };
            var none = new Dictionary<string, string>();
            Assert.That(MissingModules(sources, none), Is.EqualTo(new[]
            {
                "com.unity.modules.physics (used in Collider.cs)", "com.unity.modules.terrain (used in Convert.cs)", "com.unity.modules.imgui (used in Window.cs)",
            }));
            var lookAlikes = new Dictionary<string, string>
            {
                ["Renderer.cs"] = "// MeshCollider in a comment\npublic GregoryTerrainRenderer Terrain { get; set; } string s = \"GregoryTerrain\"; void D() { x.Terrain = t; }",
            };
            Assert.That(MissingModules(lookAlikes, none), Is.Empty);
            Assert.That(MissingModules(new Dictionary<string, string> { ["A.cs"] = "Rigidbody b;" },
                new Dictionary<string, string> { ["com.unity.modules.physics"] = "2.0.0" }),
                Is.EqualTo(new[] { "com.unity.modules.physics: version 2.0.0, a built-in module is 1.0.0" }));
        }
    }
}
