using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>
    /// gt shaders' SPIR-V cache (Tools~/rig/shaders.py, SpirvCache) on a copy of the package's shaders
    /// with a cache of its own: a stage compiled before is reused with the same bytes, and a change
    /// in a file the stages include makes glslang compile every stage again.
    /// </summary>
    [TestFixture, Parallelizable(ParallelScope.Self)]
    public class ShaderCacheTests
    {
        string _root;

        [SetUp]
        public void CopyTheShaders()
        {
            _root = Path.Combine(Path.GetTempPath(), "gt-shader-cache-" + Guid.NewGuid().ToString("N"));
            Copy(PackageRoot.Combine("Shaders"), Path.Combine(_root, "Shaders"));
            Copy(PackageRoot.Combine("Tools~", "rig"), Path.Combine(_root, "Tools~", "rig"));
        }

        [TearDown]
        public void RemoveTheCopy()
        {
            if (Directory.Exists(_root)) Directory.Delete(_root, true);
        }

        static void Copy(string from, string to)
        {
            foreach (string dir in Directory.GetDirectories(from, "*", SearchOption.AllDirectories))
                Directory.CreateDirectory(Path.Combine(to, Path.GetRelativePath(from, dir)));
            Directory.CreateDirectory(to);
            foreach (string file in Directory.GetFiles(from, "*", SearchOption.AllDirectories))
                File.Copy(file, Path.Combine(to, Path.GetRelativePath(from, file)));
        }

        /// <summary>gt shaders --spirv-only --only base into OUT of the copy: (stages reused, stages compiled).</summary>
        (int reused, int compiled) Compile(string output)
        {
            string stdout = ReadbackRun.Exec("python3", new[]
            {
                Path.Combine(_root, "Tools~", "rig", "shaders.py"), Path.Combine(_root, output), "--clean", "--spirv-only", "--only", "base",
                "--dxc", Path.Combine(PackageRoot.Path, "..", "shared", "dxc", "bin", "dxc"),
            }, new Dictionary<string, string> { ["GT_SHADER_CACHE"] = Path.Combine(_root, "cache") });
            Match m = Regex.Match(stdout, @"shader cache: (\d+) stages reused, (\d+) compiled by glslang");
            Assert.That(m.Success, Is.True, "no shader cache line:\n" + stdout);
            return (int.Parse(m.Groups[1].Value), int.Parse(m.Groups[2].Value));
        }

        static string[] Modules(string folder) =>
            Directory.GetFiles(folder, "*.spv").OrderBy(f => f, StringComparer.Ordinal).ToArray();

        [Test]
        public void AStageCompiledBeforeIsReusedWithTheSameBytes()
        {
            Assert.That(Compile("first"), Is.EqualTo((0, 5)), "an empty cache: every stage compiled");
            Assert.That(Compile("second"), Is.EqualTo((5, 0)), "the same inputs: every stage reused");
            string[] first = Modules(Path.Combine(_root, "first", "base")), second = Modules(Path.Combine(_root, "second", "base"));
            Assert.That(second.Select(Path.GetFileName), Is.EqualTo(first.Select(Path.GetFileName)));
            for (int i = 0; i < first.Length; i++)
                Assert.That(File.ReadAllBytes(second[i]), Is.EqualTo(File.ReadAllBytes(first[i])), Path.GetFileName(first[i]));
        }

        [Test]
        public void AChangedIncludeCompilesEveryStageAgain()
        {
            Assert.That(Compile("first"), Is.EqualTo((0, 5)));
            File.AppendAllText(Path.Combine(_root, "Shaders", "Pipelines", "TerrainStages.hlsl"), "\nstatic const float GtShaderCacheProbe = 1.0;\n");
            Assert.That(Compile("second"), Is.EqualTo((0, 5)), "TerrainStages.hlsl changed: no stage may come from the cache");
        }
    }
}
