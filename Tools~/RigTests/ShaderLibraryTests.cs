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
    /// <c>gt shaderlab</c> (Tools~/rig/shaderlab.py): every pass, variant and stage of
    /// GregoryTerrain.shader and every compute kernel compiled with glslang and with Microsoft's DXC
    /// against Unity's real shader libraries (../shared/unity-shaderlib), linted for FXC's rules that
    /// neither compiler enforces (Tools~/rig/fxc_lint.py), then the .shader imported as a Built-in-only, a
    /// URP-only and an HDRP-only project would import it. Also shows the check failing on broken
    /// copies of the package, and the PackageRequirements selection on a copy with known blocks.
    /// </summary>
    [TestFixture, Parallelizable(ParallelScope.Self), Order(1)]
    public class ShaderLibraryTests
    {
        static readonly string[] Emulations = { "half-twins", "texture-types", "hdrp-matrix-swizzle", "hdrp-shadow-context-buffer" };
        const string ScreenShadowLimit = "builtin-shadows-screen-tex2Dproj";

        int _exitCode;
        string _output;
        double _seconds;

        static string Script => PackageRoot.Combine("Tools~", "rig", "shaderlab.py");
        internal static string ShaderLib => Path.GetFullPath(PackageRoot.Combine("..", "shared", "unity-shaderlib"));

        [OneTimeSetUp]
        public void RunTheCheck()
        {
            var clock = Stopwatch.StartNew();
            // Counts of the two variants the cost test compares: spirv-opt over every variant is a
            // quarter of a full run; `gt shaderlab --counts` prints them all.
            (_exitCode, _output) = RunScript("--counts", "base,noise");
            _seconds = clock.Elapsed.TotalSeconds;
            TestContext.Out.WriteLine($"gt shaderlab --counts base,noise: {_seconds:F0} s, exit {_exitCode}");
            foreach (string l in Lines().Where(l => l.StartsWith("shaderlab") || l.StartsWith("cost ") || l.StartsWith("lint ") || Regex.IsMatch(l, @"^project \w+: subshaders")))
                TestContext.Out.WriteLine(l);
        }

        IEnumerable<string> Lines() => _output.Split('\n').Select(l => l.TrimEnd('\r'));

        /// <summary>The FAIL lines (with their errors) whose case starts with the given prefix.</summary>
        string Failures(string prefix, int max = 80)
        {
            var picked = new List<string>();
            bool inside = false;
            foreach (string l in Lines())
            {
                if (!l.StartsWith("     ")) inside = l.StartsWith(prefix);
                if (inside) picked.Add(l);
                if (picked.Count >= max) break;
            }
            return picked.Count > 0 ? string.Join("\n", picked) : "(no output for " + prefix + ")\n" + string.Join("\n", Lines().Take(20));
        }

        (int compiled, int failed, int limit, int emulated) Summary(string pipeline)
        {
            var m = Lines().Select(l => Regex.Match(l, $@"^shaderlab {pipeline}: (\d+) compiled, (\d+) failed, (\d+) glslang-limit, (\d+) emulated$"))
                .FirstOrDefault(x => x.Success);
            Assert.That(m, Is.Not.Null, $"no summary line for {pipeline}:\n" + string.Join("\n", Lines().Take(40)));
            return (int.Parse(m.Groups[1].Value), int.Parse(m.Groups[2].Value), int.Parse(m.Groups[3].Value), int.Parse(m.Groups[4].Value));
        }

        (int compiled, int failed, int limit) DxcSummary(string pipeline)
        {
            var m = Lines().Select(l => Regex.Match(l, $@"^shaderlab dxc {pipeline}: (\d+) compiled, (\d+) failed, (\d+) dxc-limit$"))
                .FirstOrDefault(x => x.Success);
            Assert.That(m, Is.Not.Null, $"no DXC summary line for {pipeline}:\n" + string.Join("\n", Lines().Where(l => l.StartsWith("shaderlab"))));
            return (int.Parse(m.Groups[1].Value), int.Parse(m.Groups[2].Value), int.Parse(m.Groups[3].Value));
        }

        /// <summary>
        /// DXC (HLSL 2018, Unity's use_dxc defines) compiles every case glslang compiles: FXC's language
        /// rules that glslang lets through (a conditional operator on structs, `int float` after
        /// Built-in's `#define half float`) fail here.
        /// </summary>
        [TestCase("URP")]
        [TestCase("HDRP")]
        [TestCase("Builtin")]
        [TestCase("Compute")]
        public void EveryCaseCompilesWithDxc(string pipeline)
        {
            var d = DxcSummary(pipeline);
            var g = Summary(pipeline);
            TestContext.Out.WriteLine($"{pipeline}: DXC {d.compiled} compiled, {d.failed} failed, {d.limit} dxc-limit; glslang {g.compiled} compiled");
            Assert.That(d.failed, Is.EqualTo(0), Failures("dxc FAIL " + pipeline));
            Assert.That(d.compiled + d.failed + d.limit, Is.EqualTo(g.compiled + g.failed + g.limit), pipeline + ": DXC saw every case");
            Assert.That(d.compiled, Is.GreaterThan(0), pipeline + ": nothing compiled");
        }

        /// <summary>A failure put down to a known DXC/FXC difference is named on its own line, one per case.</summary>
        [Test]
        public void DxcLimitCasesAreNamedOneByOne()
        {
            var limits = Lines().Where(l => l.StartsWith("dxc-limit: ")).ToList();
            foreach (string l in limits)
                Assert.That(l, Does.Match(@"^dxc-limit: (URP|HDRP|Builtin|Compute) .+: [\w-]+$"), l);
            int counted = new[] { "URP", "HDRP", "Builtin", "Compute" }.Sum(p => DxcSummary(p).limit);
            Assert.That(limits.Count, Is.EqualTo(counted), "every dxc-limit case is listed");
        }

        /// <summary>
        /// FXC's rules that neither compiler enforces (Tools~/rig/fxc_lint.py: barriers in varying flow,
        /// loops ending on a UAV read, reserved words as names, groupshared size): no finding in any
        /// pipeline. Each finding is listed as "lint rule: file:line: message".
        /// </summary>
        [TestCase("URP")]
        [TestCase("HDRP")]
        [TestCase("Builtin")]
        [TestCase("Compute")]
        public void TheLintFindsNothing(string pipeline)
        {
            var m = Lines().Select(l => Regex.Match(l, $@"^shaderlab lint {pipeline}: (\d+) findings$")).FirstOrDefault(x => x.Success);
            Assert.That(m, Is.Not.Null, $"no lint summary line for {pipeline}");
            var findings = Lines().Where(l => l.StartsWith("lint ")).ToList();
            foreach (string l in findings)
                Assert.That(l, Does.Match(@"^lint [\w-]+: \S+:\d+: .+$"), l);
            Assert.That(int.Parse(m.Groups[1].Value), Is.EqualTo(0), string.Join("\n", findings));
        }

        [TestCase("URP")]
        [TestCase("HDRP")]
        [TestCase("Builtin")]
        [TestCase("Compute")]
        public void EveryCaseCompilesAgainstUnitysRealLibraries(string pipeline)
        {
            Assert.That(Directory.Exists(ShaderLib), Is.True, "Unity's shader libraries are missing: " + ShaderLib);
            var s = Summary(pipeline);
            TestContext.Out.WriteLine($"{pipeline}: {s.compiled} compiled, {s.failed} failed, {s.limit} glslang-limit, {s.emulated} emulated ({_seconds:F0} s for the whole check)");
            Assert.That(s.failed, Is.EqualTo(0), Failures("FAIL " + pipeline));
            Assert.That(s.compiled, Is.GreaterThan(0), pipeline + ": nothing compiled");
        }

        /// <summary>
        /// The only failures put down to glslang are the Built-in screen-space shadow lookup, each named
        /// on its own line: a Built-in forward fragment stage with SHADOWS_SCREEN on (and the mobile
        /// UNITY_NO_SCREENSPACE_SHADOWS path, which reads the shadow map directly, off).
        /// </summary>
        [Test]
        public void GlslangLimitCasesAreNamedOneByOne()
        {
            var limits = Lines().Where(l => l.StartsWith("glslang-limit: ")).ToList();
            foreach (string l in limits)
            {
                var m = Regex.Match(l, @"^glslang-limit: (\w+) sub\d+ (\w+) variant (\S+) stage (\w+) \(\w+\): (\S+)$");
                Assert.That(m.Success, Is.True, l);
                Assert.That(m.Groups[1].Value, Is.EqualTo("Builtin"), l);
                Assert.That(m.Groups[3].Value.Split('+'), Does.Contain("shadows_screen").And.Not.Contain("unity_no_screenspace_shadows"), l);
                Assert.That(m.Groups[4].Value, Is.EqualTo("frag"), l);
                Assert.That(m.Groups[5].Value, Is.EqualTo(ScreenShadowLimit), l);
            }
            int counted = new[] { "URP", "HDRP", "Builtin", "Compute" }.Sum(p => Summary(p).limit);
            Assert.That(limits.Count, Is.EqualTo(counted), "every glslang-limit case is listed");
            TestContext.Out.WriteLine(string.Join("\n", limits));
        }

        /// <summary>
        /// The emulation of FXC/HLSLcc behaviour is reported per case, apart from the results, and is
        /// only ever one of the README's three; the SRP libraries need the half twins on every case.
        /// </summary>
        [Test]
        public void EmulationIsReportedPerCaseAndOnlyTheKnownKinds()
        {
            var emulated = Lines().Where(l => l.StartsWith("emulated: ")).ToList();
            foreach (string l in emulated)
            {
                var m = Regex.Match(l, @"^emulated: (\w+) .*: ([\w-]+(?:, [\w-]+)*)$");
                Assert.That(m.Success, Is.True, l);
                Assert.That(m.Groups[2].Value.Split(", "), Is.SubsetOf(Emulations), l);
            }
            foreach (string pipeline in new[] { "URP", "HDRP", "Builtin", "Compute" })
                Assert.That(emulated.Count(l => l.StartsWith("emulated: " + pipeline + " ")), Is.EqualTo(Summary(pipeline).emulated), pipeline);
            foreach (string pipeline in new[] { "URP", "HDRP" })
            {
                var s = Summary(pipeline);
                Assert.That(s.emulated, Is.EqualTo(s.compiled + s.failed + s.limit), pipeline + ": SRP Core's half twins are in every case");
            }
        }

        /// <summary>
        /// Unity compiles every SubShader of the file on import, whatever the pipeline; only
        /// PackageRequirements keep a SubShader out. Goal: no compile error in any project kind.
        /// </summary>
        [TestCase("builtin")]
        [TestCase("urp")]
        [TestCase("hdrp")]
        public void EveryProjectKindImportsTheShaderWithoutErrors(string kind)
        {
            var m = Lines().Select(l => Regex.Match(l, $@"^project {kind}: subshaders used (\d+) .*; passes compiled (\d+), cases (\d+), compile errors (\d+)"))
                .FirstOrDefault(x => x.Success);
            Assert.That(m, Is.Not.Null, $"no project line for {kind}");
            TestContext.Out.WriteLine(Lines().First(l => l.StartsWith($"project {kind}: subshaders")));
            Assert.That(int.Parse(m.Groups[1].Value), Is.GreaterThan(0), kind + ": no SubShader used");
            Assert.That(int.Parse(m.Groups[2].Value), Is.GreaterThan(0), kind + ": no pass compiled");
            Assert.That(int.Parse(m.Groups[4].Value), Is.EqualTo(0), m.Value + "\n" + Failures($"project {kind}: FAIL", 40));
        }

        /// <summary>
        /// Instruction counts (gt shaderlab --counts) exist for every pass that compiled and measure
        /// real code: the noise variant of a pass costs more than its base variant.
        /// </summary>
        [Test]
        public void InstructionCountsArePrintedPerPassAndFollowTheCode()
        {
            var costs = Lines().Select(l => Regex.Match(l, @"^cost (.+) variant (\S+): .*total (\d+)$")).Where(m => m.Success)
                .ToDictionary(m => (m.Groups[1].Value, m.Groups[2].Value), m => int.Parse(m.Groups[3].Value));
            var passes = Lines().Select(l => Regex.Match(l, @"^PASS (\w+ sub\d+ \S+|Compute \S+) variant (\S+) ")).Where(m => m.Success)
                .Select(m => m.Groups[1].Value).Distinct().ToList();
            Assert.That(passes, Is.Not.Empty);
            foreach (string p in passes)
                Assert.That(costs.Keys.Any(k => k.Item1 == p), Is.True, p + ": no cost line");
            int compared = 0;
            foreach (var kv in costs.Where(k => k.Key.Item2 == "noise"))
            {
                Assert.That(costs.TryGetValue((kv.Key.Item1, "base"), out int baseCost), Is.True, kv.Key.Item1);
                Assert.That(kv.Value, Is.GreaterThan(baseCost), kv.Key.Item1 + ": noise adds code");
                compared++;
            }
            Assert.That(compared, Is.GreaterThan(0));
        }

        /// <summary>A throwaway copy of the package's Shaders folder (all the check reads).</summary>
        internal sealed class PackageCopy : IDisposable
        {
            public readonly string Root = Path.Combine(Path.GetTempPath(), "gt-shaderlab-copy-" + Guid.NewGuid().ToString("N"));
            string Shader => Path.Combine(Root, "Shaders", "GregoryTerrain.shader");
            public int SubShaderCount => Regex.Matches(File.ReadAllText(Shader), @"^\s*SubShader\s*$", RegexOptions.Multiline).Count;

            public PackageCopy()
            {
                string from = PackageRoot.Combine("Shaders");
                foreach (string f in Directory.GetFiles(from, "*", SearchOption.AllDirectories))
                {
                    string to = Path.Combine(Root, "Shaders", Path.GetRelativePath(from, f));
                    Directory.CreateDirectory(Path.GetDirectoryName(to));
                    File.Copy(f, to);
                }
            }

            /// <summary>The first package file the first pass of a SubShader with this RenderPipeline tag
            /// (null: none, Built-in) includes.</summary>
            public string AdapterOf(string renderPipeline)
            {
                string text = File.ReadAllText(Shader);
                // null: the first SubShader without a RenderPipeline tag (Built-in).
                var tag = renderPipeline != null
                    ? Regex.Match(text, $"\"RenderPipeline\"\\s*=\\s*\"{renderPipeline}\"")
                    : Regex.Matches(text, @"\bTags\s*\{[^}]*\}").FirstOrDefault(t => !t.Value.Contains("RenderPipeline") && !t.Value.Contains("LightMode"));
                Assert.That(tag != null && tag.Success, Is.True, renderPipeline ?? "Built-in");
                var inc = Regex.Match(text.Substring(tag.Index), "#include \"Packages/com\\.gregoryterrain\\.tessellation/([^\"]+)\"");
                Assert.That(inc.Success, Is.True, renderPipeline + ": no package include");
                return Path.Combine(Root, inc.Groups[1].Value);
            }

            /// <summary>Replaces every SubShader's PackageRequirements with the given entries, by RenderPipeline tag.</summary>
            public void SetRequirements(string urp, string hdrp)
            {
                string text = Regex.Replace(File.ReadAllText(Shader), @"PackageRequirements\s*\{[^{}]*\}", "");
                text = Regex.Replace(text, @"SubShader\s*\{(?=(?:\s|//[^\n]*)*Tags\s*\{[^}]*""RenderPipeline""\s*=\s*""(\w+)"")", m =>
                    m.Value + "\n        PackageRequirements { " + (m.Groups[1].Value == "UniversalPipeline" ? urp : hdrp) + " }\n");
                File.WriteAllText(Shader, text);
            }

            public void Dispose()
            {
                if (Directory.Exists(Root)) Directory.Delete(Root, true);
            }
        }

        internal static (int, string) RunScript(params string[] args)
        {
            var psi = new ProcessStartInfo("python3") { RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false };
            psi.ArgumentList.Add(Script);
            foreach (string a in args) psi.ArgumentList.Add(a);
            using var p = Process.Start(psi);
            var stderr = p.StandardError.ReadToEndAsync();
            string stdout = p.StandardOutput.ReadToEnd();
            if (!p.WaitForExit(900_000))
            {
                p.Kill(true);
                Assert.Fail("shaderlab.py did not finish in 15 minutes");
            }
            return (p.ExitCode, stdout + stderr.Result);
        }
    }

    /// <summary>
    /// The check seen failing: broken copies of the package, PackageRequirements Unity would reject,
    /// missing libraries; and the project kinds' SubShader selection on a copy with known blocks.
    /// Apart from ShaderLibraryTests so that running these does not run the whole check.
    /// </summary>
    [TestFixture, Parallelizable(ParallelScope.Self), Order(6)]
    public class ShaderLibraryCheckTests
    {
        static string ShaderLib => ShaderLibraryTests.ShaderLib;
        static (int, string) RunScript(params string[] args) => ShaderLibraryTests.RunScript(args);

        /// <summary>A copy whose URP adapter calls an undeclared function fails, the error naming it.</summary>
        [Test]
        public void ABrokenAdapterFailsTheCheck()
        {
            using var copy = new ShaderLibraryTests.PackageCopy();
            string adapter = copy.AdapterOf("UniversalPipeline");
            File.AppendAllText(adapter, "\nfloat4 GT_RigBrokenOnPurpose(float4 v) { return GT_RigUndeclaredFunction(v); }\n");
            var (code, output) = RunScript("--package", copy.Root, "--shaderlib", ShaderLib, "--check", "pipelines",
                                           "--pipeline", "URP", "--variants", "base", "--quiet");
            var m = Regex.Match(output, @"shaderlab URP: (\d+) compiled, (\d+) failed");
            Assert.That(m.Success, Is.True, output);
            Assert.That(int.Parse(m.Groups[2].Value), Is.GreaterThan(0), output);
            Assert.That(output, Does.Match(@"FAIL URP [^\n]*\n\s+ERROR: [^\n]*GT_RigUndeclaredFunction"), "the error names the function");
            Assert.That(code, Is.EqualTo(1));
        }

        /// <summary>
        /// An error only DXC sees (FXC's language: a conditional operator choosing between structs,
        /// which glslang accepts) fails the check on DXC's summary line, the error naming the operator.
        /// </summary>
        [Test]
        public void ADxcOnlyErrorFailsTheCheck()
        {
            using var copy = new ShaderLibraryTests.PackageCopy();
            string adapter = copy.AdapterOf("UniversalPipeline");
            File.AppendAllText(adapter, "\nstruct GtRigPair { float a; };\n"
                                        + "GtRigPair GT_RigPick(bool c, GtRigPair x, GtRigPair y) { return c ? x : y; }\n");
            var (code, output) = RunScript("--package", copy.Root, "--shaderlib", ShaderLib, "--check", "pipelines",
                                           "--pipeline", "URP", "--variants", "base", "--quiet");
            Assert.That(output, Does.Match(@"shaderlab URP: \d+ compiled, 0 failed"), "glslang accepts it");
            var m = Regex.Match(output, @"shaderlab dxc URP: (\d+) compiled, (\d+) failed");
            Assert.That(m.Success, Is.True, output);
            Assert.That(int.Parse(m.Groups[2].Value), Is.GreaterThan(0), output);
            Assert.That(output, Does.Match(@"dxc FAIL URP [^\n]*\n\s+[^\n]*URPAdapter\.hlsl:\d+:\d+: error: conditional operator"), output);
            Assert.That(code, Is.EqualTo(1));
        }

        /// <summary>
        /// A lint finding fails the check: a copy whose CacheTileFactors returns on a value read from
        /// its RW buffer before the group's barrier (FXC error X3663), on a kernel both compilers accept.
        /// </summary>
        [Test]
        public void ALintFindingFailsTheCheck()
        {
            using var copy = new ShaderLibraryTests.PackageCopy();
            string kernels = Path.Combine(copy.Root, "Shaders", "Cache", "VertexCacheKernels.hlsl");
            var lines = File.ReadAllLines(kernels).ToList();
            int barrier = lines.FindIndex(l => l.Trim() == "GroupMemoryBarrierWithGroupSync();");
            Assert.That(barrier, Is.GreaterThan(0), "no barrier in " + kernels);
            lines.Insert(barrier, "    if (_TileFactorsRW[tile].edge.x < 0.0) return;");
            File.WriteAllLines(kernels, lines);
            int line = barrier + 2;   // the barrier, 1-based, after the inserted line
            var (code, output) = RunScript("--package", copy.Root, "--shaderlib", ShaderLib, "--check", "pipelines",
                                           "--pipeline", "Compute", "--variants", "base", "--quiet");
            Assert.That(output, Does.Match(@"shaderlab dxc Compute: \d+ compiled, 0 failed"), "DXC accepts it");
            Assert.That(output, Does.Contain($"lint barrier-in-varying-flow: Shaders/Cache/VertexCacheKernels.hlsl:{line}: "), output);
            Assert.That(output, Does.Match(@"shaderlab lint Compute: [1-9]\d* findings"), output);
            Assert.That(code, Is.EqualTo(1));
        }

        /// <summary>
        /// The glslang limit is recognised by its own spirv-val error only: any other error in the
        /// Built-in SHADOWS_SCREEN variants is a failure, not a glslang-limit.
        /// </summary>
        [Test]
        public void AnotherErrorInTheScreenShadowVariantsIsAFailureNotALimit()
        {
            using var copy = new ShaderLibraryTests.PackageCopy();
            string adapter = copy.AdapterOf(null);
            File.AppendAllText(adapter, "\n#if defined(SHADOWS_SCREEN)\nfloat4 GT_RigBrokenOnPurpose() { return GT_RigUndeclaredFunction(); }\n#endif\n");
            var (code, output) = RunScript("--package", copy.Root, "--shaderlib", ShaderLib, "--check", "pipelines",
                                           "--pipeline", "Builtin", "--variants", "SHADOWS_SCREEN", "--quiet");
            var m = Regex.Match(output, @"shaderlab Builtin: (\d+) compiled, (\d+) failed, (\d+) glslang-limit");
            Assert.That(m.Success, Is.True, output);
            Assert.That(int.Parse(m.Groups[1].Value), Is.EqualTo(0), output);
            Assert.That(int.Parse(m.Groups[3].Value), Is.EqualTo(0), output);
            Assert.That(output, Does.Not.Contain("glslang-limit: "));
            Assert.That(output, Does.Match(@"FAIL Builtin [^\n]*shadows_screen stage frag[^\n]*\n\s+ERROR: [^\n]*GT_RigUndeclaredFunction"), output);
            Assert.That(code, Is.EqualTo(1));
        }

        /// <summary>
        /// HDRP's ShaderVariablesLightLoop.hlsl has no include guard (the mock had one): included after
        /// ShaderVariables.hlsl, every light-loop global is declared twice. The check must see it.
        /// </summary>
        [Test]
        public void TheHdrpDoubleIncludeFailsTheCheck()
        {
            using var copy = new ShaderLibraryTests.PackageCopy();
            string adapter = copy.AdapterOf("HDRenderPipeline");
            const string inc = "#include \"Packages/com.unity.render-pipelines.high-definition/Runtime/Lighting/LightLoop/ShaderVariablesLightLoop.hlsl\"\n";
            File.AppendAllText(adapter, "\n" + inc + inc);
            var (code, output) = RunScript("--package", copy.Root, "--shaderlib", ShaderLib, "--check", "pipelines",
                                           "--pipeline", "HDRP", "--variants", "base", "--quiet");
            var m = Regex.Match(output, @"shaderlab HDRP: (\d+) compiled, (\d+) failed");
            Assert.That(m.Success, Is.True, output);
            Assert.That(int.Parse(m.Groups[2].Value), Is.GreaterThan(0), output);
            Assert.That(output, Does.Match(@"FAIL HDRP [^\n]*\n\s+ERROR: [^\n]*ShaderVariablesLightLoop\.hlsl[^\n]*redefinition"), output);
            Assert.That(code, Is.EqualTo(1));
        }

        /// <summary>
        /// Unity's PackageRequirements rules on a copy with known blocks: a SubShader needing an absent
        /// package, a version outside its range or a later Unity is skipped; Built-in ones (no block)
        /// are used everywhere.
        /// </summary>
        [TestCase("\"com.unity.render-pipelines.universal\": \"[14.0,15.0)\"", "\"com.unity.render-pipelines.high-definition\"",
                  "Builtin", "URP Builtin", "HDRP Builtin")]
        [TestCase("\"com.unity.render-pipelines.universal\": \"15.0\"", "\"com.unity.render-pipelines.high-definition\": \"unity=2022.3\"",
                  "Builtin", "Builtin", "HDRP Builtin")]
        [TestCase("\"com.unity.render-pipelines.universal\": \"[14.0.9]\" \"unity\": \"2023.1\"", "\"com.unity.render-pipelines.high-definition\": \"(14.0.11,14.0.12]\"",
                  "Builtin", "Builtin", "HDRP Builtin")]
        public void ProjectKindsSkipExactlyTheSubShadersWhoseRequirementsFail(string urp, string hdrp, string builtinUses, string urpUses, string hdrpUses)
        {
            using var copy = new ShaderLibraryTests.PackageCopy();
            copy.SetRequirements(urp, hdrp);
            var (code, output) = RunScript("--package", copy.Root, "--shaderlib", ShaderLib, "--check", "projects", "--selection-only");
            Assert.That(code, Is.EqualTo(0), output);
            foreach (var (kind, uses) in new[] { ("builtin", builtinUses), ("urp", urpUses), ("hdrp", hdrpUses) })
            {
                var m = Regex.Match(output, $@"project {kind}: subshaders used (\d+) \(([^)]*)\), skipped (.*); passes");
                Assert.That(m.Success, Is.True, output);
                var used = m.Groups[2].Value.Split(", ").Select(u => u.Split(' ')[1]).ToList();
                var skipped = Regex.Matches(m.Groups[3].Value, @"\d+ (\w+) \(").Select(x => x.Groups[1].Value).ToList();
                var expected = uses.Split(' ');
                Assert.That(used.Distinct(), Is.EquivalentTo(expected), m.Value);
                Assert.That(skipped.Intersect(expected), Is.Empty, m.Value);
                Assert.That(used.Count + skipped.Count, Is.EqualTo(copy.SubShaderCount), m.Value);
            }
        }

        [TestCase("\"com.unity.render-pipelines.universal\": \"14.x\"", "version '14.x'")]
        [TestCase("\"com.unity.render-pipelines.universal\": \"[15.0,14.0]\"", "is empty")]
        [TestCase("\"unity\"", "\"unity\" needs a version range")]
        public void AnInvalidRequirementIsAnErrorNamingTheEntry(string urp, string message)
        {
            using var copy = new ShaderLibraryTests.PackageCopy();
            copy.SetRequirements(urp, "\"com.unity.render-pipelines.high-definition\"");
            var (code, output) = RunScript("--package", copy.Root, "--shaderlib", ShaderLib, "--check", "projects", "--selection-only");
            Assert.That(code, Is.EqualTo(2), output);
            Assert.That(output, Does.Contain("SubShader ").And.Contain(message), output);
        }

        [Test]
        public void MissingDxcIsAnErrorSayingWhere()
        {
            var (code, output) = RunScript("--dxc", Path.Combine(Path.GetTempPath(), "gt-no-such-dxc"), "--variants", "base");
            Assert.That(code, Is.EqualTo(2), output);
            Assert.That(output, Does.Contain("no DXC there").And.Contain("gt-no-such-dxc"), output);
        }

        [Test]
        public void MissingLibrariesAreAnErrorSayingWhere()
        {
            var (code, output) = RunScript("--shaderlib", Path.Combine(Path.GetTempPath(), "gt-no-such-shaderlib"), "--variants", "base");
            Assert.That(code, Is.EqualTo(2), output);
            Assert.That(output, Does.Contain("Unity's shader libraries not found").And.Contain("gt-no-such-shaderlib"), output);
        }
    }
}
