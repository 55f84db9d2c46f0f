using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.Json;
using System.Text.RegularExpressions;
using System.Xml.Linq;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>
    /// Player builds carry only what draws and queries the terrain: the authoring code (fitting, G1
    /// building, brushes, heightmap readers) is the Editor-only assembly GregoryTerrain.Authoring in
    /// Editor/Authoring, and no player assembly reaches it. Unity enforces the asmdef side; the dotnet
    /// side enforces it by compiling Core (Tools~/dotnet/Core) without the authoring files. These tests
    /// hold the declarations to that, and hold Runtime/Core to code the runtime actually uses.
    /// </summary>
    [TestFixture]
    public class AuthoringSplitTests
    {
        const string AuthoringName = "GregoryTerrain.Authoring";
        static readonly string AuthoringDir = Path.Combine("Editor", "Authoring");

        // ---- the declarations -----------------------------------------------------------------

        [Test]
        public void AuthoringAssemblyIsEditorOnlyPureCSharpOnCore()
        {
            Asmdef a = Asmdef.Read(PackageRoot.Combine(AuthoringDir, AuthoringName + ".asmdef"));
            Assert.That(a.Name, Is.EqualTo(AuthoringName));
            Assert.That(a.EditorOnly, Is.True, "includePlatforms must be [\"Editor\"]");
            Assert.That(a.NoEngineReferences, Is.True, "noEngineReferences (pure C#, tested by dotnet test)");
            Assert.That(a.References, Is.EqualTo(new[] { "GregoryTerrain.Core" }));
            Assert.That(Directory.GetFiles(PackageRoot.Combine(AuthoringDir), "*.asmdef", SearchOption.AllDirectories).Length, Is.EqualTo(1),
                "every authoring file compiles into this one assembly");
            string core = File.ReadAllText(PackageRoot.Combine("Runtime", "Core", "AssemblyInfo.cs"));
            Assert.That(core, Does.Contain($"InternalsVisibleTo(\"{AuthoringName}\")"));
        }

        /// <summary>What is wrong with the package's asmdefs: a player-built assembly that references the authoring one.</summary>
        internal static List<string> PlayerReferencesToAuthoring(IEnumerable<Asmdef> asmdefs) =>
            asmdefs.Where(a => !a.EditorOnly && a.References.Contains(AuthoringName))
                   .Select(a => $"{a.Name} is built for players and references {AuthoringName}").ToList();

        [Test]
        public void OnlyEditorOnlyAssembliesReferenceAuthoring()
        {
            List<Asmdef> all = PackageAsmdefs().ToList();
            Assert.That(all.Select(a => a.Name), Does.Contain("GregoryTerrain.Runtime").And.Contain("GregoryTerrain.Core").And.Contain(AuthoringName));
            Assert.That(PlayerReferencesToAuthoring(all), Is.Empty);
            Assert.That(all.Single(a => a.Name == "GregoryTerrain.Editor").References, Does.Contain(AuthoringName), "the editor tools use it");
        }

        [Test]
        public void AsmdefCheckRejectsAPlayerAssemblyReferencingAuthoring()
        {
            var runtime = new Asmdef("GregoryTerrain.Runtime", new[] { "GregoryTerrain.Core", AuthoringName }, new string[0], false);
            var editor = new Asmdef("GregoryTerrain.Editor", new[] { AuthoringName }, new[] { "Editor" }, false);
            Assert.That(PlayerReferencesToAuthoring(new[] { runtime, editor }),
                Is.EqualTo(new[] { $"GregoryTerrain.Runtime is built for players and references {AuthoringName}" }));
        }

        /// <summary>
        /// The off-Unity builds reference the authoring project exactly where Unity's asmdefs reference
        /// the assembly, so `gt unity-api` fails the way Unity would on a player file that uses it.
        /// </summary>
        [TestCase("EditorCheck", "Editor")]
        [TestCase("TestsEditorCheck", "Tests/Editor")]
        [TestCase("TestsRuntimeCheck", "Tests/Runtime")]
        [TestCase("RuntimePlayer", "Runtime")]
        [TestCase("RuntimeEditor", "Runtime")]
        [TestCase("SamplesCheck", "Samples~/GroundWalk")]
        [TestCase("SamplesInputSystemCheck", "Samples~/GroundWalk")]
        public void CheckProjectReferencesAuthoringAsItsAsmdefDoes(string checkProject, string asmdefFolder)
        {
            string dir = PackageRoot.Combine(asmdefFolder.Split('/'));
            Asmdef a = Asmdef.Read(Directory.GetFiles(dir, "*.asmdef").Single());
            string project = PackageRoot.Combine("Tools~", "UnityApiCheck", checkProject, checkProject + ".csproj");
            Assert.That(ReferencesAuthoringProject(project), Is.EqualTo(a.References.Contains(AuthoringName)),
                $"{checkProject} and {a.Name}'s asmdef disagree on referencing {AuthoringName}");
        }

        [Test]
        public void DotnetProjectsCompileCoreAndAuthoringApart()
        {
            string dotnet = PackageRoot.Combine("Tools~", "dotnet");
            Assert.That(CompileIncludes(Path.Combine(dotnet, "Core", "GregoryTerrain.Core.csproj")), Is.EqualTo(new[] { "../../../Runtime/Core/**/*.cs" }));
            string authoring = Path.Combine(dotnet, "Authoring", "GregoryTerrain.Authoring.csproj");
            Assert.That(CompileIncludes(authoring), Is.EqualTo(new[] { "../../../Editor/Authoring/**/*.cs" }));
            Assert.That(XDocument.Load(authoring).Descendants("AssemblyName").Single().Value, Is.EqualTo(AuthoringName));
            Assert.That(ProjectReferences(authoring), Is.EqualTo(new[] { "../Core/GregoryTerrain.Core.csproj" }), "authoring builds on Core alone");
            Assert.That(ProjectReferences(Path.Combine(dotnet, "Core", "GregoryTerrain.Core.csproj")), Is.Empty);
        }

        // ---- the sources ----------------------------------------------------------------------

        /// <summary>
        /// No player file (Runtime/**, Samples~, Tests/Runtime) names a type the authoring assembly
        /// declares. The compilers say so too (Core's and the player check projects lack the
        /// reference); this names the file and the type in one line.
        /// </summary>
        [Test]
        public void NoPlayerFileNamesAnAuthoringType()
        {
            var authoringTypes = new HashSet<string>(Sources(AuthoringDir).SelectMany(f => TopLevelTypes(f.Value)), StringComparer.Ordinal);
            Assert.That(authoringTypes, Does.Contain("HeightmapFitter").And.Contain("G1Builder").And.Contain("PatchBrush"));
            var player = Sources("Runtime").Concat(Sources("Samples~")).Concat(Sources(Path.Combine("Tests", "Runtime")));
            var bad = new List<string>();
            foreach (var f in player)
                foreach (string name in NamesUsed(f.Value).Where(authoringTypes.Contains))
                    bad.Add($"{f.Key} names {name}");
            Assert.That(bad, Is.Empty, $"player files use {AuthoringName} (it is Editor only)");
        }

        /// <summary>
        /// Every Runtime/Core file is reached, type reference by type reference, from the components
        /// (Runtime/*.cs) or the samples' scripts: Core holds what draws and queries the terrain, and
        /// code only the editor, the tests or gt-cli use belongs in Editor/Authoring (or Tools~).
        /// Also prints the lines of C# the package's player assemblies (Core + Runtime) hold.
        /// </summary>
        [Test]
        public void EveryCoreFileIsReachedFromTheRuntime()
        {
            Dictionary<string, string> core = Sources(Path.Combine("Runtime", "Core"));
            var roots = Directory.GetFiles(PackageRoot.Combine("Runtime"), "*.cs").Select(Read)
                .Concat(Sources("Samples~").Values).ToList();
            List<string> unreached = Unreached(core, roots);
            int lines = Sources("Runtime").Values.Sum(s => s.Count(c => c == '\n'));   // as wc -l counts
            TestContext.Out.WriteLine($"player assemblies (GregoryTerrain.Core + GregoryTerrain.Runtime): {Sources("Runtime").Count} files, {lines} lines of C#");
            Assert.That(core.Count, Is.GreaterThan(40), "Core files found");
            Assert.That(unreached, Is.Empty, "Core files no runtime code reaches (move them to Editor/Authoring, or use them)");
        }

        [Test]
        public void ReachabilityFindsAFileOnlyTheEditorUses()
        {
            var core = new Dictionary<string, string>
            {
                ["Core/Patch.cs"] = "namespace G {\n    internal sealed partial class Patch { Box b; } }",
                ["Core/PatchMore.cs"] = "namespace G {\n    internal sealed partial class Patch { void M() { Maths.Add(); } } }",
                ["Core/Maths.cs"] = "namespace G {\n    static class Maths { struct Nested { } public static void Add() { } } }",
                ["Core/Box.cs"] = "namespace G {\n    [Mark(1)] internal struct Box { } }",
                ["Core/MarkAttribute.cs"] = "namespace G {\n    sealed class MarkAttribute : System.Attribute { public MarkAttribute(int n) { } } }",
                ["Core/AssemblyInfo.cs"] = "[assembly: InternalsVisibleTo(\"G.Editor\")]",
                ["Core/Brush.cs"] = "namespace G {\n    // Patch\n    internal static class Brush { Patch p; Nested n; } }",
            };
            var roots = new[] { "class Renderer { Patch p; string s = \"Brush\"; /* Brush */ }" };
            Assert.That(Unreached(core, roots), Is.EqualTo(new[] { "Core/Brush.cs (Brush)" }),
                "a file named only in a string or a comment, or by nested type names, is not reached; an attribute is reached by its use without 'Attribute'");
        }

        // ---- helpers --------------------------------------------------------------------------

        internal sealed class Asmdef
        {
            public readonly string Name;
            public readonly string[] References;
            public readonly string[] IncludePlatforms;
            public readonly bool NoEngineReferences;
            public bool EditorOnly => IncludePlatforms.Length == 1 && IncludePlatforms[0] == "Editor";

            public Asmdef(string name, string[] references, string[] includePlatforms, bool noEngineReferences)
            {
                Name = name; References = references; IncludePlatforms = includePlatforms; NoEngineReferences = noEngineReferences;
            }

            public static Asmdef Read(string path)
            {
                using var doc = JsonDocument.Parse(File.ReadAllText(path));
                JsonElement r = doc.RootElement;
                string[] Strings(string key) => r.TryGetProperty(key, out JsonElement e) && e.ValueKind == JsonValueKind.Array
                    ? e.EnumerateArray().Select(x => x.GetString()).ToArray() : new string[0];
                bool noEngine = r.TryGetProperty("noEngineReferences", out JsonElement n) && n.ValueKind == JsonValueKind.True;
                return new Asmdef(r.GetProperty("name").GetString(), Strings("references"), Strings("includePlatforms"), noEngine);
            }
        }

        static IEnumerable<Asmdef> PackageAsmdefs() =>
            new[] { "Runtime", "Editor", "Tests", "Samples~" }
                .SelectMany(d => Directory.GetFiles(PackageRoot.Combine(d), "*.asmdef", SearchOption.AllDirectories))
                .Select(Asmdef.Read);

        static bool ReferencesAuthoringProject(string csproj) =>
            ProjectReferences(csproj).Any(r => r.EndsWith("Tools~/dotnet/Authoring/GregoryTerrain.Authoring.csproj", StringComparison.Ordinal));

        static string[] ProjectReferences(string csproj) =>
            XDocument.Load(csproj).Descendants("ProjectReference").Select(r => r.Attribute("Include").Value.Replace('\\', '/')).ToArray();

        static string[] CompileIncludes(string csproj) =>
            XDocument.Load(csproj).Descendants("Compile").Select(c => c.Attribute("Include").Value.Replace('\\', '/')).ToArray();

        static string Read(string path) => File.ReadAllText(path);

        /// <summary>The .cs files under a package folder, by path relative to the package, with their text.</summary>
        static Dictionary<string, string> Sources(string folder) =>
            Directory.GetFiles(PackageRoot.Combine(folder), "*.cs", SearchOption.AllDirectories)
                .Where(f => !f.Contains(Path.DirectorySeparatorChar + "obj" + Path.DirectorySeparatorChar))
                .OrderBy(f => f, StringComparer.Ordinal)
                .ToDictionary(f => Path.GetRelativePath(PackageRoot.Path, f).Replace('\\', '/'), Read);

        /// <summary>Code without comments, string and character literals: what the compiler resolves names in.</summary>
        internal static string CodeOnly(string source) =>
            Regex.Replace(source, @"//[^\n]*|/\*.*?\*/|@""(?:""""|[^""])*""|""(?:\\.|[^""\\\n])*""|'(?:\\.|[^'\\\n])+'", m => m.Value.StartsWith("/") ? " " : "\"\"",
                RegexOptions.Singleline);

        /// <summary>Types declared directly in a namespace (one brace deep): what another file can name without qualification by a type.</summary>
        internal static IEnumerable<string> TopLevelTypes(string source)
        {
            string code = CodeOnly(source);
            foreach (Match m in Regex.Matches(code, @"\b(?:class|struct|enum|interface|record)\s+(\w+)"))
            {
                int depth = 0;
                for (int i = 0; i < m.Index; i++) depth += code[i] == '{' ? 1 : code[i] == '}' ? -1 : 0;
                if (depth == 1) yield return m.Groups[1].Value;
            }
        }

        /// <summary>
        /// Capitalised identifiers the code names, each also with "Attribute" ([GenerateHlsl] names
        /// GenerateHlslAttribute): a superset of the types it uses (a member of the same name counts
        /// too, which only errs towards reached).
        /// </summary>
        static IEnumerable<string> NamesUsed(string source) =>
            Regex.Matches(CodeOnly(source), @"\b[A-Z]\w*\b").SelectMany(m => new[] { m.Value, m.Value + "Attribute" }).Distinct(StringComparer.Ordinal);

        /// <summary>
        /// Files of <paramref name="core"/> that no root reaches through type names, as "file (types)".
        /// A partial type is reached in every file that declares part of it.
        /// </summary>
        internal static List<string> Unreached(IDictionary<string, string> core, IEnumerable<string> roots)
        {
            var declaredIn = new Dictionary<string, List<string>>(StringComparer.Ordinal);
            foreach (var f in core)
                foreach (string t in TopLevelTypes(f.Value))
                {
                    if (!declaredIn.TryGetValue(t, out var files)) declaredIn[t] = files = new List<string>();
                    files.Add(f.Key);
                }
            var reached = new HashSet<string>(StringComparer.Ordinal);
            var pending = new Stack<string>(roots);
            while (pending.Count > 0)
                foreach (string name in NamesUsed(pending.Pop()))
                    if (declaredIn.TryGetValue(name, out var files))
                        foreach (string f in files)
                            if (reached.Add(f)) pending.Push(core[f]);
            bool declaresTypes(string f) => TopLevelTypes(core[f]).Any();   // AssemblyInfo.cs: attributes only
            return core.Keys.Where(f => !reached.Contains(f) && declaresTypes(f)).OrderBy(f => f, StringComparer.Ordinal)
                .Select(f => $"{f} ({string.Join(", ", TopLevelTypes(core[f]))})").ToList();
        }
    }
}
