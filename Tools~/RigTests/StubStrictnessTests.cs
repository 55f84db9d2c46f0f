using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Linq;
using System.Reflection;
using System.Runtime.Loader;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>
    /// The Unity API stubs must be as strict as Unity's declarations: a stub class left unsealed, an
    /// attribute allowed twice where Unity allows it once, a delegate at namespace level that Unity
    /// nests, lets code compile here that Unity rejects. The stub assemblies are built and their types
    /// read by reflection against facts of UnityCsReference 2022.3, kept as data with their source
    /// (Tools~/RigTests/Data/unity-2022.3-stub-facts.tsv).
    /// </summary>
    [TestFixture]
    public class StubStrictnessTests
    {
        AssemblyLoadContext _context;
        Assembly _engine, _editor;

        [OneTimeSetUp]
        public void BuildAndLoadStubs()
        {
            string project = PackageRoot.Combine("Tools~", "UnityApiCheck", "Stubs", "UnityEditor", "UnityEditor.csproj");
            string outDir = Path.Combine(Path.GetTempPath(), "gt-stubs-" + Guid.NewGuid().ToString("N"));
            var psi = new ProcessStartInfo("dotnet") { ArgumentList = { "build", project, "-c", "Release", "-nologo", "-v", "quiet", "-o", outDir } };
            psi.RedirectStandardOutput = true; psi.RedirectStandardError = true; psi.UseShellExecute = false;
            psi.Environment["DOTNET_CLI_TELEMETRY_OPTOUT"] = "1";
            using (var p = Process.Start(psi))
            {
                string output = p.StandardOutput.ReadToEnd() + p.StandardError.ReadToEnd();
                p.WaitForExit();
                Assert.That(p.ExitCode, Is.EqualTo(0), "building the stubs failed:\n" + output);
            }
            _context = new AssemblyLoadContext("unity-stubs", isCollectible: true);
            _engine = _context.LoadFromAssemblyPath(Path.Combine(outDir, "UnityEngine.dll"));
            _editor = _context.LoadFromAssemblyPath(Path.Combine(outDir, "UnityEditor.dll"));
        }

        [OneTimeTearDown]
        public void Unload() => _context?.Unload();

        static IEnumerable<TestCaseData> Facts()
        {
            foreach (string line in File.ReadAllLines(PackageRoot.Combine("Tools~", "RigTests", "Data", "unity-2022.3-stub-facts.tsv")))
            {
                if (line.Length == 0 || line.StartsWith("#", StringComparison.Ordinal)) continue;
                string[] f = line.Split('\t');
                if (f.Length != 3) throw new FormatException("3 tab-separated fields expected: " + line);
                yield return new TestCaseData(f[0], f[1], f[2]).SetName($"{f[0]} {f[1]}");
            }
        }

        [Test]
        public void FactsAreListed() => Assert.That(Facts().Count(), Is.GreaterThanOrEqualTo(40));

        [TestCaseSource(nameof(Facts))]
        public void StubMatchesUnity(string typeName, string fact, string source)
        {
            Type t = _engine.GetType(typeName) ?? _editor.GetType(typeName);
            Assert.That(t, Is.Not.Null, $"{typeName} is not in the stubs (fact from {source})");
            string where = $"{typeName}: Unity 2022.3 says {fact} ({source})";
            bool isStatic = t.IsClass && t.IsAbstract && t.IsSealed;
            if (fact == "sealed") Assert.That(t.IsSealed && !isStatic, Is.True, where);
            else if (fact == "not-sealed") Assert.That(t.IsSealed, Is.False, where);
            else if (fact == "abstract") Assert.That(t.IsAbstract && !t.IsSealed, Is.True, where);
            else if (fact == "static") Assert.That(isStatic, Is.True, where);
            else if (fact == "not-static") Assert.That(isStatic, Is.False, where);
            else if (fact == "struct") Assert.That(t.IsValueType && !t.IsEnum, Is.True, where);
            else if (fact == "class") Assert.That(t.IsClass, Is.True, where);
            else if (fact == "enum") Assert.That(t.IsEnum, Is.True, where);
            else if (fact.StartsWith("nested-in:", StringComparison.Ordinal))
                Assert.That(t.DeclaringType?.FullName, Is.EqualTo(fact.Substring("nested-in:".Length)), where);
            else if (fact.StartsWith("base:", StringComparison.Ordinal))
                Assert.That(t.BaseType?.FullName, Is.EqualTo(fact.Substring("base:".Length)), where);
            else if (fact.StartsWith("usage:", StringComparison.Ordinal))
            {
                var usage = t.GetCustomAttribute<AttributeUsageAttribute>(inherit: true);
                Assert.That(usage, Is.Not.Null, where);
                string actual = $"usage:{usage.ValidOn},AllowMultiple={usage.AllowMultiple},Inherited={usage.Inherited}";
                Assert.That(actual, Is.EqualTo(fact), where);
            }
            else Assert.Fail($"unknown fact '{fact}' for {typeName}");
        }

        /// <summary>
        /// Every stub type and member keeps its Scripting Reference page: "SR:Page" on its own line or
        /// in the comment lines directly above it (attribute lines between them allowed). A further
        /// part of a partial type needs none when another part names the page.
        /// </summary>
        [Test]
        public void EveryStubDeclarationNamesItsScriptingReferencePage()
        {
            var missing = new List<string>();
            int declarations = 0;
            var files = Directory.GetFiles(PackageRoot.Combine("Tools~", "UnityApiCheck", "Stubs"), "*.cs", SearchOption.AllDirectories)
                .Where(f => !f.Contains(Path.DirectorySeparatorChar + "obj" + Path.DirectorySeparatorChar)).ToList();
            var partialType = new Regex(@"^public\s+(?:sealed\s+|abstract\s+|static\s+)*partial\s+(?:class|struct)\s+(\w+)");
            var namedTypes = new HashSet<string>();
            foreach (string file in files)
                foreach (string l in File.ReadAllLines(file))
                {
                    var t = Regex.Match(l.Trim(), @"^public\s+(?:sealed\s+|abstract\s+|static\s+)*(?:partial\s+)?(?:class|struct)\s+(\w+)");
                    if (t.Success && l.Contains("SR:")) namedTypes.Add(t.Groups[1].Value);
                }
            foreach (string file in files)
            {
                string[] lines = File.ReadAllLines(file);
                for (int i = 0; i < lines.Length; i++)
                {
                    string l = lines[i].Trim();
                    if (!Regex.IsMatch(l, @"^(\[[^\]]*\]\s*)*public\s+(?!override)")) continue;
                    declarations++;
                    bool named = l.Contains("SR:");
                    for (int k = i - 1; !named && k >= 0 && (lines[k].TrimStart().StartsWith("//", StringComparison.Ordinal) || lines[k].TrimStart().StartsWith("[", StringComparison.Ordinal)); k--)
                        named = lines[k].Contains("SR:");
                    var partial = partialType.Match(l);
                    if (!named && partial.Success) named = namedTypes.Contains(partial.Groups[1].Value);
                    if (!named) missing.Add($"{Path.GetFileName(file)}:{i + 1}: {l}");
                }
            }
            Assert.That(declarations, Is.GreaterThan(100), "public stub declarations read");
            Assert.That(missing, Is.Empty, "stub declarations without an SR:<Page> reference:\n" + string.Join("\n", missing));
        }
    }
}
