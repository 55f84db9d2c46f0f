using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>
    /// Runs <c>gt shaders</c> once (into a private build folder) and checks that every stage of every
    /// variant listed in Tools~/rig/shader_variants.txt compiled, validated and cross-compiled, and
    /// that an effect which is off leaves no code behind.
    /// </summary>
    [TestFixture, Parallelizable(ParallelScope.Self), Order(3)]
    public class ShaderCompileTests
    {
        static readonly string[] Stages = { "vert", "tesc", "tese", "frag", "fallback" };
        // The vertex cache's compute kernels, compiled for GT_VERTEX_CACHE variants only.
        static readonly string[] CacheStages = { "cache_factors", "cache_vertices" };

        static readonly string[] LodStages = { "lod_pieces", "lod_seams", "lod_slots", "lod_vertices" };   // the levels' factor and vertex cache kernels

        static string[] StagesOf(string[] keywords) =>
            keywords.Contains("GT_VERTEX_CACHE") ? Stages.Concat(CacheStages).ToArray()
            : keywords.Contains("GT_LOD") ? Stages.Concat(LodStages).ToArray() : Stages;
        static readonly string[] Targets = { "spirv", "glsl450", "essl320", "msl21", "dxc" };

        string packageRoot;
        string buildDir;
        string spirvDir;
        int exitCode;
        string output;
        List<(string name, string[] keywords)> variants;

        [OneTimeSetUp]
        public void CompileAll()
        {
            packageRoot = FindPackageRoot();
            variants = ReadVariants(Path.Combine(packageRoot, "Tools~", "rig", "shader_variants.txt"));
            buildDir = Path.Combine(Path.GetTempPath(), "gt-shader-tests-" + Guid.NewGuid().ToString("N"));
            spirvDir = Path.Combine(buildDir, "spirv");
            (exitCode, output) = Run("bash", new[] { Path.Combine(packageRoot, "Tools~", "gt"), "shaders" },
                                     new Dictionary<string, string> { ["GT_BUILD_DIR"] = buildDir });
            TestContext.Out.WriteLine(output);
        }

        [OneTimeTearDown]
        public void RemoveBuildDir()
        {
            if (buildDir != null && Directory.Exists(buildDir))
                Directory.Delete(buildDir, true);
        }

        [Test]
        public void EveryVariantAndStagePassesOnEveryTarget()
        {
            var lines = ResultLines();
            var failed = lines.Where(l => l.status != "PASS").Select(l => $"{l.variant}/{l.stage}").ToList();
            Assert.That(failed, Is.Empty, output);
            foreach (var l in lines)
                Assert.That(l.targets, Is.EquivalentTo(Targets), $"{l.variant}/{l.stage}");
            Assert.That(exitCode, Is.EqualTo(0), output);
        }

        [Test]
        public void EveryListedVariantAndStageWasCompiledExactlyOnce()
        {
            var expected = variants.SelectMany(v => StagesOf(v.keywords).Select(s => $"{v.name}/{s}")).ToList();
            var seen = ResultLines().Select(l => $"{l.variant}/{l.stage}").ToList();
            Assert.That(seen, Is.EquivalentTo(expected), "missing or extra variant/stage");
            // The variant list must hold what the issue asks for: all 16 combinations of the four
            // effect/mode keywords, each debug view alone, the factor readback with and without
            // noise (gt bench), the six snow variants, the seven vertex-cache variants (with the effects,
            // snow, and two debug views over the cache) and the eight levels-of-detail ones (GT_LOD: alone,
            // with the effects, the two readbacks, with snow, and
            // the Patch Id view over the levels' cache),
            // and the eight range-origin ones (GT_RANGE_ORIGIN: alone, with noise (gt lod-carry's single
            // range), the fair variant, the four readbacks the deep-zoom tests draw, and with snow),
            // and the six tiled-noise ones (GT_NOISE_TABLE: the fair variant, its readback alone and with
            // an origin, the fair variant with an origin, with the levels and in the cache's kernels).
            Assert.That(variants.Count, Is.EqualTo(16 + 3 + 2 + 6 + 7 + 7 + 8 + 6));
            Assert.That(variants.Count(v => v.keywords.Contains("GT_NOISE_TABLE")), Is.EqualTo(6));
            Assert.That(variants.Count(v => v.keywords.Contains("GT_LOD")), Is.EqualTo(7 + 1));
            Assert.That(variants.Count(v => v.keywords.Contains("GT_RANGE_ORIGIN")), Is.EqualTo(8 + 2));
            // GT_RANGE_ORIGIN, GT_LOD and GT_VERTEX_CACHE are one multi_compile set: never two together.
            Assert.That(variants.Count(v => v.keywords.Count(k => k is "GT_RANGE_ORIGIN" or "GT_LOD" or "GT_VERTEX_CACHE") > 1), Is.EqualTo(0), "one multi_compile set");
            Assert.That(variants.Count(v => v.keywords.Contains("GT_SNOW")), Is.EqualTo(9));
            Assert.That(variants.Count(v => v.keywords.Contains("GT_VERTEX_CACHE")), Is.EqualTo(7 + 1));
            var counts = Regex.Match(output, @"variants: (\d+), stages: (\d+) \(\+(\d+) with GT_VERTEX_CACHE\), compiled: (\d+), passed: (\d+), failed: (\d+)");
            Assert.That(counts.Success, Is.True, "no counts line");
            int total = variants.Sum(v => StagesOf(v.keywords).Length);
            Assert.That(int.Parse(counts.Groups[1].Value), Is.EqualTo(variants.Count));
            Assert.That(int.Parse(counts.Groups[2].Value), Is.EqualTo(Stages.Length));
            Assert.That(int.Parse(counts.Groups[3].Value), Is.EqualTo(CacheStages.Length));
            Assert.That(int.Parse(counts.Groups[4].Value), Is.EqualTo(total));
            Assert.That(int.Parse(counts.Groups[5].Value), Is.EqualTo(total));
            Assert.That(int.Parse(counts.Groups[6].Value), Is.EqualTo(0));
        }

        // "An effect that is off costs nothing": the keyword removes the code, not a branch around it.
        [TestCase("noise", "tese")]
        [TestCase("noise", "fallback")]
        [TestCase("noise", "tesc")]          // the frustum margin grows by the noise bound
        [TestCase("height_color", "tese")]
        [TestCase("height_color", "fallback")]
        [TestCase("height_color", "frag")]
        [TestCase("readback", "tese")]
        [TestCase("readback", "fallback")]
        [TestCase("snow", "tese")]
        [TestCase("snow", "fallback")]
        [TestCase("snow", "frag")]           // the blend by depth
        [TestCase("snow", "tesc")]           // the tile bounds grow by the depth cap
        // The range origin (deep zoom): without GT_RANGE_ORIGIN the tessellated stages compile none
        // of its code, not even an untaken branch (the driver kept registers for it).
        [TestCase("range_origin", "vert")]
        [TestCase("range_origin", "tesc")]
        [TestCase("range_origin", "tese")]
        public void AnEffectThatIsOffHasFewerInstructions(string effect, string stage)
        {
            int off = InstructionCount("base", stage);
            int on = InstructionCount(effect, stage);
            TestContext.Out.WriteLine($"{stage}: base {off} instructions, {effect} {on}");
            Assert.That(off, Is.LessThan(on));
        }

        // Stages an effect does not touch come out identical in size: nothing of it leaks there.
        [TestCase("noise", "frag")]
        [TestCase("noise", "vert")]
        [TestCase("height_color", "vert")]
        [TestCase("height_color", "tesc")]
        [TestCase("readback", "frag")]
        [TestCase("range_origin", "frag")]
        [TestCase("range_origin", "fallback")]   // GT_FALLBACK keeps the origin's run-time branch in every variant
        public void AnEffectAddsNothingToStagesThatDoNotUseIt(string effect, string stage)
        {
            Assert.That(InstructionCount(effect, stage), Is.EqualTo(InstructionCount("base", stage)));
        }

        // The fair variant (noise + height colour) drops the origin's code the same way.
        [Test]
        public void TheRangeOriginsCodeIsInTheFairVariantOnlyWithItsKeyword()
        {
            Assert.That(InstructionCount("noise+height_color", "tese"), Is.LessThan(InstructionCount("noise+height_color+range_origin", "tese")));
            Assert.That(InstructionCount("noise+height_color", "tesc"), Is.LessThan(InstructionCount("noise+height_color+range_origin", "tesc")));
        }

        // The rig-only readback buffer exists only in the GT_READBACK variants (vertices: domain and
        // fallback stages) and the GT_FACTOR_READBACK ones (factors: hull stage), never in a Unity build.
        [Test]
        public void OnlyReadbackVariantsDeclareTheReadbackBuffer()
        {
            foreach (var (name, keywords) in variants)
            {
                bool readback = keywords.Contains("GT_READBACK");
                bool factorReadback = keywords.Contains("GT_FACTOR_READBACK");
                foreach (var stage in Stages)
                {
                    bool declares = Disassemble(name, stage).Contains("\"_Readback\"");
                    bool writes = (readback && (stage == "tese" || stage == "fallback")) || (factorReadback && stage == "tesc");
                    Assert.That(declares, Is.EqualTo(writes), $"{name}/{stage}");
                }
            }
        }

        // The vertex cache moves the evaluation into the compute kernels: the cached domain stage
        // reads records and touches no patch data, the hull reads the decided factors, and the
        // vertex stage evaluates no corners.
        [Test]
        public void CachedStagesReadTheCacheAndEvaluateNothing()
        {
            foreach (var (name, keywords) in variants.Where(v => v.keywords.Contains("GT_VERTEX_CACHE")))
            {
                string tese = Disassemble(name, "tese"), tesc = Disassemble(name, "tesc"), vert = Disassemble(name, "vert");
                Assert.That(tese, Does.Contain("\"_VertexCache\""), name);
                Assert.That(tese, Does.Not.Contain("\"_ControlPoints\""), name);
                Assert.That(tesc, Does.Contain("\"_TileFactors\""), name);
                Assert.That(tesc, Does.Not.Contain("\"_ControlPoints\""), name);
                Assert.That(vert, Does.Not.Contain("\"_ControlPoints\""), name);
                string kernel = Disassemble(name, "cache_vertices");
                Assert.That(kernel, Does.Contain("\"_ControlPoints\"").And.Contain("\"_VertexCacheRW\""), name);
                // Its loop ends on the factors: read-only, as FXC wants (a UAV read there needs [allow_uav_condition]).
                Assert.That(kernel, Does.Contain("\"_TileFactors\"").And.Not.Contain("\"_TileFactorsRW\""), name);
                Assert.That(Disassemble(name, "cache_factors"), Does.Contain("\"_TileFactorsRW\""), name);
            }
            // Without the keyword nothing of the cache is there.
            foreach (var stage in Stages)
                Assert.That(Disassemble("noise+height_color", stage), Does.Not.Contain("_VertexCache").And.Not.Contain("_TileFactors"), stage);
        }

        // Unity's own file for the kernels (its adapter takes the LOD camera from globals): every
        // keyword combination its #pragma multi_compile_local lines make compiles and validates.
        [Test]
        public void UnityCacheComputeFileCompilesForEveryKeywordCombination()
        {
            string src = Path.Combine(packageRoot, "Shaders", "Cache", "TerrainCache.compute");
            string[] effects = { "GT_NOISE", "GT_HEIGHT_COLOR", "GT_SNOW", "GT_NOISE_TABLE" };
            for (int mask = 0; mask < 1 << effects.Length; mask++)
                foreach (var kernel in new[] { "CacheTileFactors", "CacheTileVertices" })
                {
                    string spv = Path.Combine(buildDir, $"unity-cache-{mask}-{kernel}.spv");
                    var args = new List<string> { "-D", "-V", "-S", "comp", "-e", kernel, "--hlsl-iomap", "--stb", "2", "--suavb", "5" };
                    args.AddRange(effects.Where((e, i) => (mask & (1 << i)) != 0).Select(e => "-D" + e));
                    args.AddRange(new[] { "-o", spv, src });
                    var (rc, text) = Run("glslangValidator", args.ToArray(), null);
                    Assert.That(rc, Is.EqualTo(0), $"{kernel} mask {mask}: {text}");
                    var (vrc, vtext) = Run("spirv-val", new[] { spv }, null);
                    Assert.That(vrc, Is.EqualTo(0), $"{kernel} mask {mask}: {vtext}");
                }
        }

        // Unity's side of the cache's kernels: VertexCachePass must bind every buffer a kernel reads,
        // under that kernel (an unbound one is an error at Dispatch in Unity, which the rig cannot
        // see). The names each kernel of TerrainCache.compute reads (all effects on, spirv-cross
        // reflection) against the ShaderIds the pass's SetBuffer calls give that kernel.
        [Test]
        public void VertexCachePassBindsEveryBufferEachKernelReads()
        {
            string src = Path.Combine(packageRoot, "Shaders", "Cache", "TerrainCache.compute");
            string pass = File.ReadAllText(Path.Combine(packageRoot, "Runtime", "VertexCachePass.cs"));
            var ids = Regex.Matches(File.ReadAllText(Path.Combine(packageRoot, "Runtime", "ShaderIds.cs")),
                                    @"static readonly int (\w+) = Shader\.PropertyToID\(""(\w+)""\)")
                .ToDictionary(m => m.Groups[1].Value, m => m.Groups[2].Value);
            var patch = Regex.Match(pass, @"static void BindPatchBuffers\([^)]*\)\s*\{(.*?)\n        \}", RegexOptions.Singleline);
            Assert.That(patch.Success, Is.True, "BindPatchBuffers not found in VertexCachePass.cs");
            var patchNames = Regex.Matches(patch.Groups[1].Value, @"SetBuffer\(kernel, ShaderIds\.(\w+)").Select(m => ids[m.Groups[1].Value]).ToList();
            foreach (var (kernel, field) in new[] { ("CacheTileFactors", "_factorsKernel"), ("CacheTileVertices", "_verticesKernel") })
            {
                var bound = Regex.Matches(pass, $@"SetBuffer\({field}, ShaderIds\.(\w+)").Select(m => ids[m.Groups[1].Value]).ToList();
                if (Regex.IsMatch(pass, $@"BindPatchBuffers\(shader, {field},")) bound.AddRange(patchNames);
                string spv = Path.Combine(buildDir, $"unity-cache-bindings-{kernel}.spv");
                var (rc, text) = Run("glslangValidator", new[] { "-D", "-V", "-S", "comp", "-e", kernel, "--hlsl-iomap", "--stb", "2", "--suavb", "5",
                                                                 "-DGT_NOISE", "-DGT_HEIGHT_COLOR", "-DGT_SNOW", "-DGT_NOISE_TABLE", "-o", spv, src }, null);
                Assert.That(rc, Is.EqualTo(0), text);
                var (rrc, json) = Run("spirv-cross", new[] { spv, "--reflect" }, null);
                Assert.That(rrc, Is.EqualTo(0), json);
                var read = Regex.Matches(Regex.Match(json, @"""ssbos""\s*:\s*\[(.*?)\]", RegexOptions.Singleline).Groups[1].Value, @"""name""\s*:\s*""(\w+)""")
                    .Select(m => m.Groups[1].Value).ToList();
                Assert.That(read, Is.Not.Empty, kernel);
                Assert.That(read, Is.SubsetOf(bound), $"{kernel} reads [{string.Join(", ", read)}]; VertexCachePass binds [{string.Join(", ", bound)}]");
            }
        }

        // --- helpers ------------------------------------------------------------------------------

        List<(string status, string variant, string stage, string[] targets)> ResultLines()
        {
            var list = new List<(string, string, string, string[])>();
            foreach (var line in output.Split('\n'))
            {
                var m = Regex.Match(line, @"^(PASS|FAIL) (\S+)\s+(\S+)\s*(.*)$");
                if (m.Success)
                    list.Add((m.Groups[1].Value, m.Groups[2].Value, m.Groups[3].Value,
                              m.Groups[4].Value.Split(' ', StringSplitOptions.RemoveEmptyEntries)));
            }
            return list;
        }

        string Disassemble(string variant, string stage)
        {
            string spv = Path.Combine(spirvDir, variant, stage + ".spv");
            Assert.That(File.Exists(spv), Is.True, spv);
            var (rc, text) = Run("spirv-dis", new[] { spv }, null);
            Assert.That(rc, Is.EqualTo(0), text);
            return text;
        }

        // Instructions that do work: everything but debug names and source annotations.
        int InstructionCount(string variant, string stage)
        {
            var debug = new Regex(@"^\s*Op(Name|MemberName|Source|SourceExtension|Line|NoLine|String|ModuleProcessed)\b");
            var instruction = new Regex(@"^\s*(%\S+ = )?Op\w+");
            return Disassemble(variant, stage).Split('\n').Count(l => instruction.IsMatch(l) && !debug.IsMatch(l));
        }

        // Same rule as shaders.py: keywords in file order, lower case without "GT_", joined by '+'.
        static List<(string, string[])> ReadVariants(string path)
        {
            var list = new List<(string, string[])>();
            foreach (var raw in File.ReadAllLines(path))
            {
                string line = raw.Split('#')[0].Trim();
                if (line.Length == 0) continue;
                var keywords = line == "-" ? new string[0] : line.Split(' ', StringSplitOptions.RemoveEmptyEntries);
                string name = string.Join("+", keywords.Select(k => (k.StartsWith("GT_") ? k.Substring(3) : k).ToLowerInvariant()));
                list.Add((name.Length == 0 ? "base" : name, keywords));
            }
            return list;
        }

        static string FindPackageRoot()
        {
            for (var dir = new DirectoryInfo(TestContext.CurrentContext.TestDirectory); dir != null; dir = dir.Parent)
                if (File.Exists(Path.Combine(dir.FullName, "package.json")))
                    return dir.FullName;
            throw new DirectoryNotFoundException("no package.json above " + TestContext.CurrentContext.TestDirectory);
        }

        static (int, string) Run(string file, string[] args, Dictionary<string, string> env)
        {
            var psi = new ProcessStartInfo(file) { RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false };
            foreach (var a in args) psi.ArgumentList.Add(a);
            if (env != null)
                foreach (var kv in env) psi.Environment[kv.Key] = kv.Value;
            using var p = Process.Start(psi);
            var stderr = p.StandardError.ReadToEndAsync();
            string stdout = p.StandardOutput.ReadToEnd();
            if (!p.WaitForExit(600_000))
            {
                p.Kill(true);
                Assert.Fail($"{file} did not finish in 10 minutes");
            }
            return (p.ExitCode, stdout + stderr.Result);
        }
    }
}
