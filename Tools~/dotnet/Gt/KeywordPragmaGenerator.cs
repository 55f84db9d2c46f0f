using System;
using System.Collections.Generic;
using System.Linq;
using System.Text;
using System.Text.RegularExpressions;

namespace GregoryTerrain.Rig
{
    /// <summary>
    /// gt generate, the keyword half: GregoryTerrain.shader's keyword pragmas from Core's one
    /// declaration (<see cref="ShaderKeywords.Sets"/>), a file per <see cref="KeywordScope"/> that the
    /// shader reads with #include_with_pragmas. Plain pragma lines under a header; no conditional (Unity
    /// evaluates one around a pragma only on a few predefined macros: nothing here needs it).
    /// </summary>
    static class KeywordPragmaGenerator
    {
        const string Folder = "Shaders/Pipelines/";

        /// <summary>The generated file of each scope, relative to the package root, and who reads it.</summary>
        public static readonly (KeywordScope scope, string path, string readBy)[] Files =
        {
            (KeywordScope.TessellatedSubShader, Folder + "ShaderKeywords.Tessellated.cs.hlsl", "every pass of a tessellated SubShader"),
            (KeywordScope.FallbackSubShader, Folder + "ShaderKeywords.Fallback.cs.hlsl", "every pass of a fallback SubShader"),
            (KeywordScope.ColourPasses, Folder + "ShaderKeywords.Colour.cs.hlsl", "the colour pass of every SubShader"),
        };

        /// <summary>The files for <paramref name="sets"/>; throws naming the set and value it cannot declare.</summary>
        public static List<ContractGenerator.GeneratedFile> Generate(IReadOnlyList<KeywordSet> sets)
        {
            for (int i = 0; i < sets.Count; i++) Check(sets, i);
            return Files.Select(f => new ContractGenerator.GeneratedFile(f.path, Pragmas(sets.Where(s => (s.Scope & f.scope) != 0).ToList(), f.readBy))).ToList();
        }

        /// <summary>The <c>#pragma</c> line of <paramref name="set"/>, as Unity reads it.</summary>
        public static string PragmaLine(KeywordSet set)
        {
            string kind = set.Pragma == KeywordPragma.ShaderFeatureLocal ? "shader_feature_local" : "multi_compile_local";
            // shader_feature with one keyword already means "it or none"; every other set names the off state '_'.
            string off = set.Pragma == KeywordPragma.ShaderFeatureLocal && set.Keywords.Length == 1 ? "" : " _";
            return $"#pragma {kind}{StageSuffix(set.Stages)}{off} {string.Join(" ", set.Keywords.Select(k => k.name))}";
        }

        /// <summary>Package-keyword combinations of <paramref name="sets"/>: each set one of its keywords or none.</summary>
        public static int Combinations(IEnumerable<KeywordSet> sets) => sets.Aggregate(1, (n, s) => n * (s.Keywords.Length + 1));

        static string StageSuffix(KeywordStages stages) => stages switch
        {
            KeywordStages.All => "",
            KeywordStages.Vertex => "_vertex",
            KeywordStages.Hull => "_hull",
            KeywordStages.Domain => "_domain",
            KeywordStages.Fragment => "_fragment",
            _ => throw new ArgumentException($"Stages {stages}: Unity's keyword pragmas name every stage or exactly one"),
        };

        static string Pragmas(List<KeywordSet> sets, string readBy)
        {
            var s = new StringBuilder();
            s.Append("// ").Append(ContractGenerator.DoNotEdit).Append(typeof(ShaderKeywords).FullName).Append(".Sets (Runtime/Core/Terrain/ShaderKeywords.cs): do not edit.\n");
            s.Append("// The package's keywords in ").Append(readBy).Append(" (#include_with_pragmas): ").Append(Combinations(sets)).Append(" combinations.\n");
            foreach (KeywordSet set in sets) s.Append(PragmaLine(set)).Append('\n');
            return s.ToString();
        }

        static void Check(IReadOnlyList<KeywordSet> sets, int i)
        {
            KeywordSet set = sets[i];
            string first = set.Keywords.Length > 0 ? set.Keywords[0].name : "(none)";
            string where = $"ShaderKeywords.Sets[{i}] ({first})";
            if (set.Keywords.Length == 0) throw new ArgumentException($"{where}: a set needs a keyword");
            try { StageSuffix(set.Stages); }
            catch (ArgumentException e) { throw new ArgumentException($"{where}: {e.Message}"); }
            bool colour = (set.Scope & KeywordScope.ColourPasses) != 0;
            if (set.Scope == 0 || (set.Scope & ~(KeywordScope.EverySubShader | KeywordScope.ColourPasses)) != 0 || colour && set.Scope != KeywordScope.ColourPasses)
                throw new ArgumentException($"{where}: Scope {set.Scope}: one of TessellatedSubShader, FallbackSubShader, EverySubShader or ColourPasses (a colour pass reads its SubShader's file too, so a set in both is declared twice there)");
            if ((set.Scope & KeywordScope.FallbackSubShader) != 0 | colour && (set.Stages & KeywordStages.All & ~(KeywordStages.Hull | KeywordStages.Domain)) == 0)
                throw new ArgumentException($"{where}: Stages {set.Stages} in a fallback SubShader's pass{(colour ? " (the colour file is read by the fallback's colour pass too)" : "")}, which has no hull or domain stage");
            if (set.SwitchedBy == KeywordSwitch.Renderer && set.Pragma != KeywordPragma.MultiCompileLocal)
                throw new ArgumentException($"{where}: Pragma {set.Pragma} for a set the renderer switches (a build strips shader_feature variants no saved material uses; use MultiCompileLocal)");
            for (int k = 0; k < set.Keywords.Length; k++)
            {
                var (name, flag) = set.Keywords[k];
                if (name == null || !Regex.IsMatch(name, "^GT_[A-Z0-9]+(_[A-Z0-9]+)*$"))
                    throw new ArgumentException($"{where}: keyword '{name}' is not GT_ and upper-case words joined by '_'");
                bool oneFlag = flag != FrameKeywords.None && ((int)flag & ((int)flag - 1)) == 0;
                if (set.SwitchedBy == KeywordSwitch.Renderer ? !oneFlag : flag != FrameKeywords.None)
                    throw new ArgumentException($"{where}: keyword {name} has flag {flag} (a renderer's keyword has its one FrameKeywords flag, a material's None)");
                for (int j = 0; j < sets.Count; j++)
                    for (int m = 0; m < sets[j].Keywords.Length; m++)
                    {
                        var other = sets[j].Keywords[m];
                        bool same = other.name == name || flag != FrameKeywords.None && other.flag == flag;
                        if ((j, m) != (i, k) && same)
                            throw new ArgumentException($"{where}: keyword {name} ({flag}) declared twice: again in ShaderKeywords.Sets[{j}] as {other.name} ({other.flag})");
                    }
            }
        }
    }
}
