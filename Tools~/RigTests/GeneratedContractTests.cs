using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Linq;
using System.Reflection;
using System.Runtime.InteropServices;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>
    /// The generated side of each GPU contract (gt generate, <see cref="ContractGenerator"/>) is what
    /// its one declaration in Core gives today: regenerated into a temp folder and compared line by
    /// line with the committed file. A hand edit or a declaration changed without <c>gt generate</c>
    /// fails here, naming the file and its first differing line.
    /// </summary>
    [TestFixture]
    public class GeneratedContractTests
    {
        [Test]
        public void EveryGeneratedFileIsCurrent()
        {
            Assert.That(ContractGenerator.Contracts(), Does.Contain(typeof(TerrainParams)));
            string temp = Path.Combine(Path.GetTempPath(), "gt-generate-" + Guid.NewGuid().ToString("N"));
            try
            {
                var files = ContractGenerator.All();
                Assert.That(files.Select(f => f.Path), Does.Contain("Shaders/Pipelines/ShaderKeywords.Tessellated.cs.hlsl"));
                ContractGenerator.Write(files, temp);
                var stale = new List<string>();
                foreach (var f in files)
                {
                    string committed = PackageRoot.Combine(f.Path);
                    if (!File.Exists(committed)) { stale.Add($"{f.Path}: missing"); continue; }
                    string difference = ContractGenerator.FirstDifference(File.ReadAllText(committed), File.ReadAllText(Path.Combine(temp, f.Path)));
                    if (difference != null) stale.Add($"{f.Path} is stale: {difference}");
                }
                Assert.That(stale, Is.Empty, "run gt generate and commit what it writes");
                TestContext.Progress.WriteLine($"generated and current: {string.Join(", ", files.Select(f => f.Path))}");
            }
            finally
            {
                if (Directory.Exists(temp)) Directory.Delete(temp, true);
            }
        }

        [Test]
        public void EachGeneratedFileSaysItIsGeneratedAndIsIncluded()
        {
            foreach (var f in ContractGenerator.All())
                Assert.That(f.Text.Split('\n')[0], Does.StartWith("// " + ContractGenerator.DoNotEdit), f.Path);
            Assert.That(File.ReadAllText(PackageRoot.Combine("Shaders", "Terrain", "TerrainInputs.hlsl")),
                Does.Contain("#include \"TerrainParams.cs.hlsl\""), "the cbuffer holds the generated members");
        }

        /// <summary>The comparison the staleness test makes, on a hand-edited copy: it names the line and both texts.</summary>
        [Test]
        public void AHandEditedLineIsNamed()
        {
            string generated = ContractGenerator.Generate(new[] { typeof(TerrainParams) })[0].Text;
            string edited = generated.Replace("float4 _Tess;", "float4 _Tess2;");
            int line = Array.FindIndex(generated.Split('\n'), l => l.StartsWith("float4 _Tess;")) + 1;
            Assert.That(line, Is.GreaterThan(0));
            Assert.That(ContractGenerator.FirstDifference(generated, generated), Is.Null);
            Assert.That(ContractGenerator.FirstDifference(edited, generated),
                Does.StartWith($"line {line}: committed 'float4 _Tess2;").And.Contain("generated 'float4 _Tess;"));
            Assert.That(ContractGenerator.FirstDifference(generated + "float4 _Extra;\n", generated), Does.Contain("generated end of file"));
            Assert.That(ContractGenerator.FirstDifference(generated.TrimEnd('\n'), generated), Does.Contain("line ends differ"));
            Assert.That(ContractGenerator.FirstDifference(generated.Replace("\n", "\r\n"), generated), Does.Contain("and a CR"));
        }

        [StructLayout(LayoutKind.Sequential)]
        [GenerateHlsl("Shaders/Bad.cs.hlsl", "Runtime/Core/Bad.Generated.cs")]
        struct ScalarContract
        {
            public Float4 range;
            public float scale;
        }

        [Test]
        public void AFieldThatIsNotAFloat4IsRefusedNamingIt()
        {
            var e = Assert.Throws<ArgumentException>(() => ContractGenerator.Generate(new[] { typeof(ScalarContract) }));
            Assert.That(e.Message, Does.Contain("ScalarContract.scale").And.Contain("Single").And.Contain("_Scale"));
        }

        [StructLayout(LayoutKind.Sequential)]
        [GenerateHlsl("Shaders/Bad.cs.hlsl", Record = true)]
        struct BrokenArrayRecord
        {
            [HlslArray("points", 3)] public Float4 point0;
            public Float4 point1;
            public Float4 corner;
        }

        [Test]
        public void ARecordArrayNeedsItsNumberedFieldsInOrder()
        {
            string record = ContractGenerator.Generate(new[] { typeof(GregoryPatchRecord) }).Single().Text;
            Assert.That(record, Does.Contain("struct GregoryPatchRecord\n{\n    float4 points[20];"));
            var e = Assert.Throws<ArgumentException>(() => ContractGenerator.Generate(new[] { typeof(BrokenArrayRecord) }));
            Assert.That(e.Message, Does.Contain("BrokenArrayRecord.point0").And.Contain("point0..point2"));
        }

        /// <summary>
        /// SRP's own HLSL generator guards a file with its name alone (TERRAINPARAMS_CS_HLSL); a user's
        /// TerrainParams.cs would get the same guard, and a pass including both would lose ours.
        /// </summary>
        [Test]
        public void EachGuardIsPrefixedSoAUsersFileOfTheSameNameCannotHideIt()
        {
            foreach (var f in ContractGenerator.Generate(ContractGenerator.Contracts()).Where(f => f.Path.EndsWith(".hlsl")))
            {
                string guard = "GT_" + Path.GetFileName(f.Path).Replace('.', '_').ToUpperInvariant();
                Assert.That(f.Text, Does.Contain($"\n#ifndef {guard}\n#define {guard}\n").And.EndWith($"#endif // {guard}\n"), f.Path);
            }
        }

        [StructLayout(LayoutKind.Sequential)]
        [GenerateHlsl("Shaders/Bad.cs.hlsl", "Runtime/Core/Bad.Generated.cs")]
        struct NewlineCommentContract
        {
            [HlslComment("metres\nfloat4 _Injected;")] public Float4 range;
        }

        [StructLayout(LayoutKind.Sequential)]
        [GenerateHlsl("Shaders/Bad.cs.hlsl", Record = true)]
        struct CarriageReturnCommentRecord
        {
            [HlslComment("per frame\r")] public Float4 corner;
        }

        [StructLayout(LayoutKind.Sequential)]
        [GenerateHlsl("Shaders/Bad.cs.hlsl", "Runtime/Core/Bad.Generated.cs")]
        struct BackslashCommentContract
        {
            [HlslComment("per frame \\")] public Float4 range;
        }

        /// <summary>A comment is written after "// ": a line break would start HLSL, a trailing '\' would continue the comment onto the next declaration.</summary>
        [Test]
        public void ACommentThatWouldBreakItsLineIsRefusedNamingFieldAndText()
        {
            var e = Assert.Throws<ArgumentException>(() => ContractGenerator.Generate(new[] { typeof(NewlineCommentContract) }));
            Assert.That(e.Message, Does.Contain("NewlineCommentContract.range").And.Contain("metres\\nfloat4 _Injected;"));
            e = Assert.Throws<ArgumentException>(() => ContractGenerator.Generate(new[] { typeof(CarriageReturnCommentRecord) }));
            Assert.That(e.Message, Does.Contain("CarriageReturnCommentRecord.corner").And.Contain("per frame\\r"));
            e = Assert.Throws<ArgumentException>(() => ContractGenerator.Generate(new[] { typeof(BackslashCommentContract) }));
            Assert.That(e.Message, Does.Contain("BackslashCommentContract.range").And.Contain("per frame \\"));
        }

        // ---- The keyword set (Core's ShaderKeywords.Sets, KeywordPragmaGenerator) ----------------

        /// <summary>A hand-edited keyword pragma file is stale: the comparison names the file's line and both texts.</summary>
        [Test]
        public void AHandEditedKeywordPragmaIsNamed()
        {
            var file = KeywordPragmaGenerator.Generate(ShaderKeywords.Sets).Single(f => f.Path.EndsWith("ShaderKeywords.Tessellated.cs.hlsl"));
            string committed = File.ReadAllText(PackageRoot.Combine(file.Path));
            Assert.That(ContractGenerator.FirstDifference(committed, file.Text), Is.Null, file.Path + " is current");
            string edited = committed.Replace("#pragma multi_compile_local _ GT_SNOW", "#pragma shader_feature_local GT_SNOW");
            Assert.That(edited, Is.Not.EqualTo(committed));
            Assert.That(ContractGenerator.FirstDifference(edited, file.Text),
                Does.Match(@"^line \d+: committed '#pragma shader_feature_local GT_SNOW', generated '#pragma multi_compile_local _ GT_SNOW'$"));
        }

        /// <summary>Each set's pragma as Unity reads it: a one-keyword shader_feature without '_', every other set with it, a one-stage set suffixed.</summary>
        [Test]
        public void EachSetIsOnePragmaLine()
        {
            Assert.That(ShaderKeywords.Sets.Select(KeywordPragmaGenerator.PragmaLine), Is.EqualTo(new[]
            {
                "#pragma shader_feature_local GT_NOISE",
                "#pragma shader_feature_local GT_NOISE_TABLE",
                "#pragma multi_compile_local _ GT_SNOW",
                "#pragma multi_compile_local _ GT_RANGE_ORIGIN GT_LOD GT_VERTEX_CACHE",
                "#pragma shader_feature_local GT_HEIGHT_COLOR",
                "#pragma shader_feature_local _ GT_DEBUG_NORMALS GT_DEBUG_PATCH_ID GT_DEBUG_TESS_FACTOR",
            }));
            var fragmentOnly = new KeywordSet(KeywordPragma.ShaderFeatureLocal, KeywordSwitch.Material, KeywordScope.ColourPasses, KeywordStages.Fragment, ("GT_X", FrameKeywords.None));
            Assert.That(KeywordPragmaGenerator.PragmaLine(fragmentOnly), Is.EqualTo("#pragma shader_feature_local_fragment GT_X"));
            // 2 x 2 x 2 x 4 in a tessellated SubShader's every pass, 2 x 4 more in its colour pass: issue 39's 256.
            Assert.That(KeywordPragmaGenerator.Combinations(ShaderKeywords.Sets.Where(k => (k.Scope & KeywordScope.TessellatedSubShader) != 0)), Is.EqualTo(32));
            Assert.That(KeywordPragmaGenerator.Combinations(ShaderKeywords.Sets), Is.EqualTo(256));
        }

        static KeywordSet Set(KeywordPragma pragma, KeywordSwitch by, KeywordStages stages, KeywordScope scope, params (string, FrameKeywords)[] keywords) =>
            new KeywordSet(pragma, by, scope, stages, keywords);

        /// <summary>Every flag the frame planner can raise switches exactly one declared keyword (a new flag without one would be ignored by the renderer).</summary>
        [Test]
        public void EveryFrameKeywordsFlagHasItsKeyword()
        {
            var switched = ShaderKeywords.SwitchedBy(KeywordSwitch.Renderer);
            foreach (FrameKeywords flag in Enum.GetValues(typeof(FrameKeywords)))
                if (flag != FrameKeywords.None)
                    Assert.That(switched.Count(k => k.flag == flag), Is.EqualTo(1), $"FrameKeywords.{flag}: renderer keywords declared with it");
        }

        /// <summary>A declaration Unity would misread, or the renderer could not switch, is refused naming the set and the value.</summary>
        [TestCase("renderer shader_feature", "Sets[1] (GT_SNOW): Pragma ShaderFeatureLocal for a set the renderer switches")]
        [TestCase("two stages", "Sets[1] (GT_SNOW): Stages Vertex, Fragment: Unity's keyword pragmas name every stage or exactly one")]
        [TestCase("hull in fallback", "Sets[1] (GT_SNOW): Stages Hull in a fallback SubShader")]
        [TestCase("domain in colour", "Sets[1] (GT_SNOW): Stages Domain in a fallback SubShader's pass (the colour file")]
        [TestCase("colour and subshader", "Sets[1] (GT_SNOW): Scope TessellatedSubShader, ColourPasses: one of")]
        [TestCase("no scope", "Sets[1] (GT_SNOW): Scope 0: one of")]
        [TestCase("lower case", "Sets[1] (GT_snow): keyword 'GT_snow' is not GT_ and upper-case words joined by '_'")]
        [TestCase("renderer without flag", "Sets[1] (GT_SNOW): keyword GT_SNOW has flag None")]
        [TestCase("material with flag", "Sets[1] (GT_SNOW): keyword GT_SNOW has flag Snow")]
        [TestCase("twice", "Sets[0] (GT_NOISE): keyword GT_NOISE (None) declared twice: again in ShaderKeywords.Sets[1] as GT_NOISE (None)")]
        [TestCase("flag twice", "Sets[1] (GT_SNOW): keyword GT_SNOW (Snow) declared twice: again in ShaderKeywords.Sets[1] as GT_LOD (Snow)")]
        public void ABadKeywordSetIsRefusedNamingIt(string broken, string message)
        {
            var noise = Set(KeywordPragma.ShaderFeatureLocal, KeywordSwitch.Material, KeywordStages.All, KeywordScope.EverySubShader, ("GT_NOISE", FrameKeywords.None));
            var mc = KeywordPragma.MultiCompileLocal;
            var r = KeywordSwitch.Renderer;
            var all = KeywordScope.EverySubShader;
            KeywordSet bad = broken switch
            {
                "renderer shader_feature" => Set(KeywordPragma.ShaderFeatureLocal, r, KeywordStages.All, all, ("GT_SNOW", FrameKeywords.Snow)),
                "two stages" => Set(mc, r, KeywordStages.Vertex | KeywordStages.Fragment, all, ("GT_SNOW", FrameKeywords.Snow)),
                "hull in fallback" => Set(mc, r, KeywordStages.Hull, all, ("GT_SNOW", FrameKeywords.Snow)),
                "domain in colour" => Set(mc, r, KeywordStages.Domain, KeywordScope.ColourPasses, ("GT_SNOW", FrameKeywords.Snow)),
                "colour and subshader" => Set(mc, r, KeywordStages.All, KeywordScope.TessellatedSubShader | KeywordScope.ColourPasses, ("GT_SNOW", FrameKeywords.Snow)),
                "no scope" => Set(mc, r, KeywordStages.All, 0, ("GT_SNOW", FrameKeywords.Snow)),
                "lower case" => Set(mc, r, KeywordStages.All, all, ("GT_snow", FrameKeywords.Snow)),
                "renderer without flag" => Set(mc, r, KeywordStages.All, all, ("GT_SNOW", FrameKeywords.None)),
                "material with flag" => Set(mc, KeywordSwitch.Material, KeywordStages.All, all, ("GT_SNOW", FrameKeywords.Snow)),
                "twice" => Set(mc, KeywordSwitch.Material, KeywordStages.All, all, ("GT_NOISE", FrameKeywords.None)),
                "flag twice" => Set(mc, r, KeywordStages.All, all, ("GT_SNOW", FrameKeywords.Snow), ("GT_LOD", FrameKeywords.Snow)),
                _ => throw new ArgumentException(broken),
            };
            var e = Assert.Throws<ArgumentException>(() => KeywordPragmaGenerator.Generate(new[] { noise, bad }));
            Assert.That(e.Message, Does.StartWith("ShaderKeywords." + message));
        }

        /// <summary>
        /// Unity ignores an asset without a .meta in an immutable package: gt generate runs metas.py
        /// after writing, which gives a new .hlsl a ShaderIncludeImporter and a new .cs a MonoImporter.
        /// </summary>
        [Test]
        public void ANewGeneratedFileGetsAMetaWithItsImporter()
        {
            Assert.That(File.ReadAllText(PackageRoot.Combine("Tools~", "rig", "generate.sh")),
                Does.Match(@"gt-cli\S* generate [^\n]*\n[\s\S]*metas\.py"), "generate.sh runs metas.py after gt-cli generate");
            string temp = Path.Combine(Path.GetTempPath(), "gt-generate-" + Guid.NewGuid().ToString("N"));
            try
            {
                var files = ContractGenerator.All();
                ContractGenerator.Write(files, temp);
                var python = Process.Start(new ProcessStartInfo("python3") { ArgumentList = { PackageRoot.Combine("Tools~", "rig", "metas.py"), temp }, RedirectStandardOutput = true, UseShellExecute = false });
                python.StandardOutput.ReadToEnd();
                python.WaitForExit();
                Assert.That(python.ExitCode, Is.Zero);
                foreach (var f in files)
                {
                    string meta = Path.Combine(temp, f.Path + ".meta");
                    Assert.That(File.Exists(meta), f.Path);
                    Assert.That(File.ReadAllText(meta), Does.Contain(f.Path.EndsWith(".hlsl") ? "\nShaderIncludeImporter:\n" : "\nMonoImporter:\n"), f.Path);
                }
            }
            finally
            {
                if (Directory.Exists(temp)) Directory.Delete(temp, true);
            }
        }

        /// <summary>
        /// The attributes are the rig's: under [Conditional("GT_CONTRACTS")] a player build (no such
        /// symbol) compiles their uses away, while Core built for the rig defines it and keeps them.
        /// </summary>
        [Test]
        public void TheContractAttributesAreCompiledOnlyForTheRig()
        {
            foreach (Type a in new[] { typeof(GenerateHlslAttribute), typeof(HlslArrayAttribute), typeof(HlslCommentAttribute) })
                Assert.That(a.GetCustomAttributes<ConditionalAttribute>().Select(c => c.ConditionString), Is.EqualTo(new[] { "GT_CONTRACTS" }), a.Name);
            Assert.That(typeof(TerrainParams).GetCustomAttribute<GenerateHlslAttribute>(), Is.Not.Null, "Core built for the rig keeps the declarations");
            Assert.That(typeof(ScalarContract).GetCustomAttribute<GenerateHlslAttribute>(), Is.Not.Null, "the tests keep theirs");
        }
    }
}
