// gt pipeline_pass_all (Tools~/rig/pipeline_pass_all.py) draws every variant of every pass of each pipeline's tessellated
// SubShader; it is not part of gt test (it takes about half an hour). This checks, without drawing, that it enumerates
// the variants gt shaderlab compiles for those SubShaders and that every keyword the shader declares is among them.
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    [TestFixture]
    public class PipelinePassAllTests
    {
        static string[] Lines(string script, params string[] args)
        {
            string root = HarnessRun.PackageRoot();
            HarnessRun r = HarnessRun.Start("python3", new[] { Path.Combine(root, "Tools~", "rig", script) }.Concat(args).ToList(),
                new Dictionary<string, string>());
            Assert.That(r.ExitCode, Is.EqualTo(0), script + " failed:\n" + r.Stdout + r.Stderr);
            return r.Stdout.Split('\n').Where(l => l.Length > 0).ToArray();
        }

        [Test]
        public void TheAllVariantsCommand_ListsShaderlabsVariantsOfEachPipelinesTessellatedSubShader()
        {
            string[] all = Lines("pipeline_pass_all.py", "--list");
            string[] shaderlab = Lines("shaderlab.py", "--list-variants");
            // The first SubShader of each pipeline in the file is its tessellated one (Unity picks the first it can run).
            var first = new Dictionary<string, string>();
            foreach (string[] f in shaderlab.Select(l => l.Split('\t')))
                if (!first.ContainsKey(f[0])) first[f[0]] = f[1];
            string[] expected = shaderlab.Where(l => { var f = l.Split('\t'); return first[f[0]] == f[1]; }).ToArray();
            var perPipeline = all.GroupBy(l => l.Split('\t')[0]).ToDictionary(g => g.Key, g => g.Count());
            TestContext.Out.WriteLine($"pipeline_pass_all --list: {all.Length} variants ({string.Join(", ", perPipeline.Select(kv => $"{kv.Key} {kv.Value}"))}); " +
                                      $"shaderlab: {shaderlab.Length} over every SubShader, {expected.Length} in the tessellated ones");
            Assert.That(first.Keys, Is.EquivalentTo(new[] { "URP", "HDRP", "Builtin" }));
            Assert.That(all, Is.EqualTo(expected), "pipeline_pass_all draws exactly shaderlab's variants of the tessellated SubShaders");

            // Independently of shaderlab's enumeration: every keyword the shader's passes declare (and multi_compile_fog's
            // three) is drawn by some variant.
            string rootDir = HarnessRun.PackageRoot();
            string text = File.ReadAllText(Path.Combine(rootDir, "Shaders", "GregoryTerrain.shader")) +
                          string.Concat(Directory.GetFiles(Path.Combine(rootDir, "Shaders", "Pipelines"), "ShaderKeywords.*.cs.hlsl").Select(File.ReadAllText));
            var declared = Regex.Matches(text, @"#pragma\s+(?:multi_compile|shader_feature)\w*([^\r\n]*)")
                .SelectMany(m => m.Groups[1].Value.Split(' ', '\t')).Where(k => k.Length > 0 && !Regex.IsMatch(k, "^_+$")).ToHashSet();
            if (Regex.IsMatch(text, @"#pragma\s+multi_compile_fog")) declared.UnionWith(new[] { "FOG_LINEAR", "FOG_EXP", "FOG_EXP2" });
            var drawn = all.SelectMany(l => l.Split('\t')[3].Split(' ')).ToHashSet();
            Assert.That(declared.Count, Is.GreaterThan(20), "keywords found in the shader's pragmas");
            Assert.That(declared.Where(k => !drawn.Contains(k)), Is.Empty, "declared keywords no variant draws");
            // Built-in's screen-space shadow and its mobile path are both drawn.
            Assert.That(all, Does.Contain("Builtin\t4\tForwardBase\tSHADOWS_SCREEN").And.Contain("Builtin\t4\tForwardBase\tSHADOWS_SCREEN UNITY_NO_SCREENSPACE_SHADOWS"));
        }
    }
}
