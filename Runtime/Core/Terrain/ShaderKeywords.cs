using System;
using System.Collections.Generic;

namespace GregoryTerrain
{
    /// <summary>Unity's pragma of a keyword set.</summary>
    internal enum KeywordPragma
    {
        ShaderFeatureLocal,   // a build keeps only the variants its saved materials use
        MultiCompileLocal,    // a build keeps every variant: a script may switch it at run time
    }

    /// <summary>What switches a set: the material asset's toggles, or the renderer on its runtime copy (<see cref="FrameKeywords"/>).</summary>
    internal enum KeywordSwitch { Material, Renderer }

    /// <summary>The passes of GregoryTerrain.shader that declare a set: each flag one generated pragma file.</summary>
    [Flags]
    internal enum KeywordScope
    {
        TessellatedSubShader = 1,   // every pass, through the SubShader's HLSLINCLUDE
        FallbackSubShader = 2,
        EverySubShader = TessellatedSubShader | FallbackSubShader,
        ColourPasses = 4,           // URP ForwardLit, HDRP ForwardOnly, Built-in ForwardBase
    }

    /// <summary>The stages a set changes: all of them, or exactly one (the pragma's _vertex, _hull, _domain or _fragment).</summary>
    [Flags]
    internal enum KeywordStages { Vertex = 1, Hull = 2, Domain = 4, Fragment = 8, All = 15 }

    /// <summary>
    /// One #pragma line: at most one of its keywords is on, or none (the plain terrain). Each keyword
    /// has the <see cref="FrameKeywords"/> flag that switches it (a renderer's set) or None (a material's).
    /// </summary>
    internal sealed class KeywordSet
    {
        public readonly KeywordPragma Pragma;
        public readonly KeywordSwitch SwitchedBy;
        public readonly KeywordScope Scope;
        public readonly KeywordStages Stages;
        public readonly (string name, FrameKeywords flag)[] Keywords;

        public KeywordSet(KeywordPragma pragma, KeywordSwitch switchedBy, KeywordScope scope, KeywordStages stages,
                          params (string name, FrameKeywords flag)[] keywords)
        {
            Pragma = pragma; SwitchedBy = switchedBy; Scope = scope; Stages = stages; Keywords = keywords;
        }
    }

    /// <summary>
    /// The package's shader keywords, declared once: the names the C# switches, and the sets
    /// <c>gt generate</c> writes as GregoryTerrain.shader's pragmas (Shaders/Pipelines/ShaderKeywords.*.cs.hlsl,
    /// read with #include_with_pragmas; GeneratedContractTests fails on a stale one). The compute
    /// files declare the toggles they mirror themselves (ShaderContractTests checks the names).
    /// </summary>
    internal static class ShaderKeywords
    {
        public const string Noise = "GT_NOISE", HeightColor = "GT_HEIGHT_COLOR";
        public const string NoiseTable = "GT_NOISE_TABLE";   // the tiled noise: repeats every 256 cells of each octave
        public const string Snow = "GT_SNOW", Levels = "GT_LOD", VertexCache = "GT_VERTEX_CACHE";
        public const string RangeOrigin = "GT_RANGE_ORIGIN";   // on while RelativeSurface.NeedsRangeOriginKeyword
        public const string DebugNormals = "GT_DEBUG_NORMALS", DebugPatchId = "GT_DEBUG_PATCH_ID", DebugTessFactor = "GT_DEBUG_TESS_FACTOR";

        const KeywordPragma Feature = KeywordPragma.ShaderFeatureLocal, MultiCompile = KeywordPragma.MultiCompileLocal;
        const KeywordSwitch Material = KeywordSwitch.Material, Renderer = KeywordSwitch.Renderer;
        const FrameKeywords None = FrameKeywords.None;

        /// <summary>Every set, in the order the generated files declare them.</summary>
        public static readonly KeywordSet[] Sets =
        {
            new KeywordSet(Feature, Material, KeywordScope.EverySubShader, KeywordStages.All, (Noise, None)),
            new KeywordSet(Feature, Material, KeywordScope.EverySubShader, KeywordStages.All, (NoiseTable, None)),   // modifies the noise
            new KeywordSet(MultiCompile, Renderer, KeywordScope.EverySubShader, KeywordStages.All, (Snow, FrameKeywords.Snow)),
            // Where the vertices come from: the levels and the cache compile the origin's code and never draw together.
            new KeywordSet(MultiCompile, Renderer, KeywordScope.TessellatedSubShader, KeywordStages.All,
                (RangeOrigin, FrameKeywords.RangeOrigin), (Levels, FrameKeywords.Levels), (VertexCache, FrameKeywords.VertexCache)),
            new KeywordSet(Feature, Material, KeywordScope.ColourPasses, KeywordStages.All, (HeightColor, None)),
            // The debug views replace each other: the KeywordEnum GT_DEBUG, whose None has no keyword.
            new KeywordSet(Feature, Material, KeywordScope.ColourPasses, KeywordStages.All, (DebugNormals, None), (DebugPatchId, None), (DebugTessFactor, None)),
        };

        /// <summary>The keywords of every set <paramref name="switchedBy"/> switches, in declaration order (a new array: read it once).</summary>
        public static (string name, FrameKeywords flag)[] SwitchedBy(KeywordSwitch switchedBy)
        {
            var found = new List<(string, FrameKeywords)>();
            foreach (KeywordSet set in Sets)
                if (set.SwitchedBy == switchedBy) found.AddRange(set.Keywords);
            return found.ToArray();
        }
    }
}
