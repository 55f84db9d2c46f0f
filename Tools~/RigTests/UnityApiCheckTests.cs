using System;
using System.Diagnostics;
using System.IO;
using System.Linq;
using System.Threading;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>
    /// Builds Tools~/UnityApiCheck: the package's Unity-side C# (Runtime player and editor builds,
    /// Editor, Samples~) against stubs written from Unity's Scripting Reference. Honest only as far
    /// as the stubs are faithful to the documentation (Tools~/UnityApiCheck/README.md).
    /// </summary>
    [TestFixture, Parallelizable(ParallelScope.Self), Order(10)]
    public class UnityApiCheckTests
    {
        // One dotnet build per test run, shared by every test that reads its assemblies (PublicApiTests):
        // a second, incremental build of the same sources cost ~22 s and checked nothing the first had not.
        static readonly Lazy<(int exit, string errors)> Once = new Lazy<(int, string)>(RunBuild, LazyThreadSafetyMode.ExecutionAndPublication);
        static int _buildsRun;

        [Test]
        public void UnitySideCodeCompilesAgainstTheDocumentedApi() => Build();

        [Test]
        public void TheBuildRunsOncePerTestRun()
        {
            Build();
            Build();
            Assert.That(_buildsRun, Is.EqualTo(1), "dotnet build processes started for UnityApiCheck in this test run");
        }

        /// <summary>Builds every UnityApiCheck project (Release) once per test run; fails the calling test with the build's errors.</summary>
        internal static void Build()
        {
            var (exit, errors) = Once.Value;
            Assert.That(exit, Is.EqualTo(0), "dotnet build of UnityApiCheck failed:\n" + errors);
        }

        static (int, string) RunBuild()
        {
            Interlocked.Increment(ref _buildsRun);
            string project = PackageRoot.Combine("Tools~", "UnityApiCheck", "UnityApiCheck.csproj");
            var psi = new ProcessStartInfo("dotnet", $"build \"{project}\" -c Release -nologo")
            {
                RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false,
            };
            psi.Environment["DOTNET_CLI_TELEMETRY_OPTOUT"] = "1";
            psi.Environment["DOTNET_NOLOGO"] = "1";
            using var p = Process.Start(psi);
            var stderr = p.StandardError.ReadToEndAsync();
            string output = p.StandardOutput.ReadToEnd() + stderr.Result;
            p.WaitForExit();
            return (p.ExitCode, string.Join("\n", output.Split('\n').Where(l => l.Contains("error")).Distinct().Take(40)));
        }

        /// <summary>
        /// The check must compile against the real Core, never against stand-ins: every project
        /// reference of every check project is a stub, another check project, Core's own project or
        /// the authoring project.
        /// </summary>
        [Test]
        public void ChecksReferenceOnlyStubsAndTheRealCore()
        {
            string dir = PackageRoot.Combine("Tools~", "UnityApiCheck");
            var projects = Directory.GetFiles(dir, "*.csproj", SearchOption.AllDirectories)
                .Where(f => !f.Contains(Path.DirectorySeparatorChar + "obj" + Path.DirectorySeparatorChar)).ToList();
            Assert.That(projects.Count, Is.GreaterThanOrEqualTo(6), "UnityApiCheck projects found");
            var bad = new System.Collections.Generic.List<string>();
            int coreRefs = 0;
            foreach (string f in projects)
            {
                foreach (System.Xml.Linq.XElement r in System.Xml.Linq.XDocument.Load(f).Descendants("ProjectReference"))
                {
                    string include = r.Attribute("Include").Value.Replace('\\', '/');
                    if (include.EndsWith("Tools~/dotnet/Core/GregoryTerrain.Core.csproj")) { coreRefs++; continue; }
                    // The Editor-only authoring code, real too; which check projects may reference it: AuthoringSplitTests.
                    if (include.EndsWith("Tools~/dotnet/Authoring/GregoryTerrain.Authoring.csproj")) continue;
                    if (include.StartsWith("../Stubs/") || include.StartsWith("Stubs/")) continue;
                    bool fromStub = f.Replace('\\', '/').Contains("/Stubs/");
                    if (fromStub && System.Text.RegularExpressions.Regex.IsMatch(include, @"^\.\./Unity(Engine|Editor)/Unity(Engine|Editor)\.csproj$")) continue;
                    if (System.Text.RegularExpressions.Regex.IsMatch(include, @"^(\.\./)?(RuntimePlayer|RuntimeEditor|EditorCheck|SamplesCheck|SamplesInputSystemCheck|TestsRuntimeCheck|TestsEditorCheck)/\w+\.csproj$")) continue;
                    bad.Add($"{Path.GetFileName(f)} -> {include}");
                }
            }
            Assert.That(bad, Is.Empty, "unexpected project references");
            Assert.That(coreRefs, Is.GreaterThanOrEqualTo(4), "projects referencing the real Core");
            Assert.That(Directory.Exists(Path.Combine(dir, "CoreExpected")), Is.False, "Core stand-ins must not come back");
        }
    }
}
