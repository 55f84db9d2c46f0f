// Tools~/rig/render_state.py: the render state of a ShaderLab pass as harness options, read with
// shaderlab.py's parser. The rig's draws take their Cull, ZTest, ZWrite, ZClip and ColorMask from it
// (HarnessRun.Harness, the rig's scripts), so what it reads is what the harness draws.
using System.IO;
using System.Linq;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    [TestFixture]
    public class RenderStateTests
    {
        static HarnessRun Run(string shaderText, params string[] args)
        {
            string dir = Path.Combine(HarnessRun.PackageRoot(), ".build", "rigtests-render-state");
            Directory.CreateDirectory(dir);
            string shader = Path.Combine(dir, TestContext.CurrentContext.Test.ID + ".shader");
            File.WriteAllText(shader, shaderText);
            var a = new System.Collections.Generic.List<string> { HarnessRun.PackageRoot() + "/Tools~/rig/render_state.py", "--shader", shader };
            a.AddRange(args);
            return HarnessRun.Start("python3", a);
        }

        /// <summary>A shader of one SubShader per (pipeline tag, draw tag, forward LightMode, pass state).</summary>
        static string Shader(params (string pipeline, string draw, string lightMode, string state)[] subs)
        {
            var s = new System.Text.StringBuilder("Shader \"T\"\n{\n");
            foreach (var (pipeline, draw, lightMode, state) in subs)
            {
                string rp = pipeline == null ? "" : $"\"RenderPipeline\" = \"{pipeline}\" ";
                s.Append($"    SubShader\n    {{\n        Tags {{ {rp}\"GregoryTerrainDraw\" = \"{draw}\" }}\n");
                s.Append($"        Pass\n        {{\n            Name \"P\"\n            Tags {{ \"LightMode\" = \"{lightMode}\" }}\n");
                s.Append($"            Stencil {{ Ref 2 Pass Replace }}\n            {state}\n");
                s.Append("            HLSLPROGRAM\n            // Cull Front inside a program is not ShaderLab\n            ENDHLSL\n        }\n    }\n");
            }
            return s.Append("}\n").ToString();
        }

        [Test]
        public void TheShippedShader_ForwardPassesOfBothDraws_AreCullBackWithShaderLabsDepth()
        {
            foreach (string draw in new[] { "tessellated", "fallback" })
            {
                HarnessRun r = HarnessRun.Start("python3", new[] { HarnessRun.PackageRoot() + "/Tools~/rig/render_state.py", "--draw", draw });
                Assert.That(r.ExitCode, Is.EqualTo(0), r.Stderr);
                Assert.That(r.Stdout.Trim(), Is.EqualTo("--cull back --ztest lequal --zwrite on --zclip on --color-mask rgba"), draw);
            }
        }

        [Test]
        public void APassThatNamesNothing_GetsShaderLabsDefaults_AndTheSubShadersOwnState()
        {
            HarnessRun plain = Run(Shader((null, "Tessellated", "ForwardBase", "")));
            Assert.That(plain.ExitCode, Is.EqualTo(0), plain.Stderr);
            Assert.That(plain.Stdout.Trim(), Is.EqualTo("--cull back --ztest lequal --zwrite on --zclip on --color-mask rgba"));
            HarnessRun named = Run(Shader((null, "Tessellated", "ForwardBase", "Cull Off\n ZTest Always ZWrite Off\n ZClip False\n ColorMask RGB")));
            Assert.That(named.ExitCode, Is.EqualTo(0), named.Stderr);
            Assert.That(named.Stdout.Trim(), Is.EqualTo("--cull off --ztest always --zwrite off --zclip off --color-mask rgb"),
                "ShaderLab is free-form: two commands on one line are both read");
            HarnessRun inherited = Run(Shader((null, "Tessellated", "ForwardBase", "")).Replace("Tags { \"GregoryTerrainDraw\" = \"Tessellated\" }",
                "Tags { \"GregoryTerrainDraw\" = \"Tessellated\" }\n        Cull Front ZWrite Off"));
            Assert.That(inherited.ExitCode, Is.EqualTo(0), inherited.Stderr);
            Assert.That(inherited.Stdout.Trim(), Is.EqualTo("--cull front --ztest lequal --zwrite off --zclip on --color-mask rgba"), "the SubShader's state");
        }

        [Test]
        public void ForwardPassesThatDisagree_FailNamingBoth()
        {
            HarnessRun r = Run(Shader(("UniversalPipeline", "Tessellated", "UniversalForwardOnly", "Cull Back"),
                                      (null, "Tessellated", "ForwardBase", "Cull Front"),
                                      (null, "Fallback", "ForwardBase", "Cull Off")));
            Assert.That(r.ExitCode, Is.EqualTo(2), r.Stdout);
            Assert.That(r.Stderr, Does.Contain("SubShader 1 (Builtin) Pass \"P\" has Cull front but SubShader 0 (URP) Pass \"P\" has Cull back"));
            HarnessRun fallback = Run(Shader((null, "Tessellated", "ForwardBase", "Cull Back"), (null, "Fallback", "ForwardBase", "Cull Off")), "--draw", "fallback");
            Assert.That(fallback.Stdout.Trim(), Does.StartWith("--cull off "), "each draw reads its own SubShaders");
        }

        [TestCase("Cull [_Cull]", "Cull [_Cull] reads a material property")]
        [TestCase("ZTest LessEqual", "ZTest 'LessEqual' is not a value ShaderLab takes")]
        [TestCase("ColorMask GR", "ColorMask 'GR' is not a value ShaderLab takes")]
        public void AStateTheRigCannotDraw_FailsNamingThePassAndCommand(string state, string expected)
        {
            HarnessRun r = Run(Shader((null, "Tessellated", "ForwardBase", state)));
            Assert.That(r.ExitCode, Is.EqualTo(2), r.Stdout);
            Assert.That(r.Stderr, Does.Contain("SubShader 0 (Builtin) Pass \"P\"").And.Contain(expected));
        }

        /// <summary>stencil_options of the shader's first pass, through python (one line: the options, or the error).</summary>
        static HarnessRun StencilOptions(string shaderText)
        {
            string dir = Path.Combine(HarnessRun.PackageRoot(), ".build", "rigtests-render-state");
            Directory.CreateDirectory(dir);
            string shader = Path.Combine(dir, TestContext.CurrentContext.Test.ID + ".shader");
            File.WriteAllText(shader, shaderText);
            string code = "import sys; sys.path.insert(0, sys.argv[1]); import render_state as r, shaderlab\n" +
                          "sub = shaderlab.parse_shader(sys.argv[2])[0]\n" +
                          "try: print(r.stencil_options(sub, sub.passes[0], 'P'))\n" +
                          "except r.RenderStateError as e: print('error', e)";
            return HarnessRun.Start("python3", new[] { "-c", code, HarnessRun.PackageRoot() + "/Tools~/rig", shader });
        }

        [Test]
        public void TheStencilBlock_IsThePassesElseTheSubShaders_AsOneHarnessOption_AndNoneWithoutOne()
        {
            // Shader() writes "Stencil { Ref 2 Pass Replace }" in every pass.
            HarnessRun own = StencilOptions(Shader((null, "Tessellated", "ForwardBase", "")));
            Assert.That(own.Stdout.Trim(), Is.EqualTo("['--stencil', 'Ref 2 Pass Replace']"), own.Stderr);
            string shared = Shader((null, "Tessellated", "ForwardBase", "")).Replace("Stencil { Ref 2 Pass Replace }", "")
                .Replace("\"Tessellated\" }", "\"Tessellated\" }\n        Stencil\n        {\n            WriteMask 6\n            Ref 0 CompBack NotEqual\n        }");
            HarnessRun sub = StencilOptions(shared);
            Assert.That(sub.Stdout.Trim(), Is.EqualTo("['--stencil', 'WriteMask 6 Ref 0 CompBack NotEqual']"), sub.Stderr);
            HarnessRun none = StencilOptions(Shader((null, "Tessellated", "ForwardBase", "")).Replace("Stencil { Ref 2 Pass Replace }", ""));
            Assert.That(none.Stdout.Trim(), Is.EqualTo("[]"), "no Stencil block: Unity's stencil test off, no option");
        }

        [TestCase("Stencil { Ref [_StencilRef] Pass Replace }", "Stencil Ref [_StencilRef] reads a material property")]
        [TestCase("Stencil { Ref 256 }", "Stencil Ref '256' is not a value ShaderLab takes")]
        [TestCase("Stencil { Ref 1 Comp LessEqual }", "Stencil Comp 'LessEqual' is not a value ShaderLab takes")]
        [TestCase("Stencil { Ref 1 Pass Incr }", "Stencil Pass 'Incr' is not a value ShaderLab takes")]
        [TestCase("Stencil { Ref 1 Mask 3 }", "Stencil command 'Mask' is not one ShaderLab takes")]
        [TestCase("Stencil { Ref 1 Pass }", "is not command-value pairs")]
        public void AStencilBlockTheHarnessCannotDraw_FailsNamingThePassAndCommand(string block, string expected)
        {
            HarnessRun r = StencilOptions(Shader((null, "Tessellated", "ForwardBase", "")).Replace("Stencil { Ref 2 Pass Replace }", block));
            Assert.That(r.Stdout.Trim(), Does.StartWith("error P: ").And.Contain(expected), r.Stderr);
        }

        [Test]
        public void TheShippedShader_HdrpPasses_CarryHdrpsStencilBlocks_AndTheOthersNone()
        {
            string code = "import sys; sys.path.insert(0, sys.argv[1]); import render_state as r, shaderlab\n" +
                          "for sub in shaderlab.parse_shader(sys.argv[2]):\n" +
                          "    for p in sub.passes: print(sub.pipeline, p.name, ' '.join(r.stencil_options(sub, p, p.name)))";
            HarnessRun r = HarnessRun.Start("python3", new[] { "-c", code, HarnessRun.PackageRoot() + "/Tools~/rig",
                HarnessRun.PackageRoot() + "/Shaders/GregoryTerrain.shader" });
            Assert.That(r.ExitCode, Is.EqualTo(0), r.Stderr);
            string[] lines = r.Stdout.Split('\n', System.StringSplitOptions.RemoveEmptyEntries);
            Assert.That(lines.Where(l => l.Contains("--stencil")), Is.EqualTo(new[] {
                "HDRP DepthForwardOnly --stencil WriteMask 9 Ref 1 Comp Always Pass Replace", "HDRP ForwardOnly --stencil WriteMask 6 Ref 0 Comp Always Pass Replace",
                "HDRP DepthForwardOnly --stencil WriteMask 9 Ref 1 Comp Always Pass Replace", "HDRP ForwardOnly --stencil WriteMask 6 Ref 0 Comp Always Pass Replace" }),
                "both HDRP SubShaders' depth and forward passes (HDRP's StencilUsage bits: see Tools~/rig/README.md)");
            Assert.That(lines.Count(l => !l.Contains("--stencil")), Is.GreaterThan(10), "every other pass: no stencil");
        }

        [Test]
        public void NoForwardPassForTheDraw_Fails()
        {
            HarnessRun r = Run(Shader((null, "Tessellated", "ShadowCaster", "")));
            Assert.That(r.ExitCode, Is.EqualTo(2), r.Stdout);
            Assert.That(r.Stderr, Does.Contain("no pass with LightMode UniversalForwardOnly, ForwardOnly, ForwardBase"));
        }
    }
}
