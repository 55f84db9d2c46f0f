// Gregory Terrain: the terrain surface, tessellated from the patch grid on the GPU.
// Drawn by GregoryTerrainRenderer (one procedural draw: M x M four-control-point tile patches, or the
// instanced fallback); the renderer fills the buffers and the packed constants through a
// MaterialPropertyBlock, so the numeric values below are only defaults. The material owns the
// effect switches (keywords). Documentation~/index.md describes every setting.
//
// SubShader order matters: Unity takes the first SubShader whose RenderPipeline tag matches the
// active pipeline and whose passes the GPU supports. Each pipeline has a tessellated SubShader
// (#pragma require tessellation tessHW) followed by a fallback SubShader (vert_fallback) that
// devices without hull/domain stages get instead. Shadow and depth passes run the same stages, so
// shadows and depth come from the same tessellated surface as the colour. Each SubShader's
// "GregoryTerrainDraw" tag (Tessellated / Fallback) tells GregoryTerrainRenderer which draw the
// SubShader Unity picked expects (Material.GetTag without fallbacks reads the SubShader in use).
//
// Keywords: the package's are exactly the shipped ones of Tools~/rig/shader_variants.txt
// (GT_PAPER_MODE, GT_READBACK and GT_FACTOR_READBACK are rig-only and never declared here), all
// shader_feature_local except GT_SNOW, which SnowSimulator switches at run time, and GT_VERTEX_CACHE,
// which GregoryTerrainRenderer switches (Vertex evaluation = Compute cache: the domain stage reads the
// vertices TerrainCache.compute evaluated): both are multi_compile_local, so a player build keeps both
// variants even when no saved material has them on. GT_VERTEX_CACHE only in the tessellated passes
// (the fallback has no hull/domain stage to feed). Depth and shadow passes declare only GT_NOISE,
// GT_SNOW (and GT_VERTEX_CACHE), the ones that change the shape or where it comes from. The pipelines' own
// keywords are multi_compile, only where a pass reads them: URP's main-light shadow keywords and
// Built-in's SHADOWS_SCREEN on the forward passes (received shadows), URP's _GBUFFER_NORMALS_OCT on
// DepthNormals. Each pass defines one GT_PASS_* (and GT_FALLBACK without a tessellator) before its
// adapter; `frag` writes colour, the packed normal (DepthNormals) or nothing (depth, shadow). Checked off Unity by
// Tools~/RigTests/ShaderLabTests.cs and compiled pass by pass by `gt shaderlab` (glslang, Unity's
// libraries mocked).
Shader "GregoryTerrain/Terrain"
{
    Properties
    {
        [Header(Effects)]
        [Toggle(GT_NOISE)] _GtNoise ("Noise detail (eq. 12-13)", Float) = 1
        [Toggle(GT_HEIGHT_COLOR)] _GtHeightColor ("Height colour (eq. 14-15)", Float) = 1

        // One popup for the debug views, as they replace each other: KeywordEnum enables
        // GT_DEBUG_<ENTRY> (the property name, '_', the entry upper-cased), which matches the one
        // `shader_feature_local _ GT_DEBUG_NORMALS GT_DEBUG_PATCH_ID GT_DEBUG_TESS_FACTOR` set of
        // the forward passes; None enables GT_DEBUG_NONE, which no pass declares (the '_' variant).
        [Header(Debug view)]
        [KeywordEnum(None, Normals, Patch_Id, Tess_Factor)] GT_DEBUG ("Debug view (replaces the lit colour)", Float) = 0

        [Header(Defaults. The renderer overrides these)]
        _Tess ("Tessellation: tiles M, max factor (1-64), target pixels per segment, uniform factor (0 = adaptive)", Vector) = (16, 64, 8, 0)
        _Noise ("Noise: amplitude, frequency, alpha (> 1), beta (> 1)", Vector) = (0.02, 16, 2, 2)
        _NoiseOctaves ("Noise octaves: N (0-16), vertices-across override (0 = auto), unused, unused", Vector) = (6, 0, 0, 0)
        _HeightColor ("Height colour: gamma (> 0), colour-noise amplitude, colour-noise frequency, unused", Vector) = (0.5, 0.1, 64, 0)
        _ColorLow ("Low colour C (eq. 15)", Color) = (0.22, 0.33, 0.14, 1)
        _ColorHigh ("High colour B (eq. 15)", Color) = (0.9, 0.9, 0.92, 1)

        // Written by the renderer only.
        [HideInInspector] _Range ("Range (c, d, g, h) relative to the origin", Vector) = (0, 0, 1, 1)
        [HideInInspector] _RangeOrigin ("Range origin (hi.x, hi.y, lo.x, lo.y)", Vector) = (0, 0, 0, 0)
        [HideInInspector] _GridSize ("Grid size (n, m, 0, 0)", Vector) = (1, 1, 0, 0)
        [HideInInspector] _TileLattice ("Tile lattice: 0 (tiles on the range) or the range the tiles were anchored at", Vector) = (0, 0, 0, 0)
    }

    // Universal Render Pipeline, tessellated.
    SubShader
    {
        Tags { "RenderPipeline" = "UniversalPipeline" "RenderType" = "Opaque" "Queue" = "Geometry" "GregoryTerrainDraw" = "Tessellated" }
        LOD 300

        Pass
        {
            Name "ForwardLit"
            Tags { "LightMode" = "UniversalForward" }
            ZWrite On
            ZTest LEqual
            Cull Back

            HLSLPROGRAM
            // Hull and domain stages: tessellation hardware required. A device without it skips
            // this SubShader and takes the next one (vert_fallback, no hull/domain).
            #pragma target 4.6
            #pragma require tessellation tessHW
            #pragma vertex vert
            #pragma hull hull_shader
            #pragma domain domain_shader
            #pragma fragment frag
            // Effects: off = not compiled into the build at all (shader_feature: unused variants are stripped).
            #pragma shader_feature_local GT_NOISE
            #pragma multi_compile_local _ GT_SNOW
            // Vertex evaluation (renderer setting): the compute pre-pass's cached vertices, switched at run time.
            #pragma multi_compile_local _ GT_VERTEX_CACHE
            #pragma shader_feature_local GT_HEIGHT_COLOR
            #pragma shader_feature_local _ GT_DEBUG_NORMALS GT_DEBUG_PATCH_ID GT_DEBUG_TESS_FACTOR
            // Main-light shadows received (URPAdapter.hlsl, GT_MainLightShadow): URP's own keywords.
            #pragma multi_compile _ _MAIN_LIGHT_SHADOWS _MAIN_LIGHT_SHADOWS_CASCADE
            #pragma multi_compile_fragment _ _SHADOWS_SOFT
            #define GT_PASS_FORWARD 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/URPAdapter.hlsl"
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/TerrainStages.hlsl"
            ENDHLSL
        }

        Pass
        {
            Name "ShadowCaster"
            Tags { "LightMode" = "ShadowCaster" }
            ZWrite On
            ZTest LEqual
            ColorMask 0
            Cull Back

            HLSLPROGRAM
            // Hull and domain stages: tessellation hardware required. A device without it skips
            // this SubShader and takes the next one (vert_fallback, no hull/domain).
            #pragma target 4.6
            #pragma require tessellation tessHW
            #pragma vertex vert
            #pragma hull hull_shader
            #pragma domain domain_shader
            #pragma fragment frag
            #pragma shader_feature_local GT_NOISE
            #pragma multi_compile_local _ GT_SNOW
            // Vertex evaluation (renderer setting): the compute pre-pass's cached vertices, switched at run time.
            #pragma multi_compile_local _ GT_VERTEX_CACHE
            #define GT_PASS_SHADOWCASTER 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/URPAdapter.hlsl"
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/TerrainStages.hlsl"
            ENDHLSL
        }

        Pass
        {
            Name "DepthOnly"
            Tags { "LightMode" = "DepthOnly" }
            ZWrite On
            ZTest LEqual
            ColorMask 0
            Cull Back

            HLSLPROGRAM
            // Hull and domain stages: tessellation hardware required. A device without it skips
            // this SubShader and takes the next one (vert_fallback, no hull/domain).
            #pragma target 4.6
            #pragma require tessellation tessHW
            #pragma vertex vert
            #pragma hull hull_shader
            #pragma domain domain_shader
            #pragma fragment frag
            #pragma shader_feature_local GT_NOISE
            #pragma multi_compile_local _ GT_SNOW
            // Vertex evaluation (renderer setting): the compute pre-pass's cached vertices, switched at run time.
            #pragma multi_compile_local _ GT_VERTEX_CACHE
            #define GT_PASS_DEPTH 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/URPAdapter.hlsl"
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/TerrainStages.hlsl"
            ENDHLSL
        }

        Pass
        {
            Name "DepthNormals"
            Tags { "LightMode" = "DepthNormals" }
            ZWrite On
            ZTest LEqual
            Cull Back

            HLSLPROGRAM
            // Hull and domain stages: tessellation hardware required. A device without it skips
            // this SubShader and takes the next one (vert_fallback, no hull/domain).
            #pragma target 4.6
            #pragma require tessellation tessHW
            #pragma vertex vert
            #pragma hull hull_shader
            #pragma domain domain_shader
            #pragma fragment frag
            #pragma shader_feature_local GT_NOISE
            #pragma multi_compile_local _ GT_SNOW
            // Vertex evaluation (renderer setting): the compute pre-pass's cached vertices, switched at run time.
            #pragma multi_compile_local _ GT_VERTEX_CACHE
            // URP's normal packing for the deferred renderer's accurate G-buffer normals.
            #pragma multi_compile_fragment _ _GBUFFER_NORMALS_OCT
            #define GT_PASS_DEPTH_NORMALS 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/URPAdapter.hlsl"
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/TerrainStages.hlsl"
            ENDHLSL
        }
    }

    // Universal Render Pipeline, no tessellator.
    SubShader
    {
        Tags { "RenderPipeline" = "UniversalPipeline" "RenderType" = "Opaque" "Queue" = "Geometry" "GregoryTerrainDraw" = "Fallback" }
        LOD 200

        Pass
        {
            Name "ForwardLit"
            Tags { "LightMode" = "UniversalForward" }
            ZWrite On
            ZTest LEqual
            Cull Back

            HLSLPROGRAM
            // No tessellator: each tile is an instanced (F+1)^2 UV grid evaluated in the vertex stage.
            #pragma target 4.5
            #pragma vertex vert_fallback
            #pragma fragment frag
            // Effects: off = not compiled into the build at all (shader_feature: unused variants are stripped).
            #pragma shader_feature_local GT_NOISE
            #pragma multi_compile_local _ GT_SNOW
            #pragma shader_feature_local GT_HEIGHT_COLOR
            #pragma shader_feature_local _ GT_DEBUG_NORMALS GT_DEBUG_PATCH_ID GT_DEBUG_TESS_FACTOR
            // Main-light shadows received (URPAdapter.hlsl, GT_MainLightShadow): URP's own keywords.
            #pragma multi_compile _ _MAIN_LIGHT_SHADOWS _MAIN_LIGHT_SHADOWS_CASCADE
            #pragma multi_compile_fragment _ _SHADOWS_SOFT
            #define GT_PASS_FORWARD 1
            #define GT_FALLBACK 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/URPAdapter.hlsl"
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/TerrainStages.hlsl"
            ENDHLSL
        }

        Pass
        {
            Name "ShadowCaster"
            Tags { "LightMode" = "ShadowCaster" }
            ZWrite On
            ZTest LEqual
            ColorMask 0
            Cull Back

            HLSLPROGRAM
            // No tessellator: each tile is an instanced (F+1)^2 UV grid evaluated in the vertex stage.
            #pragma target 4.5
            #pragma vertex vert_fallback
            #pragma fragment frag
            #pragma shader_feature_local GT_NOISE
            #pragma multi_compile_local _ GT_SNOW
            #define GT_PASS_SHADOWCASTER 1
            #define GT_FALLBACK 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/URPAdapter.hlsl"
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/TerrainStages.hlsl"
            ENDHLSL
        }

        Pass
        {
            Name "DepthOnly"
            Tags { "LightMode" = "DepthOnly" }
            ZWrite On
            ZTest LEqual
            ColorMask 0
            Cull Back

            HLSLPROGRAM
            // No tessellator: each tile is an instanced (F+1)^2 UV grid evaluated in the vertex stage.
            #pragma target 4.5
            #pragma vertex vert_fallback
            #pragma fragment frag
            #pragma shader_feature_local GT_NOISE
            #pragma multi_compile_local _ GT_SNOW
            #define GT_PASS_DEPTH 1
            #define GT_FALLBACK 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/URPAdapter.hlsl"
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/TerrainStages.hlsl"
            ENDHLSL
        }

        Pass
        {
            Name "DepthNormals"
            Tags { "LightMode" = "DepthNormals" }
            ZWrite On
            ZTest LEqual
            Cull Back

            HLSLPROGRAM
            // No tessellator: each tile is an instanced (F+1)^2 UV grid evaluated in the vertex stage.
            #pragma target 4.5
            #pragma vertex vert_fallback
            #pragma fragment frag
            #pragma shader_feature_local GT_NOISE
            #pragma multi_compile_local _ GT_SNOW
            // URP's normal packing for the deferred renderer's accurate G-buffer normals.
            #pragma multi_compile_fragment _ _GBUFFER_NORMALS_OCT
            #define GT_PASS_DEPTH_NORMALS 1
            #define GT_FALLBACK 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/URPAdapter.hlsl"
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/TerrainStages.hlsl"
            ENDHLSL
        }
    }

    // High Definition Render Pipeline (forward-only material), tessellated.
    SubShader
    {
        Tags { "RenderPipeline" = "HDRenderPipeline" "RenderType" = "Opaque" "Queue" = "Geometry" "GregoryTerrainDraw" = "Tessellated" }
        LOD 300

        Pass
        {
            Name "ForwardOnly"
            Tags { "LightMode" = "ForwardOnly" }
            ZWrite On
            ZTest LEqual
            Cull Back

            HLSLPROGRAM
            // Hull and domain stages: tessellation hardware required. A device without it skips
            // this SubShader and takes the next one (vert_fallback, no hull/domain).
            #pragma target 4.6
            #pragma require tessellation tessHW
            #pragma vertex vert
            #pragma hull hull_shader
            #pragma domain domain_shader
            #pragma fragment frag
            // Effects: off = not compiled into the build at all (shader_feature: unused variants are stripped).
            #pragma shader_feature_local GT_NOISE
            #pragma multi_compile_local _ GT_SNOW
            // Vertex evaluation (renderer setting): the compute pre-pass's cached vertices, switched at run time.
            #pragma multi_compile_local _ GT_VERTEX_CACHE
            #pragma shader_feature_local GT_HEIGHT_COLOR
            #pragma shader_feature_local _ GT_DEBUG_NORMALS GT_DEBUG_PATCH_ID GT_DEBUG_TESS_FACTOR
            #define GT_PASS_FORWARD 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/HDRPAdapter.hlsl"
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/TerrainStages.hlsl"
            ENDHLSL
        }

        Pass
        {
            Name "DepthForwardOnly"
            Tags { "LightMode" = "DepthForwardOnly" }
            ZWrite On
            ZTest LEqual
            ColorMask 0
            Cull Back

            HLSLPROGRAM
            // Hull and domain stages: tessellation hardware required. A device without it skips
            // this SubShader and takes the next one (vert_fallback, no hull/domain).
            #pragma target 4.6
            #pragma require tessellation tessHW
            #pragma vertex vert
            #pragma hull hull_shader
            #pragma domain domain_shader
            #pragma fragment frag
            #pragma shader_feature_local GT_NOISE
            #pragma multi_compile_local _ GT_SNOW
            // Vertex evaluation (renderer setting): the compute pre-pass's cached vertices, switched at run time.
            #pragma multi_compile_local _ GT_VERTEX_CACHE
            #define GT_PASS_DEPTH 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/HDRPAdapter.hlsl"
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/TerrainStages.hlsl"
            ENDHLSL
        }

        Pass
        {
            Name "ShadowCaster"
            Tags { "LightMode" = "ShadowCaster" }
            ZWrite On
            ZTest LEqual
            ColorMask 0
            Cull Back

            HLSLPROGRAM
            // Hull and domain stages: tessellation hardware required. A device without it skips
            // this SubShader and takes the next one (vert_fallback, no hull/domain).
            #pragma target 4.6
            #pragma require tessellation tessHW
            #pragma vertex vert
            #pragma hull hull_shader
            #pragma domain domain_shader
            #pragma fragment frag
            #pragma shader_feature_local GT_NOISE
            #pragma multi_compile_local _ GT_SNOW
            // Vertex evaluation (renderer setting): the compute pre-pass's cached vertices, switched at run time.
            #pragma multi_compile_local _ GT_VERTEX_CACHE
            #define GT_PASS_SHADOWCASTER 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/HDRPAdapter.hlsl"
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/TerrainStages.hlsl"
            ENDHLSL
        }
    }

    // High Definition Render Pipeline, no tessellator.
    SubShader
    {
        Tags { "RenderPipeline" = "HDRenderPipeline" "RenderType" = "Opaque" "Queue" = "Geometry" "GregoryTerrainDraw" = "Fallback" }
        LOD 200

        Pass
        {
            Name "ForwardOnly"
            Tags { "LightMode" = "ForwardOnly" }
            ZWrite On
            ZTest LEqual
            Cull Back

            HLSLPROGRAM
            // No tessellator: each tile is an instanced (F+1)^2 UV grid evaluated in the vertex stage.
            #pragma target 4.5
            #pragma vertex vert_fallback
            #pragma fragment frag
            // Effects: off = not compiled into the build at all (shader_feature: unused variants are stripped).
            #pragma shader_feature_local GT_NOISE
            #pragma multi_compile_local _ GT_SNOW
            #pragma shader_feature_local GT_HEIGHT_COLOR
            #pragma shader_feature_local _ GT_DEBUG_NORMALS GT_DEBUG_PATCH_ID GT_DEBUG_TESS_FACTOR
            #define GT_PASS_FORWARD 1
            #define GT_FALLBACK 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/HDRPAdapter.hlsl"
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/TerrainStages.hlsl"
            ENDHLSL
        }

        Pass
        {
            Name "DepthForwardOnly"
            Tags { "LightMode" = "DepthForwardOnly" }
            ZWrite On
            ZTest LEqual
            ColorMask 0
            Cull Back

            HLSLPROGRAM
            // No tessellator: each tile is an instanced (F+1)^2 UV grid evaluated in the vertex stage.
            #pragma target 4.5
            #pragma vertex vert_fallback
            #pragma fragment frag
            #pragma shader_feature_local GT_NOISE
            #pragma multi_compile_local _ GT_SNOW
            #define GT_PASS_DEPTH 1
            #define GT_FALLBACK 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/HDRPAdapter.hlsl"
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/TerrainStages.hlsl"
            ENDHLSL
        }

        Pass
        {
            Name "ShadowCaster"
            Tags { "LightMode" = "ShadowCaster" }
            ZWrite On
            ZTest LEqual
            ColorMask 0
            Cull Back

            HLSLPROGRAM
            // No tessellator: each tile is an instanced (F+1)^2 UV grid evaluated in the vertex stage.
            #pragma target 4.5
            #pragma vertex vert_fallback
            #pragma fragment frag
            #pragma shader_feature_local GT_NOISE
            #pragma multi_compile_local _ GT_SNOW
            #define GT_PASS_SHADOWCASTER 1
            #define GT_FALLBACK 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/HDRPAdapter.hlsl"
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/TerrainStages.hlsl"
            ENDHLSL
        }
    }

    // Built-in Render Pipeline (no RenderPipeline tag), tessellated.
    SubShader
    {
        Tags { "RenderType" = "Opaque" "Queue" = "Geometry" "GregoryTerrainDraw" = "Tessellated" }
        LOD 300

        Pass
        {
            Name "ForwardBase"
            Tags { "LightMode" = "ForwardBase" }
            ZWrite On
            ZTest LEqual
            Cull Back

            HLSLPROGRAM
            // Hull and domain stages: tessellation hardware required. A device without it skips
            // this SubShader and takes the next one (vert_fallback, no hull/domain).
            #pragma target 4.6
            #pragma require tessellation tessHW
            #pragma vertex vert
            #pragma hull hull_shader
            #pragma domain domain_shader
            #pragma fragment frag
            // Effects: off = not compiled into the build at all (shader_feature: unused variants are stripped).
            #pragma shader_feature_local GT_NOISE
            #pragma multi_compile_local _ GT_SNOW
            // Vertex evaluation (renderer setting): the compute pre-pass's cached vertices, switched at run time.
            #pragma multi_compile_local _ GT_VERTEX_CACHE
            #pragma shader_feature_local GT_HEIGHT_COLOR
            #pragma shader_feature_local _ GT_DEBUG_NORMALS GT_DEBUG_PATCH_ID GT_DEBUG_TESS_FACTOR
            // Main directional light's shadow received (BuiltinAdapter.hlsl, GT_MainLightShadow).
            #pragma multi_compile _ SHADOWS_SCREEN
            #define GT_PASS_FORWARD 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/BuiltinAdapter.hlsl"
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/TerrainStages.hlsl"
            ENDHLSL
        }

        Pass
        {
            Name "ShadowCaster"
            Tags { "LightMode" = "ShadowCaster" }
            ZWrite On
            ZTest LEqual
            ColorMask 0
            Cull Back

            HLSLPROGRAM
            // Hull and domain stages: tessellation hardware required. A device without it skips
            // this SubShader and takes the next one (vert_fallback, no hull/domain).
            #pragma target 4.6
            #pragma require tessellation tessHW
            #pragma vertex vert
            #pragma hull hull_shader
            #pragma domain domain_shader
            #pragma fragment frag
            #pragma shader_feature_local GT_NOISE
            #pragma multi_compile_local _ GT_SNOW
            // Vertex evaluation (renderer setting): the compute pre-pass's cached vertices, switched at run time.
            #pragma multi_compile_local _ GT_VERTEX_CACHE
            #define GT_PASS_SHADOWCASTER 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/BuiltinAdapter.hlsl"
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/TerrainStages.hlsl"
            ENDHLSL
        }
    }

    // Built-in Render Pipeline, no tessellator.
    SubShader
    {
        Tags { "RenderType" = "Opaque" "Queue" = "Geometry" "GregoryTerrainDraw" = "Fallback" }
        LOD 200

        Pass
        {
            Name "ForwardBase"
            Tags { "LightMode" = "ForwardBase" }
            ZWrite On
            ZTest LEqual
            Cull Back

            HLSLPROGRAM
            // No tessellator: each tile is an instanced (F+1)^2 UV grid evaluated in the vertex stage.
            #pragma target 4.5
            #pragma vertex vert_fallback
            #pragma fragment frag
            // Effects: off = not compiled into the build at all (shader_feature: unused variants are stripped).
            #pragma shader_feature_local GT_NOISE
            #pragma multi_compile_local _ GT_SNOW
            #pragma shader_feature_local GT_HEIGHT_COLOR
            #pragma shader_feature_local _ GT_DEBUG_NORMALS GT_DEBUG_PATCH_ID GT_DEBUG_TESS_FACTOR
            // Main directional light's shadow received (BuiltinAdapter.hlsl, GT_MainLightShadow).
            #pragma multi_compile _ SHADOWS_SCREEN
            #define GT_PASS_FORWARD 1
            #define GT_FALLBACK 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/BuiltinAdapter.hlsl"
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/TerrainStages.hlsl"
            ENDHLSL
        }

        Pass
        {
            Name "ShadowCaster"
            Tags { "LightMode" = "ShadowCaster" }
            ZWrite On
            ZTest LEqual
            ColorMask 0
            Cull Back

            HLSLPROGRAM
            // No tessellator: each tile is an instanced (F+1)^2 UV grid evaluated in the vertex stage.
            #pragma target 4.5
            #pragma vertex vert_fallback
            #pragma fragment frag
            #pragma shader_feature_local GT_NOISE
            #pragma multi_compile_local _ GT_SNOW
            #define GT_PASS_SHADOWCASTER 1
            #define GT_FALLBACK 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/BuiltinAdapter.hlsl"
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/TerrainStages.hlsl"
            ENDHLSL
        }
    }

    Fallback Off
}
