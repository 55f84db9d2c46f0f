// gt test runs the fixtures marked [Parallelizable(ParallelScope.Self)] two at a time (Tools~/development.md,
// "Test command"), the slowest first ([Order]). Two fixtures that share a work folder would delete or overwrite each other's files
// only when NUnit happens to pair them: these checks read the fixtures' sources instead.
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    [TestFixture]
    public class TestLaneTests
    {
        const string ParallelMark = "Parallelizable(ParallelScope.Self";   // Self, or Self | Children
        // Folders under .build that fixtures only read (built by gt setup).
        static readonly string[] ToolFolders = { "gt-cli", "harness", "computerig" };
        // Mesa's disk cache, which every process of the run shares (Mesa writes its entries atomically).
        const string MesaCache = "mesa-shader-cache";

        static Dictionary<string, string> Sources() =>
            Directory.GetFiles(PackageRoot.Combine("Tools~", "RigTests"), "*.cs", SearchOption.AllDirectories)
                .ToDictionary(f => Path.GetFileName(f), File.ReadAllText);

        /// <summary>The folders under .build a source names: ReadbackRun.PrepareWork("NAME"), ".build", "NAME" and
        /// PipelinePassRun.Draw("SCRIPT", "NAME").</summary>
        static IEnumerable<string> BuildFolders(string source) =>
            Regex.Matches(source, @"PrepareWork\(""([^""]+)""|""\.build"",\s*""([^""]+)""|PipelinePassRun\.Draw\(""[^""]+"",\s*""([^""]+)""")
                .Select(m => m.Groups.Cast<Group>().Skip(1).First(g => g.Success).Value);

        [Test]
        public void TheParallelLaneHoldsTheSlowFixtures()
        {
            var parallel = Sources().Where(s => s.Value.Contains(ParallelMark)).Select(s => s.Key).ToList();
            Assert.That(parallel, Does.Contain("ShaderLibraryTests.cs").And.Contain("BenchSmokeTests.cs").And.Contain("GpuPropertyTests.cs"));
            // Each pipeline-pass fixture's setup is a script drawing on lavapipe (~20 CPU s): alone, they left a
            // core idle for the last ~90 s of the run.
            foreach (string f in new[] { "PipelinePassGpuTests.cs", "PipelinePassDepthNormalsTests.cs", "PipelinePassFogTests.cs",
                                         "PipelinePassHdrpGpuTests.cs", "PipelinePassHdrpShadowTests.cs", "PipelinePassBuiltinShadowTests.cs" })
                Assert.That(parallel, Does.Contain(f), "a pipeline-pass fixture off the parallel lane");
        }

        /// <summary>
        /// The fixtures given an [Order] start before the others, in that order: the slowest first, so that the
        /// last minutes do not leave a core idle behind one long fixture. Each is on the parallel lane (an ordered
        /// fixture that runs alone gains nothing) and no two share a place.
        /// </summary>
        [Test]
        public void TheSlowestFixturesStartFirst()
        {
            var ordered = new List<(int order, string fixture, bool parallel)>();
            foreach (string source in Sources().Values)
                foreach (Match m in Regex.Matches(source, @"\[TestFixture(?<attrs>[^\]]*)\]\s+public class (?<name>\w+)"))
                {
                    var order = Regex.Match(m.Groups["attrs"].Value, @"\bOrder\((\d+)\)");
                    if (order.Success) ordered.Add((int.Parse(order.Groups[1].Value), m.Groups["name"].Value, m.Groups["attrs"].Value.Contains(ParallelMark)));
                }
            ordered.Sort();
            TestContext.Out.WriteLine(string.Join(", ", ordered.Select(o => $"{o.order} {o.fixture}")));
            Assert.That(ordered.Select(o => o.fixture).Take(3), Is.EqualTo(new[] { "ShaderLibraryTests", "BenchSmokeTests", "ShaderCompileTests" }),
                "the three longest (the shaderlab check ~600 CPU s, the bench smoke ~150, gt shaders ~150) start first");
            Assert.That(ordered.Where(o => !o.parallel).Select(o => o.fixture), Is.Empty, "ordered fixtures not on the parallel lane");
            Assert.That(ordered.Select(o => o.order), Is.Unique, "two fixtures share a place");
        }

        /// <summary>
        /// A dotnet build writes the obj and bin folders of every project it references (Core's among them):
        /// two at once on the lane would race for them, so at most one parallel fixture starts one
        /// (UnityApiCheckTests, once per run; PublicApiTests reads what that build wrote).
        /// </summary>
        [Test]
        public void AtMostOneParallelFixtureStartsADotnetBuild()
        {
            var building = Sources().Where(s => s.Value.Contains(ParallelMark) && Regex.IsMatch(s.Value, @"""dotnet"",\s*\$?""build\b"))
                .Select(s => s.Key).ToList();
            Assert.That(building, Has.Count.LessThanOrEqualTo(1), "parallel fixtures that start a dotnet build: " + string.Join(", ", building));
        }

        [Test]
        public void EachParallelFixtureWritesInAFolderNoOtherFixtureNames()
        {
            var sources = Sources();
            var shared = new List<string>();
            foreach (var (file, source) in sources.Where(s => s.Value.Contains(ParallelMark)).Select(s => (s.Key, s.Value)))
                foreach (string folder in BuildFolders(source).Distinct().Where(f => !ToolFolders.Contains(f) && f != MesaCache))
                {
                    var others = sources.Where(s => s.Key != file && BuildFolders(s.Value).Contains(folder)).Select(s => s.Key).ToList();
                    if (others.Count > 0) shared.Add($"{file}: .build/{folder} is named by {string.Join(", ", others)} too");
                }
            Assert.That(shared, Is.Empty, "a fixture on the parallel lane shares its work folder");
        }
    }
}
