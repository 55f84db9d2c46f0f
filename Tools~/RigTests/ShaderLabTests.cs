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
    /// Reads Shaders/GregoryTerrain.shader as text (no Unity here) and checks its structure against
    /// the stages and the rig: pragmas per SubShader, keywords against Tools~/rig/shader_variants.txt,
    /// include paths, LightMode tags per pipeline. Compiling the passes against Unity's real shader
    /// libraries is ShaderLibraryTests' job (<c>gt shaderlab</c>).
    /// </summary>
    [TestFixture]
    public class ShaderLabTests
    {
        const string PackageName = "com.gregoryterrain.tessellation";
        /// <summary>The keywords a script switches at run time, as Core declares them (ShaderKeywords).</summary>
        static readonly string[] RuntimeToggledKeywords = ShaderKeywords.SwitchedBy(KeywordSwitch.Renderer).Select(k => k.name).ToArray();
        /// <summary>The renderer's Vertex evaluation switch: declared by the tessellated passes only.</summary>
        const string VertexCacheKeyword = "GT_VERTEX_CACHE";
        static readonly string[] VertexSourceSet = { "multi_compile_local", "_", "GT_RANGE_ORIGIN", "GT_LOD", VertexCacheKeyword };
        /// <summary>The most package-keyword combinations a tessellated forward pass may compile (issue 39).</summary>
        const int MaxForwardCombinations = 256;
        static readonly string[] ForwardModes = { "UniversalForwardOnly", "ForwardOnly", "ForwardBase" };

        sealed class PassInfo
        {
            public string Name, LightMode, Program;   // Program: the SubShader's HLSLINCLUDE, then the pass's HLSLPROGRAM
            public string OwnProgram;                 // the pass's HLSLPROGRAM alone
            public string OwnAsWritten;               // the same, as the .shader writes it
            public List<string[]> Pragmas;
            public HashSet<string> Keywords;          // the package's: shader_feature*
            public HashSet<string> PipelineKeywords;  // Unity's: multi_compile*
        }

        sealed class SubShaderInfo
        {
            public int Index;
            public string Pipeline;   // "URP", "HDRP", "Builtin"
            public bool Tessellated;
            public string Body;
            public string Shared;   // its HLSLINCLUDE blocks, which Unity pastes at the top of every pass's program, files read with #include_with_pragmas in place
            public string SharedAsWritten;   // the same, as the .shader writes them
            public List<PassInfo> Passes;
            public override string ToString() => $"SubShader {Index} ({Pipeline}, {(Tessellated ? "tessellated" : "fallback")})";
        }

        List<SubShaderInfo> _subShaders;

        [OneTimeSetUp]
        public void Parse()
        {
            string text = StripComments(File.ReadAllText(PackageRoot.Combine("Shaders", "GregoryTerrain.shader")));
            _subShaders = new List<SubShaderInfo>();
            foreach (string sub in Blocks(text, "SubShader"))
            {
                var info = new SubShaderInfo { Index = _subShaders.Count, Body = sub, Passes = new List<PassInfo>() };
                string pipeline = Regex.Match(OuterPart(sub), "\"RenderPipeline\"\\s*=\\s*\"(\\w+)\"").Groups[1].Value;
                info.Pipeline = pipeline == "UniversalPipeline" ? "URP" : pipeline == "HDRenderPipeline" ? "HDRP" : pipeline == "" ? "Builtin" : pipeline;
                info.SharedAsWritten = string.Concat(Regex.Matches(OuterPart(sub), @"\bHLSLINCLUDE\b(.*?)\bENDHLSL\b", RegexOptions.Singleline).Select(x => x.Groups[1].Value));
                info.Shared = WithIncludedPragmas(info.SharedAsWritten);
                foreach (string pass in Blocks(sub, "Pass"))
                {
                    var m = Regex.Match(pass, "HLSLPROGRAM(.*?)ENDHLSL", RegexOptions.Singleline);
                    string own = m.Success ? WithIncludedPragmas(m.Groups[1].Value) : "";
                    string program = info.Shared + own;
                    var pragmas = program.Split('\n').Select(l => l.Trim()).Where(l => l.StartsWith("#pragma"))
                        .Select(l => l.Substring("#pragma".Length).Split(new[] { ' ', '\t' }, StringSplitOptions.RemoveEmptyEntries)).ToList();
                    info.Passes.Add(new PassInfo
                    {
                        Name = Regex.Match(pass, "\\bName\\s+\"([^\"]+)\"").Groups[1].Value,
                        LightMode = Regex.Match(pass, "\"LightMode\"\\s*=\\s*\"(\\w+)\"").Groups[1].Value,
                        Program = program,
                        OwnProgram = own,
                        OwnAsWritten = m.Success ? m.Groups[1].Value : "",
                        Pragmas = pragmas,
                        Keywords = new HashSet<string>(pragmas.Where(p => p.Length > 1 && p[0].StartsWith("shader_feature"))
                            .SelectMany(p => p.Skip(1)).Where(k => k != "_")
                            .Concat(pragmas.Where(p => p.Length > 1 && p[0] == "multi_compile_local")
                                .SelectMany(p => p.Skip(1)).Where(k => k.StartsWith("GT_")))),
                        PipelineKeywords = new HashSet<string>(pragmas.Where(p => p.Length > 1 && p[0].StartsWith("multi_compile"))
                            .SelectMany(p => p.Skip(1)).Where(k => k != "_" && !k.StartsWith("GT_"))),
                    });
                }
                info.Tessellated = info.Passes.Any(p => HasPragma(p, "hull"));
                _subShaders.Add(info);
            }
            TestContext.Out.WriteLine(string.Join("\n", _subShaders.Select(s => $"{s}: " + string.Join(", ", s.Passes.Select(p => $"{p.Name}[{p.LightMode}]")))));
        }

        [Test]
        public void EveryPipelineHasATessellatedThenAFallbackSubShader()
        {
            Assert.That(_subShaders.Select(s => s.Pipeline + (s.Tessellated ? "+tess" : "+fallback")),
                Is.EqualTo(new[] { "URP+tess", "URP+fallback", "HDRP+tess", "HDRP+fallback", "Builtin+tess", "Builtin+fallback" }));
        }

        [Test]
        public void EveryPassHasTheStagePragmasOfItsSubShader()
        {
            foreach (SubShaderInfo s in _subShaders)
                foreach (PassInfo p in s.Passes)
                {
                    string where = $"{s} pass {p.Name}";
                    Assert.That(p.OwnProgram, Is.Not.Empty, where + ": HLSLPROGRAM block");
                    if (s.Tessellated)
                    {
                        Assert.That(PragmaArg(p, "vertex"), Is.EqualTo("vert"), where);
                        Assert.That(PragmaArg(p, "hull"), Is.EqualTo("hull_shader"), where);
                        Assert.That(PragmaArg(p, "domain"), Is.EqualTo("domain_shader"), where);
                        Assert.That(PragmaArg(p, "fragment"), Is.EqualTo("frag"), where);
                        Assert.That(p.Pragmas.Any(a => a.Length >= 2 && a[0] == "require" && a.Contains("tessellation")), Is.True,
                            where + ": #pragma require tessellation");
                    }
                    else
                    {
                        Assert.That(PragmaArg(p, "vertex"), Is.EqualTo("vert_fallback"), where);
                        Assert.That(PragmaArg(p, "fragment"), Is.EqualTo("frag"), where);
                        Assert.That(HasPragma(p, "hull") || HasPragma(p, "domain"), Is.False, where + ": no hull/domain in a fallback");
                        Assert.That(p.Pragmas.Any(a => a.Contains("tessellation")), Is.False, where + ": a fallback must not require tessellation");
                        Assert.That(Regex.IsMatch(p.Program, @"#define\s+GT_FALLBACK\b"), Is.True, where + ": GT_FALLBACK");
                    }
                    Assert.That(Regex.Matches(p.Program, @"#define\s+GT_PASS_(FORWARD|SHADOWCASTER|DEPTH|DEPTH_NORMALS|SCENE_SELECTION|SCENE_PICKING)\b").Count, Is.EqualTo(1),
                        where + ": exactly one GT_PASS_* define");
                }
        }

        [Test]
        public void KeywordsAreTheShippedVariantKeywordsWithoutTheRigOnlyOnes()
        {
            var listed = File.ReadAllLines(PackageRoot.Combine("Tools~", "rig", "shader_variants.txt"))
                .Select(l => l.Trim()).Where(l => l.Length > 0 && !l.StartsWith("#") && l != "-")
                .SelectMany(l => l.Split(' ', StringSplitOptions.RemoveEmptyEntries)).Distinct().ToList();
            // GT_SNOW (SnowSimulator's keyword) is declared by the .shader; the snow rendering branch
            // lists it in shader_variants.txt too, so after that merge the union changes nothing.
            // GT_VERTEX_CACHE (the renderer's) likewise, once the rig's cache variants are listed,
            // and GT_NOISE_TABLE (the tiled-noise toggle) once the rig's table variants are.
            var shipped = new HashSet<string>(listed.Except(RigKeywords.RigOnly)) { "GT_SNOW", VertexCacheKeyword, "GT_NOISE_TABLE" };
            Assert.That(listed, Does.Contain("GT_PAPER_MODE").And.Contain("GT_READBACK"), "rig-only keywords are in the list");
            Assert.That(shipped, Is.EquivalentTo(new[] { "GT_NOISE", "GT_NOISE_TABLE", "GT_HEIGHT_COLOR", "GT_SNOW", VertexCacheKeyword, "GT_DEBUG_NORMALS", "GT_DEBUG_PATCH_ID", "GT_DEBUG_TESS_FACTOR", "GT_LOD", "GT_RANGE_ORIGIN" }));

            var all = new HashSet<string>(_subShaders.SelectMany(s => s.Passes).SelectMany(p => p.Keywords));
            Assert.That(all, Is.EquivalentTo(shipped), "keywords declared anywhere in the .shader");
            foreach (SubShaderInfo s in _subShaders)
                foreach (PassInfo p in s.Passes)
                {
                    string where = $"{s} pass {p.Name}";
                    // The package's keywords: shader_feature_local (a material's toggles, stripped
                    // from builds when unused), except those a script switches at run time (GT_SNOW,
                    // by SnowSimulator): a shader_feature variant no material enables in the editor
                    // would be stripped from the player, so those are multi_compile_local.
                    foreach (string[] a in p.Pragmas.Where(a => a[0].StartsWith("shader_feature")))
                    {
                        Assert.That(a[0], Is.EqualTo("shader_feature_local"), where);
                        Assert.That(a.Intersect(RuntimeToggledKeywords), Is.Empty, where + ": a run-time keyword as shader_feature");
                    }
                    foreach (string[] a in p.Pragmas.Where(a => a[0].StartsWith("multi_compile") && a.Any(k => k.StartsWith("GT_"))))
                    {
                        Assert.That(a[0], Is.EqualTo("multi_compile_local"), where);
                        Assert.That(a.Skip(1).Where(k => k != "_"), Is.SubsetOf(RuntimeToggledKeywords), where + ": only run-time keywords in multi_compile_local");
                    }
                    // The vertex cache, the levels (GT_LOD) and the range origin's variant feed the hull and domain
                    // stages: a fallback pass has none of them (it keeps the origin's run-time branch, GT_FALLBACK).
                    var forPass = s.Tessellated ? shipped : new HashSet<string>(shipped.Except(new[] { VertexCacheKeyword, "GT_LOD", "GT_RANGE_ORIGIN" }));
                    if (ForwardModes.Contains(p.LightMode))
                        Assert.That(p.Keywords, Is.EquivalentTo(forPass), where);
                    else
                        // Depth and shadow passes: only what changes the shape (or where it comes from).
                        Assert.That(p.Keywords, Is.EquivalentTo(s.Tessellated ? new[] { "GT_NOISE", "GT_NOISE_TABLE", "GT_SNOW", VertexCacheKeyword, "GT_LOD", "GT_RANGE_ORIGIN" } : new[] { "GT_NOISE", "GT_NOISE_TABLE", "GT_SNOW" }), where);
                    // Where the vertices come from, one set: the range origin's code, the levels (which
                    // compile that code too) or the cache (likewise; it draws one range, never the levels).
                    // The renderer turns on at most one (RelativeSurface.NeedsRangeOriginKeyword), so a
                    // set of their own would compile combinations that are never drawn.
                    Assert.That(p.Pragmas.Count(a => a.SequenceEqual(VertexSourceSet)), Is.EqualTo(s.Tessellated ? 1 : 0),
                        where + ": GT_RANGE_ORIGIN, GT_LOD and GT_VERTEX_CACHE as one multi_compile_local set, in tessellated passes only");
                    foreach (string rigOnly in RigKeywords.RigOnly)
                        Assert.That(Regex.IsMatch(p.Program, @"\b" + rigOnly + @"\b"), Is.False, where + ": mentions " + rigOnly);
                }
            // The debug views replace each other: one keyword set, so at most one is on.
            foreach (PassInfo p in _subShaders.SelectMany(s => s.Passes).Where(p => ForwardModes.Contains(p.LightMode)))
                Assert.That(p.Pragmas.Any(a => a.SequenceEqual(new[] { "shader_feature_local", "_", "GT_DEBUG_NORMALS", "GT_DEBUG_PATCH_ID", "GT_DEBUG_TESS_FACTOR" })),
                    Is.True, p.Name + ": the debug views as one set");
        }

        /// <summary>
        /// The package's keywords and the stage pragmas are written once, in
        /// Pipelines/TessellatedSubShader.hlsl and FallbackSubShader.hlsl, which each SubShader's
        /// HLSLINCLUDE (pasted at the top of every HLSLPROGRAM of the SubShader) reads with
        /// #include_with_pragmas; a pass's own HLSLPROGRAM adds only what that pass alone reads (the
        /// forward passes' colour and debug switches, the pipeline's keywords).
        /// </summary>
        [Test]
        public void ThePackageKeywordBlockIsWrittenOncePerSubShader()
        {
            string[] forwardOnly = { "GT_HEIGHT_COLOR", "GT_DEBUG_NORMALS", "GT_DEBUG_PATCH_ID", "GT_DEBUG_TESS_FACTOR" };
            foreach (SubShaderInfo s in _subShaders)
            {
                Assert.That(Regex.Matches(s.Shared, @"#pragma\s+(shader_feature|multi_compile)\w*[ \t][^\n]*\bGT_").Count, Is.EqualTo(s.Tessellated ? 4 : 3),
                    $"{s}: the package's keyword pragmas in the SubShader's HLSLINCLUDE");
                foreach (PassInfo p in s.Passes)
                {
                    string[] own = Regex.Matches(p.OwnProgram, @"#pragma\s+(shader_feature|multi_compile)\w*[ \t]([^\n]*)").SelectMany(x => x.Groups[2].Value.Split(' ', '\t'))
                        .Where(k => k.StartsWith("GT_")).ToArray();
                    Assert.That(own, Is.SubsetOf(ForwardModes.Contains(p.LightMode) ? forwardOnly : Array.Empty<string>()),
                        $"{s} pass {p.Name}: a package keyword declared in the pass, not once in the SubShader");
                    Assert.That(Regex.IsMatch(p.OwnProgram, @"#pragma\s+(target|require|vertex|hull|domain|fragment)\b"), Is.False,
                        $"{s} pass {p.Name}: a stage pragma in the pass, not once in the SubShader");
                }
            }
            // Written once in the package: each SubShader's HLSLINCLUDE only reads its kind's stages and its
            // kind's generated keyword pragmas; a colour pass reads the generated colour keywords.
            foreach (SubShaderInfo s in _subShaders)
            {
                string kind = s.Tessellated ? "Tessellated" : "Fallback";
                Assert.That(Regex.Split(s.SharedAsWritten.Trim(), @"\s*\n\s*"), Is.EqualTo(new[]
                    {
                        $"#include_with_pragmas \"Packages/{PackageName}/Shaders/Pipelines/{kind}SubShader.hlsl\"",
                        $"#include_with_pragmas \"Packages/{PackageName}/Shaders/Pipelines/ShaderKeywords.{kind}.cs.hlsl\"",
                    }), $"{s}: the HLSLINCLUDE reads the shared pragmas of its kind");
                foreach (PassInfo p in s.Passes)
                    Assert.That(p.OwnAsWritten.Contains("ShaderKeywords.Colour.cs.hlsl"), Is.EqualTo(ForwardModes.Contains(p.LightMode)),
                        $"{s} pass {p.Name}: the colour keywords exactly in the colour pass");
            }
        }

        /// <summary>
        /// The package-keyword combinations a tessellated forward pass compiles (the product over its
        /// sets: a set with "_" is its keywords or none, a one-keyword shader_feature on or off, a set
        /// without "_" one of its keywords): at most <see cref="MaxForwardCombinations"/>, every one a
        /// draw the renderer can make.
        /// </summary>
        [Test]
        public void ATessellatedForwardPassCompilesAtMost256PackageCombinations()
        {
            foreach (SubShaderInfo s in _subShaders.Where(s => s.Tessellated))
                foreach (PassInfo p in s.Passes.Where(p => ForwardModes.Contains(p.LightMode)))
                {
                    int combinations = PackageCombinations(p);
                    TestContext.Out.WriteLine($"{s} pass {p.Name}: {combinations} package-keyword combinations");
                    Assert.That(combinations, Is.LessThanOrEqualTo(MaxForwardCombinations), $"{s} pass {p.Name}");
                }
        }

        static int PackageCombinations(PassInfo p)
        {
            int n = 1;
            foreach (string[] a in p.Pragmas.Where(a => KeywordPragma.IsMatch(a[0]) && a.Skip(1).Any(k => k.StartsWith("GT_"))))
            {
                int keywords = a.Skip(1).Count(k => k != "_");
                n *= a.Contains("_") || keywords == 1 ? keywords + 1 : keywords;
            }
            return n;
        }

        static readonly Regex KeywordPragma = new Regex(@"^(shader_feature|multi_compile)(_local)?(_vertex|_fragment|_hull|_domain)?$");

        /// <summary>
        /// Unity reads #pragma lines only in the .shader's own HLSL and in files pulled in with
        /// #include_with_pragmas (what <c>gt shaderlab</c> emulates); in a file pulled in with a plain
        /// #include they are dropped without a word. So only a file the .shader includes with pragmas
        /// may declare a keyword.
        /// </summary>
        [Test]
        public void NoPlainlyIncludedFileDeclaresKeywords()
        {
            string shaders = PackageRoot.Combine("Shaders");
            string shader = StripComments(File.ReadAllText(Path.Combine(shaders, "GregoryTerrain.shader")));
            var withPragmas = new HashSet<string>(Regex.Matches(shader, "#\\s*include_with_pragmas\\s+\"Packages/" + PackageName + "/Shaders/([^\"]+)\"")
                .Select(m => m.Groups[1].Value));
            var declaring = Directory.GetFiles(shaders, "*.hlsl", SearchOption.AllDirectories)
                .Where(f => Regex.IsMatch(StripComments(File.ReadAllText(f)), @"(?m)^\s*#pragma\s+(multi_compile|shader_feature)"))
                .Select(f => Path.GetRelativePath(shaders, f).Replace('\\', '/')).Where(f => !withPragmas.Contains(f)).ToList();
            Assert.That(declaring, Is.Empty, "keyword pragmas in a plainly included file (Unity ignores them)");
        }

        /// <summary>
        /// Unity's keywords are compiled only where a pass reads them (each would double the pass's
        /// variants for nothing elsewhere): URP's received shadows (shadow map, cascades, the
        /// screen-space shadows feature), soft-shadow qualities, SSAO and fog on its forward pass, the
        /// punctual-light caster keyword on its ShadowCaster, the normal packing on DepthNormalsOnly, the
        /// rendering-layers target (decal layers) on both the forward pass and DepthNormalsOnly, as URP 14's Lit;
        /// HDRP's shadow filter quality on ForwardOnly and MSAA depth on DepthForwardOnly; Built-in's
        /// screen shadows and fog on ForwardBase. Keywords that change only the fragment stage are
        /// multi_compile_fragment; one that the hull or domain stage reads must not be _vertex.
        /// </summary>
        [Test]
        public void PipelineKeywordsAreDeclaredOnlyWhereAPassReadsThem()
        {
            foreach (SubShaderInfo s in _subShaders)
                foreach (PassInfo p in s.Passes)
                {
                    string[] expected =
                        s.Pipeline == "URP" && p.LightMode == "UniversalForwardOnly" ? new[] { "_MAIN_LIGHT_SHADOWS", "_MAIN_LIGHT_SHADOWS_CASCADE", "_MAIN_LIGHT_SHADOWS_SCREEN",
                            "_SHADOWS_SOFT", "_SHADOWS_SOFT_LOW", "_SHADOWS_SOFT_MEDIUM", "_SHADOWS_SOFT_HIGH", "_SCREEN_SPACE_OCCLUSION", "_WRITE_RENDERING_LAYERS" } :
                        s.Pipeline == "URP" && p.LightMode == "ShadowCaster" ? new[] { "_CASTING_PUNCTUAL_LIGHT_SHADOW" } :
                        s.Pipeline == "URP" && p.LightMode == "DepthNormalsOnly" ? new[] { "_GBUFFER_NORMALS_OCT", "_WRITE_RENDERING_LAYERS" } :
                        s.Pipeline == "HDRP" && p.LightMode == "ForwardOnly" ? new[] { "SHADOW_LOW", "SHADOW_MEDIUM", "SHADOW_HIGH" } :
                        s.Pipeline == "HDRP" && p.LightMode == "DepthForwardOnly" ? new[] { "WRITE_MSAA_DEPTH" } :
                        s.Pipeline == "Builtin" && p.LightMode == "ForwardBase" ? new[] { "SHADOWS_SCREEN" } :
                        Array.Empty<string>();
                    string where = $"{s} pass {p.Name}";
                    Assert.That(p.PipelineKeywords, Is.EquivalentTo(expected), where);
                    bool fog = p.Pragmas.Any(a => a.SequenceEqual(new[] { "multi_compile_fog" }));
                    Assert.That(fog, Is.EqualTo(s.Pipeline == "URP" && p.LightMode == "UniversalForwardOnly" || s.Pipeline == "Builtin" && p.LightMode == "ForwardBase"),
                        where + ": multi_compile_fog (URP forward and Built-in ForwardBase only, as Lit and Standard; HDRP fogs opaques itself)");
                    // The hull and domain stages run GT_ObjectToClip too: a keyword it reads must reach them.
                    if (s.Tessellated)
                        Assert.That(p.Pragmas.Where(a => a[0] == "multi_compile_vertex"), Is.Empty, where + ": multi_compile_vertex in a tessellated pass");
                }
            foreach (PassInfo p in _subShaders.Where(s => s.Pipeline == "URP").SelectMany(s => s.Passes).Where(p => p.LightMode == "UniversalForwardOnly"))
            {
                Assert.That(p.Pragmas.Any(a => a.SequenceEqual(new[] { "multi_compile", "_", "_MAIN_LIGHT_SHADOWS", "_MAIN_LIGHT_SHADOWS_CASCADE", "_MAIN_LIGHT_SHADOWS_SCREEN" })), Is.True,
                    "URP forward: the main-light shadow keywords as one set, in every stage (they add the positionWS varying)");
                Assert.That(p.Pragmas.Any(a => a.SequenceEqual(new[] { "multi_compile_fragment", "_", "_SHADOWS_SOFT", "_SHADOWS_SOFT_LOW", "_SHADOWS_SOFT_MEDIUM", "_SHADOWS_SOFT_HIGH" })), Is.True,
                    "URP forward: the soft-shadow qualities as one set, fragment stage only");
            }
            foreach (PassInfo p in _subShaders.Where(s => s.Pipeline == "HDRP").SelectMany(s => s.Passes).Where(p => p.LightMode == "ForwardOnly"))
                Assert.That(p.Pragmas.Any(a => a.SequenceEqual(new[] { "multi_compile_fragment", "SHADOW_LOW", "SHADOW_MEDIUM", "SHADOW_HIGH" })), Is.True,
                    "HDRP forward: one shadow quality always set, fragment stage only, as HDRP's Lit");
        }

        /// <summary>
        /// A project without URP or HDRP must not see their SubShaders (their includes do not exist
        /// there): each SRP SubShader opens with a PackageRequirements block naming its package (Unity
        /// wants the block before every other declaration); the Built-in ones need none.
        /// </summary>
        [Test]
        public void EverySrpSubShaderRequiresItsPackage()
        {
            foreach (SubShaderInfo s in _subShaders)
            {
                string outer = OuterPart(s.Body);
                var block = Regex.Match(outer, @"^\s*PackageRequirements\s*\{([^}]*)\}");
                string package = s.Pipeline == "URP" ? "com.unity.render-pipelines.universal" : s.Pipeline == "HDRP" ? "com.unity.render-pipelines.high-definition" : null;
                if (package == null)
                {
                    Assert.That(outer, Does.Not.Contain("PackageRequirements"), s.ToString());
                    continue;
                }
                Assert.That(block.Success, Is.True, s + ": PackageRequirements as the SubShader's first declaration");
                Assert.That(Regex.Matches(block.Groups[1].Value, "\"([^\"]+)\"\\s*:\\s*\"([^\"]+)\"").Select(m => m.Groups[1].Value + " " + m.Groups[2].Value),
                    Is.EqualTo(new[] { package + " 14.0" }), s + ": the package, from the version the rig checks (14)");
                foreach (PassInfo p in s.Passes)
                    Assert.That(p.Program, Does.Not.Contain(s.Pipeline == "URP" ? "high-definition" : "render-pipelines.universal"), $"{s} pass {p.Name}: the other pipeline's include");
            }
        }

        /// <summary>
        /// HDRP reads the stencil its materials write: the values of its Unlit (a forward-only material
        /// with its own lighting): depth prepass Ref IsUnlit (1), WriteMask IsUnlit | TraceReflectionRay
        /// (9), so SSR and GI skip the terrain; forward Ref 0, WriteMask RequiresDeferredLighting |
        /// SubsurfaceScattering (6). The depth prepass writes the normal buffer (no ColorMask 0).
        /// </summary>
        [Test]
        public void HdrpPassesWriteTheStencilAndNormalBufferAsHdrpUnlit()
        {
            foreach (SubShaderInfo s in _subShaders.Where(s => s.Pipeline == "HDRP"))
            {
                PassInfo depth = s.Passes.Single(p => p.LightMode == "DepthForwardOnly");
                PassInfo forward = s.Passes.Single(p => p.LightMode == "ForwardOnly");
                Assert.That(StencilOf(s.Body, depth.Name), Is.EqualTo("WriteMask 9 Ref 1 Comp Always Pass Replace"), s + " depth");
                Assert.That(StencilOf(s.Body, forward.Name), Is.EqualTo("WriteMask 6 Ref 0 Comp Always Pass Replace"), s + " forward");
                Assert.That(Regex.IsMatch(depth.Program, @"#define\s+GT_PASS_DEPTH_NORMALS\b"), Is.True, s + ": DepthForwardOnly writes the normal buffer");
                Assert.That(PassBody(s.Body, depth.Name), Does.Not.Contain("ColorMask 0"), s + ": the normal buffer is a colour target");
            }
        }

        /// <summary>
        /// Every HDRP pass has the render state of HDRP's own pass of its LightMode (HDRP 14's Lit.shader
        /// and Unlit.shader, with their materials' defaults: _CullMode = Back). ShadowCaster:
        /// <c>ZClip [_ZClip]</c>, the global HDRP sets to 0 while it draws a directional light's
        /// cascades (HDShadowAtlas: shadowRequest.zClip), so a caster between the light and a cascade's
        /// near plane is clamped onto it instead of clipped (without it, that terrain casts no shadow),
        /// then ZWrite On, ZTest LEqual, ColorMask 0. ForwardOnly keeps ZTest LEqual where Lit tests Equal
        /// after its full depth prepass (index.md says why). A state a pass leaves out is ShaderLab's
        /// default (Cull Back, ZWrite On, ZTest LEqual, ZClip True, ColorMask RGBA).
        /// </summary>
        [Test]
        public void HdrpPassStatesAreThoseOfHdrpsOwnPasses()
        {
            var expected = new Dictionary<string, string>
            {
                ["ShadowCaster"] = "Cull Back, ZWrite On, ZTest LEqual, ZClip [_ZClip], ColorMask 0",
                ["DepthForwardOnly"] = "Cull Back, ZWrite On, ZTest LEqual, ZClip True, ColorMask RGBA",
                ["ForwardOnly"] = "Cull Back, ZWrite On, ZTest LEqual, ZClip True, ColorMask RGBA",
                ["SceneSelectionPass"] = "Cull Off, ZWrite On, ZTest LEqual, ZClip True, ColorMask RGBA",
                ["Picking"] = "Cull Back, ZWrite On, ZTest LEqual, ZClip True, ColorMask RGBA",
            };
            int passes = 0;
            foreach (SubShaderInfo s in _subShaders.Where(s => s.Pipeline == "HDRP"))
                foreach (PassInfo p in s.Passes)
                {
                    Assert.That(PassState(s.Body, p.Name), Is.EqualTo(expected[p.LightMode]), $"{s} pass {p.Name}");
                    passes++;
                }
            Assert.That(passes, Is.EqualTo(10), "five passes in each HDRP SubShader");
        }

        /// <summary>The Scene view's passes, as Unity's own shaders have them: outline without culling, both compiled on demand.</summary>
        [Test]
        public void SrpSubShadersHaveTheSceneViewSelectionAndPickingPasses()
        {
            foreach (SubShaderInfo s in _subShaders.Where(s => s.Pipeline != "Builtin"))
            {
                PassInfo selection = s.Passes.Single(p => p.LightMode == "SceneSelectionPass");
                PassInfo picking = s.Passes.Single(p => p.LightMode == "Picking");
                Assert.That(Regex.IsMatch(selection.Program, @"#define\s+GT_PASS_SCENE_SELECTION\b"), Is.True, s.ToString());
                Assert.That(Regex.IsMatch(picking.Program, @"#define\s+GT_PASS_SCENE_PICKING\b"), Is.True, s.ToString());
                Assert.That(PassBody(s.Body, selection.Name), Does.Contain("Cull Off"), s + ": the outline covers back faces too");
                foreach (PassInfo p in new[] { selection, picking })
                    Assert.That(p.Pragmas.Any(a => a.SequenceEqual(new[] { "editor_sync_compilation" })), Is.True, $"{s} pass {p.Name}");
            }
        }

        /// <summary>
        /// The material inspector's switches produce exactly the keywords the passes declare: each
        /// [Toggle(KW)] names a declared keyword, and the debug KeywordEnum's keywords (property name,
        /// '_', entry upper-cased, as Unity builds them) minus the None entry are the debug set.
        /// </summary>
        [Test]
        public void MaterialSwitchesEnableTheDeclaredKeywords()
        {
            string text = StripComments(File.ReadAllText(PackageRoot.Combine("Shaders", "GregoryTerrain.shader")));
            string properties = Blocks(text, "Properties").Single();
            var declared = new HashSet<string>(_subShaders.SelectMany(s => s.Passes).SelectMany(p => p.Keywords));
            var toggles = Regex.Matches(properties, @"\[Toggle\((\w+)\)\]").Select(m => m.Groups[1].Value).ToList();
            Assert.That(toggles, Is.EquivalentTo(new[] { "GT_NOISE", "GT_HEIGHT_COLOR", "GT_NOISE_TABLE" }));
            foreach (string k in toggles) Assert.That(declared, Does.Contain(k));

            var enums = Regex.Matches(properties, @"\[KeywordEnum\(([^)]*)\)\]\s*(\w+)").ToList();
            Assert.That(enums.Count, Is.EqualTo(1), "one KeywordEnum: the debug view");
            string property = enums[0].Groups[2].Value;
            var entries = enums[0].Groups[1].Value.Split(',').Select(e => e.Trim()).ToList();
            Assert.That(entries[0], Is.EqualTo("None"), "the first entry (the default, 0) is no debug view");
            var produced = entries.Skip(1).Select(e => (property + "_" + e.Replace(' ', '_')).ToUpperInvariant()).ToList();
            Assert.That(produced, Is.EqualTo(new[] { "GT_DEBUG_NORMALS", "GT_DEBUG_PATCH_ID", "GT_DEBUG_TESS_FACTOR" }));
            Assert.That(declared, Does.Not.Contain((property + "_None").ToUpperInvariant()), "None maps to the '_' variant");
            Assert.That(Regex.IsMatch(properties, @"\[Toggle\(GT_DEBUG"), Is.False, "no separate debug toggles (two at once would be a variant that does not exist)");
        }

        /// <summary>
        /// Each SubShader says which draw it expects ("GregoryTerrainDraw" tag); the renderer reads the
        /// tag of the SubShader Unity picked (Material.GetTag without fallbacks), so draw and SubShader
        /// cannot disagree (e.g. a device with compute-based tessellation only, where Unity skips the
        /// tessHW SubShader).
        /// </summary>
        [Test]
        public void EverySubShaderNamesTheDrawTheRendererMustIssue()
        {
            foreach (SubShaderInfo s in _subShaders)
            {
                string tag = Regex.Match(OuterPart(s.Body), "\"GregoryTerrainDraw\"\\s*=\\s*\"(\\w+)\"").Groups[1].Value;
                Assert.That(tag, Is.EqualTo(s.Tessellated ? "Tessellated" : "Fallback"), s.ToString());
            }
            // The renderer's per-camera frame (TerrainFrameDriver.ReadDrawMode) reads it.
            string frame = File.ReadAllText(PackageRoot.Combine("Runtime", "TerrainFrameDriver.cs"));
            Assert.That(frame, Does.Contain("\"GregoryTerrainDraw\"").And.Contain("GetTag("), "the renderer's frame reads the tag");
            Assert.That(frame, Does.Contain("\"Fallback\""));
        }

        [Test]
        public void EveryIncludeResolvesToAPackageFile()
        {
            int count = 0;
            foreach (SubShaderInfo s in _subShaders)
                foreach (PassInfo p in s.Passes)
                {
                    var includes = Regex.Matches(p.Program, "#include\\s+\"([^\"]+)\"").Select(m => m.Groups[1].Value).ToList();
                    string adapter = s.Pipeline == "Builtin" ? "BuiltinAdapter" : s.Pipeline + "Adapter";
                    Assert.That(includes, Is.EqualTo(new[] { $"Packages/{PackageName}/Shaders/Pipelines/{adapter}.hlsl" }),
                        $"{s} pass {p.Name}: its pipeline's adapter only");
                    foreach (string inc in includes)
                    {
                        string relative = inc.Substring($"Packages/{PackageName}/".Length);
                        Assert.That(File.Exists(PackageRoot.Combine(relative.Split('/'))), Is.True, inc);
                        count++;
                    }
                }
            Assert.That(count, Is.GreaterThan(0));
            // Each adapter brings the stages in itself, last, after the interface they call.
            foreach (string adapter in new[] { "URPAdapter", "HDRPAdapter", "BuiltinAdapter" })
            {
                string text = StripComments(File.ReadAllText(PackageRoot.Combine("Shaders", "Pipelines", adapter + ".hlsl")));
                var includes = Regex.Matches(text, "#include\\s+\"([^\"]+)\"").Select(m => m.Groups[1].Value).ToList();
                Assert.That(includes.Last(), Is.EqualTo("TerrainStages.hlsl"), adapter + ": its last include is the stages");
                Assert.That(text.Substring(text.LastIndexOf("TerrainStages.hlsl", StringComparison.Ordinal)).Trim(), Does.Match(@"^TerrainStages\.hlsl""\s*#endif\b[^#]*$"),
                    adapter + ": the stages after everything else, before the include guard's #endif");
            }
        }

        [TestCase("URP", new[] { "UniversalForwardOnly", "ShadowCaster", "DepthOnly", "DepthNormalsOnly", "SceneSelectionPass", "Picking" })]
        [TestCase("HDRP", new[] { "SceneSelectionPass", "Picking", "DepthForwardOnly", "ForwardOnly", "ShadowCaster" })]
        [TestCase("Builtin", new[] { "ForwardBase", "ShadowCaster" })]
        public void LightModesPerPipelineAreTheRequiredSet(string pipeline, string[] required)
        {
            var subs = _subShaders.Where(s => s.Pipeline == pipeline).ToList();
            Assert.That(subs.Count, Is.EqualTo(2), pipeline);
            foreach (SubShaderInfo s in subs)
            {
                // URP: forward-only colour (its Deferred renderer skips UniversalForward for opaques) with
                // DepthNormalsOnly (drawn by the Forward renderers' and the Deferred renderer's normals prepass).
                Assert.That(s.Passes.Select(p => p.LightMode), Is.EquivalentTo(required), s.ToString());
            }
        }

        /// <summary>A pass's text (state and program) by its Name, comments stripped.</summary>
        static string PassBody(string sub, string name) =>
            Blocks(sub, "Pass").Single(b => Regex.IsMatch(b, "\\bName\\s+\"" + Regex.Escape(name) + "\""));

        /// <summary>A pass's Cull, ZWrite, ZTest, ZClip and ColorMask as written, or ShaderLab's default.</summary>
        static string PassState(string sub, string name)
        {
            string state = Regex.Replace(PassBody(sub, name), "HLSLPROGRAM.*?ENDHLSL", "", RegexOptions.Singleline);
            string Of(string key, string otherwise)
            {
                var m = Regex.Match(state, @"\b" + key + @"\s+(\[\w+\]|\w+)");
                return m.Success ? m.Groups[1].Value : otherwise;
            }
            return $"Cull {Of("Cull", "Back")}, ZWrite {Of("ZWrite", "On")}, ZTest {Of("ZTest", "LEqual")}, " +
                   $"ZClip {Of("ZClip", "True")}, ColorMask {Of("ColorMask", "RGBA")}";
        }

        /// <summary>The pass's Stencil block, whitespace collapsed ("" if none).</summary>
        static string StencilOf(string sub, string name)
        {
            var m = Regex.Match(PassBody(sub, name), @"\bStencil\s*\{([^}]*)\}");
            return m.Success ? Regex.Replace(m.Groups[1].Value.Trim(), @"\s+", " ") : "";
        }

        /// <summary>
        /// Unity's #include_with_pragmas: the package's file in place (comments stripped), so its
        /// pragmas and defines count as the program's own (what <c>gt shaderlab</c> emulates too).
        /// </summary>
        internal static string WithIncludedPragmas(string program, int depth = 0)
        {
            Assert.That(depth, Is.LessThan(8), "#include_with_pragmas nested too deep (a file including itself?)");
            return Regex.Replace(program, "#[ \t]*include_with_pragmas[ \t]+\"Packages/" + PackageName + "/([^\"]+)\"", m =>
            {
                string path = PackageRoot.Combine(m.Groups[1].Value.Split('/'));
                Assert.That(File.Exists(path), Is.True, m.Value + ": no such package file");
                string text = StripComments(File.ReadAllText(path));
                // Unity evaluates #if around such pragmas; gt shaderlab and these tests lift every one.
                Assert.That(Regex.IsMatch(text, @"^[ \t]*#[ \t]*(if|ifdef|ifndef|elif)\b", RegexOptions.Multiline), Is.False,
                    m.Groups[1].Value + ": a file read with #include_with_pragmas holds a conditional, which the rig would not evaluate");
                return WithIncludedPragmas(text, depth + 1);
            });
        }

        static bool HasPragma(PassInfo p, string name) => p.Pragmas.Any(a => a.Length > 0 && a[0] == name);

        static string PragmaArg(PassInfo p, string name) => p.Pragmas.Where(a => a.Length > 1 && a[0] == name).Select(a => a[1]).SingleOrDefault();

        static string StripComments(string text) =>
            Regex.Replace(Regex.Replace(text, @"/\*.*?\*/", "", RegexOptions.Singleline), @"//[^\n]*", "");

        /// <summary>The part of a SubShader outside its passes (its own Tags).</summary>
        static string OuterPart(string sub)
        {
            int k = Regex.Match(sub, @"\bPass\s*\{").Index;
            return k > 0 ? sub.Substring(0, k) : sub;
        }

        /// <summary>Bodies of each "keyword { ... }" at any depth, HLSL blocks skipped when matching braces.</summary>
        static List<string> Blocks(string text, string keyword)
        {
            var result = new List<string>();
            foreach (Match m in Regex.Matches(text, @"\b" + keyword + @"\s*\{"))
            {
                int open = m.Index + m.Length - 1, depth = 0, i = open;
                for (; i < text.Length; i++)
                {
                    if (string.CompareOrdinal(text, i, "HLSLPROGRAM", 0, 11) == 0) { i = text.IndexOf("ENDHLSL", i, StringComparison.Ordinal) + 6; continue; }
                    if (text[i] == '{') depth++;
                    else if (text[i] == '}' && --depth == 0) break;
                }
                result.Add(text.Substring(open + 1, i - open - 1));
            }
            return result;
        }
    }
}
