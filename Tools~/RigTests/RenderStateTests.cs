// Tools~/rig/render_state.py: the render state of a ShaderLab pass as harness options, read with
// shaderlab.py's parser. The rig's draws take their Cull, ZTest, ZWrite, ZClip and ColorMask from it
// (HarnessRun.Harness, the rig's scripts), so what it reads is what the harness draws.
using System.IO;
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

        [Test]
        public void NoForwardPassForTheDraw_Fails()
        {
            HarnessRun r = Run(Shader((null, "Tessellated", "ShadowCaster", "")));
            Assert.That(r.ExitCode, Is.EqualTo(2), r.Stdout);
            Assert.That(r.Stderr, Does.Contain("no pass with LightMode UniversalForwardOnly, ForwardOnly, ForwardBase"));
        }
    }
}
