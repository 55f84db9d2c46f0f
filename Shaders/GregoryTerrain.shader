// Gregory Terrain: the terrain surface, drawn by GregoryTerrainRenderer, which sets every value below; the material owns
// the effect switches. Per pipeline a tessellated SubShader, then its fallback; each pass defines its GT_PASS_* and includes
// its pipeline's adapter. Unwritten render state is ShaderLab's default (Cull Back, ZWrite On, ZTest LEqual): internals.md, "Unity side".
Shader "GregoryTerrain/Terrain"
{
    Properties
    {
        [Header(Effects)]
        [Toggle(GT_NOISE)] _GtNoise ("Noise detail", Float) = 1
        [Toggle(GT_HEIGHT_COLOR)] _GtHeightColor ("Height colour", Float) = 1
        [Toggle(GT_NOISE_TABLE)] _GtNoiseTable ("Tiled noise (faster; repeats every 256 noise cells)", Float) = 0

        // The debug views replace each other: KeywordEnum enables GT_DEBUG_<ENTRY> (Core's ShaderKeywords); no pass declares GT_DEBUG_NONE.
        [Header(Debug view)]
        [KeywordEnum(None, Normals, Patch_Id, Tess_Factor)] GT_DEBUG ("Debug view (replaces the lit colour)", Float) = 0

        [Header(Defaults. The renderer overrides these)]
        _Tess ("Tessellation: tiles M, max factor (1-64), target pixels per segment, uniform factor (0 = adaptive)", Vector) = (16, 64, 8, 0)
        _Noise ("Noise: amplitude, frequency, alpha (> 1), beta (> 1)", Vector) = (0.02, 16, 2, 2)
        _NoiseOctaves ("Noise octaves: N (0-16), vertices-across override (0 = auto), unused, unused", Vector) = (6, 0, 0, 0)
        _HeightColor ("Height colour: gamma (> 0), colour-noise amplitude, colour-noise frequency, unused", Vector) = (0.5, 0.1, 64, 0)
        _ColorLow ("Low colour", Color) = (0.22, 0.33, 0.14, 1)
        _ColorHigh ("High colour", Color) = (0.9, 0.9, 0.92, 1)
        // Written by the renderer only.
        [HideInInspector] _Range ("Range (c, d, g, h) relative to the origin", Vector) = (0, 0, 1, 1)
        [HideInInspector] _RangeOrigin ("Range origin (hi.x, hi.y, lo.x, lo.y)", Vector) = (0, 0, 0, 0)
        [HideInInspector] _GridSize ("Grid size (n, m, 0, 0)", Vector) = (1, 1, 0, 0)
        [HideInInspector] _TileLattice ("Tile lattice: 0 (tiles on the range) or the range the tiles were anchored at", Vector) = (0, 0, 0, 0)
        [HideInInspector] _OriginSurface ("Horizon levels: S(O), p(O) in float", Vector) = (0, 0, 0, 0)
    }

    // Universal Render Pipeline, tessellated (a project without URP skips it: PackageRequirements).
    SubShader
    {
        PackageRequirements { "com.unity.render-pipelines.universal": "14.0" }
        Tags { "RenderPipeline" = "UniversalPipeline" "RenderType" = "Opaque" "Queue" = "Geometry" "GregoryTerrainDraw" = "Tessellated" }
        LOD 300

        HLSLINCLUDE
        #include_with_pragmas "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/TessellatedSubShader.hlsl"
        #include_with_pragmas "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/ShaderKeywords.Tessellated.cs.hlsl"
        ENDHLSL

        Pass
        {
            Name "ForwardLit"
            Tags { "LightMode" = "UniversalForwardOnly" }
            HLSLPROGRAM
            #include_with_pragmas "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/ShaderKeywords.Colour.cs.hlsl"
            #pragma multi_compile _ _MAIN_LIGHT_SHADOWS _MAIN_LIGHT_SHADOWS_CASCADE _MAIN_LIGHT_SHADOWS_SCREEN
            #pragma multi_compile_fragment _ _SHADOWS_SOFT _SHADOWS_SOFT_LOW _SHADOWS_SOFT_MEDIUM _SHADOWS_SOFT_HIGH
            #pragma multi_compile_fragment _ _SCREEN_SPACE_OCCLUSION
            #pragma multi_compile_fog
            #pragma multi_compile_fragment _ _WRITE_RENDERING_LAYERS
            #define GT_PASS_FORWARD 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/URPAdapter.hlsl"
            ENDHLSL
        }

        Pass
        {
            Name "ShadowCaster"
            Tags { "LightMode" = "ShadowCaster" }
            ColorMask 0
            HLSLPROGRAM
            #pragma multi_compile _ _CASTING_PUNCTUAL_LIGHT_SHADOW
            #define GT_PASS_SHADOWCASTER 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/URPAdapter.hlsl"
            ENDHLSL
        }

        Pass
        {
            Name "DepthOnly"
            Tags { "LightMode" = "DepthOnly" }
            ColorMask R
            HLSLPROGRAM
            #define GT_PASS_DEPTH 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/URPAdapter.hlsl"
            ENDHLSL
        }

        Pass
        {
            Name "DepthNormalsOnly"
            Tags { "LightMode" = "DepthNormalsOnly" }
            HLSLPROGRAM
            #pragma multi_compile_fragment _ _GBUFFER_NORMALS_OCT
            #pragma multi_compile_fragment _ _WRITE_RENDERING_LAYERS
            #define GT_PASS_DEPTH_NORMALS 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/URPAdapter.hlsl"
            ENDHLSL
        }

        Pass
        {
            Name "SceneSelectionPass"
            Tags { "LightMode" = "SceneSelectionPass" }
            Cull Off
            HLSLPROGRAM
            #pragma editor_sync_compilation
            #define GT_PASS_SCENE_SELECTION 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/URPAdapter.hlsl"
            ENDHLSL
        }

        Pass
        {
            Name "ScenePickingPass"
            Tags { "LightMode" = "Picking" }
            HLSLPROGRAM
            #pragma editor_sync_compilation
            #define GT_PASS_SCENE_PICKING 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/URPAdapter.hlsl"
            ENDHLSL
        }
    }

    // Universal Render Pipeline, no tessellator.
    SubShader
    {
        PackageRequirements { "com.unity.render-pipelines.universal": "14.0" }
        Tags { "RenderPipeline" = "UniversalPipeline" "RenderType" = "Opaque" "Queue" = "Geometry" "GregoryTerrainDraw" = "Fallback" }
        LOD 200

        HLSLINCLUDE
        #include_with_pragmas "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/FallbackSubShader.hlsl"
        #include_with_pragmas "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/ShaderKeywords.Fallback.cs.hlsl"
        ENDHLSL

        Pass
        {
            Name "ForwardLit"
            Tags { "LightMode" = "UniversalForwardOnly" }
            HLSLPROGRAM
            #include_with_pragmas "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/ShaderKeywords.Colour.cs.hlsl"
            #pragma multi_compile _ _MAIN_LIGHT_SHADOWS _MAIN_LIGHT_SHADOWS_CASCADE _MAIN_LIGHT_SHADOWS_SCREEN
            #pragma multi_compile_fragment _ _SHADOWS_SOFT _SHADOWS_SOFT_LOW _SHADOWS_SOFT_MEDIUM _SHADOWS_SOFT_HIGH
            #pragma multi_compile_fragment _ _SCREEN_SPACE_OCCLUSION
            #pragma multi_compile_fog
            #pragma multi_compile_fragment _ _WRITE_RENDERING_LAYERS
            #define GT_PASS_FORWARD 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/URPAdapter.hlsl"
            ENDHLSL
        }

        Pass
        {
            Name "ShadowCaster"
            Tags { "LightMode" = "ShadowCaster" }
            ColorMask 0
            HLSLPROGRAM
            #pragma multi_compile_vertex _ _CASTING_PUNCTUAL_LIGHT_SHADOW
            #define GT_PASS_SHADOWCASTER 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/URPAdapter.hlsl"
            ENDHLSL
        }

        Pass
        {
            Name "DepthOnly"
            Tags { "LightMode" = "DepthOnly" }
            ColorMask R
            HLSLPROGRAM
            #define GT_PASS_DEPTH 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/URPAdapter.hlsl"
            ENDHLSL
        }

        Pass
        {
            Name "DepthNormalsOnly"
            Tags { "LightMode" = "DepthNormalsOnly" }
            HLSLPROGRAM
            #pragma multi_compile_fragment _ _GBUFFER_NORMALS_OCT
            #pragma multi_compile_fragment _ _WRITE_RENDERING_LAYERS
            #define GT_PASS_DEPTH_NORMALS 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/URPAdapter.hlsl"
            ENDHLSL
        }

        Pass
        {
            Name "SceneSelectionPass"
            Tags { "LightMode" = "SceneSelectionPass" }
            Cull Off
            HLSLPROGRAM
            #pragma editor_sync_compilation
            #define GT_PASS_SCENE_SELECTION 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/URPAdapter.hlsl"
            ENDHLSL
        }

        Pass
        {
            Name "ScenePickingPass"
            Tags { "LightMode" = "Picking" }
            HLSLPROGRAM
            #pragma editor_sync_compilation
            #define GT_PASS_SCENE_PICKING 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/URPAdapter.hlsl"
            ENDHLSL
        }
    }

    // High Definition Render Pipeline, tessellated: a forward-only material with HDRP's Unlit's stencil.
    SubShader
    {
        PackageRequirements { "com.unity.render-pipelines.high-definition": "14.0" }
        Tags { "RenderPipeline" = "HDRenderPipeline" "RenderType" = "Opaque" "Queue" = "Geometry" "GregoryTerrainDraw" = "Tessellated" }
        LOD 300

        HLSLINCLUDE
        #include_with_pragmas "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/TessellatedSubShader.hlsl"
        #include_with_pragmas "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/ShaderKeywords.Tessellated.cs.hlsl"
        ENDHLSL

        Pass
        {
            Name "SceneSelectionPass"
            Tags { "LightMode" = "SceneSelectionPass" }
            Cull Off
            HLSLPROGRAM
            #pragma editor_sync_compilation
            #define GT_PASS_SCENE_SELECTION 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/HDRPAdapter.hlsl"
            ENDHLSL
        }

        Pass
        {
            Name "ScenePickingPass"
            Tags { "LightMode" = "Picking" }
            HLSLPROGRAM
            #pragma editor_sync_compilation
            #define GT_PASS_SCENE_PICKING 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/HDRPAdapter.hlsl"
            ENDHLSL
        }

        Pass
        {
            Name "DepthForwardOnly"
            Tags { "LightMode" = "DepthForwardOnly" }
            Stencil
            {
                WriteMask 9
                Ref 1
                Comp Always
                Pass Replace
            }
            HLSLPROGRAM
            #pragma multi_compile _ WRITE_MSAA_DEPTH
            #define GT_PASS_DEPTH_NORMALS 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/HDRPAdapter.hlsl"
            ENDHLSL
        }

        Pass
        {
            Name "ForwardOnly"
            Tags { "LightMode" = "ForwardOnly" }
            Stencil
            {
                WriteMask 6
                Ref 0
                Comp Always
                Pass Replace
            }
            HLSLPROGRAM
            #include_with_pragmas "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/ShaderKeywords.Colour.cs.hlsl"
            #pragma multi_compile_fragment SHADOW_LOW SHADOW_MEDIUM SHADOW_HIGH
            #define GT_PASS_FORWARD 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/HDRPAdapter.hlsl"
            ENDHLSL
        }

        Pass
        {
            Name "ShadowCaster"
            Tags { "LightMode" = "ShadowCaster" }
            ZClip [_ZClip]   // HDRP's: 0 (clamp) for directional cascades
            ColorMask 0
            HLSLPROGRAM
            #define GT_PASS_SHADOWCASTER 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/HDRPAdapter.hlsl"
            ENDHLSL
        }
    }

    // High Definition Render Pipeline, no tessellator.
    SubShader
    {
        PackageRequirements { "com.unity.render-pipelines.high-definition": "14.0" }
        Tags { "RenderPipeline" = "HDRenderPipeline" "RenderType" = "Opaque" "Queue" = "Geometry" "GregoryTerrainDraw" = "Fallback" }
        LOD 200

        HLSLINCLUDE
        #include_with_pragmas "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/FallbackSubShader.hlsl"
        #include_with_pragmas "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/ShaderKeywords.Fallback.cs.hlsl"
        ENDHLSL

        Pass
        {
            Name "SceneSelectionPass"
            Tags { "LightMode" = "SceneSelectionPass" }
            Cull Off
            HLSLPROGRAM
            #pragma editor_sync_compilation
            #define GT_PASS_SCENE_SELECTION 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/HDRPAdapter.hlsl"
            ENDHLSL
        }

        Pass
        {
            Name "ScenePickingPass"
            Tags { "LightMode" = "Picking" }
            HLSLPROGRAM
            #pragma editor_sync_compilation
            #define GT_PASS_SCENE_PICKING 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/HDRPAdapter.hlsl"
            ENDHLSL
        }

        Pass
        {
            Name "DepthForwardOnly"
            Tags { "LightMode" = "DepthForwardOnly" }
            Stencil
            {
                WriteMask 9
                Ref 1
                Comp Always
                Pass Replace
            }
            HLSLPROGRAM
            #pragma multi_compile _ WRITE_MSAA_DEPTH
            #define GT_PASS_DEPTH_NORMALS 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/HDRPAdapter.hlsl"
            ENDHLSL
        }

        Pass
        {
            Name "ForwardOnly"
            Tags { "LightMode" = "ForwardOnly" }
            Stencil
            {
                WriteMask 6
                Ref 0
                Comp Always
                Pass Replace
            }
            HLSLPROGRAM
            #include_with_pragmas "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/ShaderKeywords.Colour.cs.hlsl"
            #pragma multi_compile_fragment SHADOW_LOW SHADOW_MEDIUM SHADOW_HIGH
            #define GT_PASS_FORWARD 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/HDRPAdapter.hlsl"
            ENDHLSL
        }

        Pass
        {
            Name "ShadowCaster"
            Tags { "LightMode" = "ShadowCaster" }
            ZClip [_ZClip]   // HDRP's: 0 (clamp) for directional cascades
            ColorMask 0
            HLSLPROGRAM
            #define GT_PASS_SHADOWCASTER 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/HDRPAdapter.hlsl"
            ENDHLSL
        }
    }

    // Built-in Render Pipeline (no RenderPipeline tag), tessellated.
    SubShader
    {
        Tags { "RenderType" = "Opaque" "Queue" = "Geometry" "GregoryTerrainDraw" = "Tessellated" }
        LOD 300

        HLSLINCLUDE
        #include_with_pragmas "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/TessellatedSubShader.hlsl"
        #include_with_pragmas "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/ShaderKeywords.Tessellated.cs.hlsl"
        ENDHLSL

        Pass
        {
            Name "ForwardBase"
            Tags { "LightMode" = "ForwardBase" }
            HLSLPROGRAM
            #include_with_pragmas "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/ShaderKeywords.Colour.cs.hlsl"
            #pragma multi_compile _ SHADOWS_SCREEN
            #pragma multi_compile_fog
            #define GT_PASS_FORWARD 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/BuiltinAdapter.hlsl"
            ENDHLSL
        }

        Pass
        {
            Name "ShadowCaster"
            Tags { "LightMode" = "ShadowCaster" }
            ColorMask 0
            HLSLPROGRAM
            #define GT_PASS_SHADOWCASTER 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/BuiltinAdapter.hlsl"
            ENDHLSL
        }
    }

    // Built-in Render Pipeline, no tessellator.
    SubShader
    {
        Tags { "RenderType" = "Opaque" "Queue" = "Geometry" "GregoryTerrainDraw" = "Fallback" }
        LOD 200

        HLSLINCLUDE
        #include_with_pragmas "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/FallbackSubShader.hlsl"
        #include_with_pragmas "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/ShaderKeywords.Fallback.cs.hlsl"
        ENDHLSL

        Pass
        {
            Name "ForwardBase"
            Tags { "LightMode" = "ForwardBase" }
            HLSLPROGRAM
            #include_with_pragmas "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/ShaderKeywords.Colour.cs.hlsl"
            #pragma multi_compile _ SHADOWS_SCREEN
            #pragma multi_compile_fog
            #define GT_PASS_FORWARD 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/BuiltinAdapter.hlsl"
            ENDHLSL
        }

        Pass
        {
            Name "ShadowCaster"
            Tags { "LightMode" = "ShadowCaster" }
            ColorMask 0
            HLSLPROGRAM
            #define GT_PASS_SHADOWCASTER 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/BuiltinAdapter.hlsl"
            ENDHLSL
        }
    }

    Fallback Off
}
