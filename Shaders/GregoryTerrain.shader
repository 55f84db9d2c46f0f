// Gregory Terrain: the terrain surface, tessellated from the patch grid on the GPU.
// Drawn by GregoryTerrainRenderer (one procedural draw: M x M four-control-point tile patches, or the
// instanced fallback); the renderer fills the buffers and the packed constants through a
// MaterialPropertyBlock, so the numeric values below are only defaults. The material owns the
// effect switches (keywords). Documentation~/index.md describes every setting.
//
// SubShader order matters: Unity takes the first SubShader whose RenderPipeline tag matches the
// active pipeline and whose passes the GPU supports. Each pipeline has a tessellated SubShader
// (#pragma require tessellation tessHW) followed by a fallback SubShader (vert_fallback) that
// devices without hull/domain stages get instead. Shadow and depth passes run the same stages with
// the camera's factors, so shadows and depth come from the same tessellated surface as the colour. Each SubShader's
// "GregoryTerrainDraw" tag (Tessellated / Fallback) tells GregoryTerrainRenderer which draw the
// SubShader Unity picked expects (Material.GetTag without fallbacks reads the SubShader in use).
//
// Pipelines: each SRP SubShader has a PackageRequirements block, so a project without that package
// skips it (no missing-include errors); the Built-in SubShaders need no package. URP draws the
// colour in a forward-only pass (UniversalForwardOnly, drawn by the Forward, Forward+ and Deferred
// renderers) with DepthNormalsOnly for the normals prepass; HDRP as a forward-only material
// (DepthForwardOnly writes the normal buffer, ForwardOnly the colour); both have the Scene view's
// selection and picking passes. Documentation~/index.md, "Pipelines", lists what each one supports.
//
// Keywords: the package's are exactly the shipped ones of Tools~/rig/shader_variants.txt (the
// rig-only ones belong to Tools~/rig/TerrainRig.hlsl). Those that change the shape or where it comes
// from are written once per SubShader, in its HLSLINCLUDE (Unity pastes it at the top of every pass's
// HLSLPROGRAM), with the stage pragmas; a pass adds only its own: the forward passes their colour and
// debug switches, each pass the pipeline keywords it reads (multi_compile; the adapters say what each
// changes). The material's toggles are shader_feature_local; those a script switches at run time are
// multi_compile_local, so a player build keeps them though no saved material has them on: GT_SNOW
// (SnowSimulator) and, in the tessellated SubShaders only, one set for where the vertices come from:
// GT_RANGE_ORIGIN (the deep-zoom code, while the renderer sends an origin), GT_LOD (the renderer's
// levels) or GT_VERTEX_CACHE (Vertex evaluation = Compute cache: the domain stage reads the vertices
// TerrainCache.compute evaluated). The levels and the cache compile the origin's code too and never
// draw together, so at most one is on (RelativeSurface.NeedsRangeOriginKeyword) and no combination is
// compiled that is never drawn. The fallback has no hull/domain stage to feed and keeps the origin's
// run-time branch. Each pass defines one GT_PASS_* before its adapter; `frag` writes what that pass
// needs (TerrainStages.hlsl). Checked off Unity by Tools~/RigTests/ShaderLabTests.cs and compiled pass
// by pass against Unity's real shader libraries by `gt shaderlab` (glslang and DXC).
Shader "GregoryTerrain/Terrain"
{
    Properties
    {
        [Header(Effects)]
        [Toggle(GT_NOISE)] _GtNoise ("Noise detail", Float) = 1
        [Toggle(GT_HEIGHT_COLOR)] _GtHeightColor ("Height colour", Float) = 1
        [Toggle(GT_NOISE_TABLE)] _GtNoiseTable ("Tiled noise (faster; repeats every 256 noise cells)", Float) = 0

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
        _ColorLow ("Low colour", Color) = (0.22, 0.33, 0.14, 1)
        _ColorHigh ("High colour", Color) = (0.9, 0.9, 0.92, 1)

        // Written by the renderer only.
        [HideInInspector] _Range ("Range (c, d, g, h) relative to the origin", Vector) = (0, 0, 1, 1)
        [HideInInspector] _RangeOrigin ("Range origin (hi.x, hi.y, lo.x, lo.y)", Vector) = (0, 0, 0, 0)
        [HideInInspector] _GridSize ("Grid size (n, m, 0, 0)", Vector) = (1, 1, 0, 0)
        [HideInInspector] _TileLattice ("Tile lattice: 0 (tiles on the range) or the range the tiles were anchored at", Vector) = (0, 0, 0, 0)
    }

    // Universal Render Pipeline, tessellated.
    SubShader
    {
        // Skipped, not compiled, in a project without this package (no missing-include errors).
        PackageRequirements
        {
            "com.unity.render-pipelines.universal": "14.0"
        }
        Tags { "RenderPipeline" = "UniversalPipeline" "RenderType" = "Opaque" "Queue" = "Geometry" "GregoryTerrainDraw" = "Tessellated" }
        LOD 300
        ZWrite On
        ZTest LEqual
        Cull Back

        // Every pass: hull and domain stages (a device without tessellation hardware skips this
        // SubShader for the next one) and the package's keywords (see the top of the file).
        HLSLINCLUDE
        #pragma target 4.6
        #pragma require tessellation tessHW
        #pragma vertex vert
        #pragma hull hull_shader
        #pragma domain domain_shader
        #pragma fragment frag
        #pragma shader_feature_local GT_NOISE
        #pragma shader_feature_local GT_NOISE_TABLE
        #pragma multi_compile_local _ GT_SNOW
        #pragma multi_compile_local _ GT_RANGE_ORIGIN GT_LOD GT_VERTEX_CACHE
        ENDHLSL

        Pass
        {
            Name "ForwardLit"
            Tags { "LightMode" = "UniversalForwardOnly" }
            HLSLPROGRAM
            #pragma shader_feature_local GT_HEIGHT_COLOR
            #pragma shader_feature_local _ GT_DEBUG_NORMALS GT_DEBUG_PATCH_ID GT_DEBUG_TESS_FACTOR
            // URP's own keywords, where the pass reads them (URPAdapter.hlsl): main-light shadows received
            // (shadow map, cascades or the screen-space shadows feature), their soft-shadow filter quality,
            // SSAO and fog (all of URP 14's fog modes, evaluated per pixel).
            #pragma multi_compile _ _MAIN_LIGHT_SHADOWS _MAIN_LIGHT_SHADOWS_CASCADE _MAIN_LIGHT_SHADOWS_SCREEN
            #pragma multi_compile_fragment _ _SHADOWS_SOFT _SHADOWS_SOFT_LOW _SHADOWS_SOFT_MEDIUM _SHADOWS_SOFT_HIGH
            #pragma multi_compile_fragment _ _SCREEN_SPACE_OCCLUSION
            #pragma multi_compile_fog
            #define GT_PASS_FORWARD 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/URPAdapter.hlsl"
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/TerrainStages.hlsl"
            ENDHLSL
        }

        Pass
        {
            Name "ShadowCaster"
            Tags { "LightMode" = "ShadowCaster" }
            ColorMask 0
            HLSLPROGRAM
            // Spot and point lights: the bias direction per vertex from _LightPosition (URP's keyword).
            // The hull and domain stages transform the vertices too: not multi_compile_vertex as URP's Lit.
            #pragma multi_compile _ _CASTING_PUNCTUAL_LIGHT_SHADOW
            #define GT_PASS_SHADOWCASTER 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/URPAdapter.hlsl"
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/TerrainStages.hlsl"
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
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/TerrainStages.hlsl"
            ENDHLSL
        }

        Pass
        {
            Name "DepthNormalsOnly"
            Tags { "LightMode" = "DepthNormalsOnly" }
            HLSLPROGRAM
            // URP's normal packing for the deferred renderer's accurate G-buffer normals.
            #pragma multi_compile_fragment _ _GBUFFER_NORMALS_OCT
            #define GT_PASS_DEPTH_NORMALS 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/URPAdapter.hlsl"
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/TerrainStages.hlsl"
            ENDHLSL
        }

        Pass
        {
            Name "SceneSelectionPass"
            Tags { "LightMode" = "SceneSelectionPass" }
            Cull Off
            HLSLPROGRAM
            // Editor only: compiled when the Scene view first needs it, not ahead (as Unity's own passes).
            #pragma editor_sync_compilation
            #define GT_PASS_SCENE_SELECTION 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/URPAdapter.hlsl"
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/TerrainStages.hlsl"
            ENDHLSL
        }

        Pass
        {
            Name "ScenePickingPass"
            Tags { "LightMode" = "Picking" }
            HLSLPROGRAM
            // Editor only: compiled when the Scene view first needs it, not ahead (as Unity's own passes).
            #pragma editor_sync_compilation
            #define GT_PASS_SCENE_PICKING 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/URPAdapter.hlsl"
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/TerrainStages.hlsl"
            ENDHLSL
        }
    }

    // Universal Render Pipeline, no tessellator.
    SubShader
    {
        // Skipped, not compiled, in a project without this package (no missing-include errors).
        PackageRequirements
        {
            "com.unity.render-pipelines.universal": "14.0"
        }
        Tags { "RenderPipeline" = "UniversalPipeline" "RenderType" = "Opaque" "Queue" = "Geometry" "GregoryTerrainDraw" = "Fallback" }
        LOD 200
        ZWrite On
        ZTest LEqual
        Cull Back

        // Every pass: no tessellator (each tile an instanced (F+1)^2 UV grid evaluated in the vertex
        // stage) and the package's keywords (see the top of the file).
        HLSLINCLUDE
        #pragma target 4.5
        #pragma vertex vert_fallback
        #pragma fragment frag
        #pragma shader_feature_local GT_NOISE
        #pragma shader_feature_local GT_NOISE_TABLE
        #pragma multi_compile_local _ GT_SNOW
        #define GT_FALLBACK 1
        ENDHLSL

        Pass
        {
            Name "ForwardLit"
            Tags { "LightMode" = "UniversalForwardOnly" }
            HLSLPROGRAM
            #pragma shader_feature_local GT_HEIGHT_COLOR
            #pragma shader_feature_local _ GT_DEBUG_NORMALS GT_DEBUG_PATCH_ID GT_DEBUG_TESS_FACTOR
            // URP's own keywords, where the pass reads them (URPAdapter.hlsl): main-light shadows received
            // (shadow map, cascades or the screen-space shadows feature), their soft-shadow filter quality,
            // SSAO and fog (all of URP 14's fog modes, evaluated per pixel).
            #pragma multi_compile _ _MAIN_LIGHT_SHADOWS _MAIN_LIGHT_SHADOWS_CASCADE _MAIN_LIGHT_SHADOWS_SCREEN
            #pragma multi_compile_fragment _ _SHADOWS_SOFT _SHADOWS_SOFT_LOW _SHADOWS_SOFT_MEDIUM _SHADOWS_SOFT_HIGH
            #pragma multi_compile_fragment _ _SCREEN_SPACE_OCCLUSION
            #pragma multi_compile_fog
            #define GT_PASS_FORWARD 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/URPAdapter.hlsl"
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/TerrainStages.hlsl"
            ENDHLSL
        }

        Pass
        {
            Name "ShadowCaster"
            Tags { "LightMode" = "ShadowCaster" }
            ColorMask 0
            HLSLPROGRAM
            // Spot and point lights: the bias direction per vertex from _LightPosition (URP's keyword).
            #pragma multi_compile_vertex _ _CASTING_PUNCTUAL_LIGHT_SHADOW
            #define GT_PASS_SHADOWCASTER 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/URPAdapter.hlsl"
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/TerrainStages.hlsl"
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
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/TerrainStages.hlsl"
            ENDHLSL
        }

        Pass
        {
            Name "DepthNormalsOnly"
            Tags { "LightMode" = "DepthNormalsOnly" }
            HLSLPROGRAM
            // URP's normal packing for the deferred renderer's accurate G-buffer normals.
            #pragma multi_compile_fragment _ _GBUFFER_NORMALS_OCT
            #define GT_PASS_DEPTH_NORMALS 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/URPAdapter.hlsl"
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/TerrainStages.hlsl"
            ENDHLSL
        }

        Pass
        {
            Name "SceneSelectionPass"
            Tags { "LightMode" = "SceneSelectionPass" }
            Cull Off
            HLSLPROGRAM
            // Editor only: compiled when the Scene view first needs it, not ahead (as Unity's own passes).
            #pragma editor_sync_compilation
            #define GT_PASS_SCENE_SELECTION 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/URPAdapter.hlsl"
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/TerrainStages.hlsl"
            ENDHLSL
        }

        Pass
        {
            Name "ScenePickingPass"
            Tags { "LightMode" = "Picking" }
            HLSLPROGRAM
            // Editor only: compiled when the Scene view first needs it, not ahead (as Unity's own passes).
            #pragma editor_sync_compilation
            #define GT_PASS_SCENE_PICKING 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/URPAdapter.hlsl"
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/TerrainStages.hlsl"
            ENDHLSL
        }
    }

    // High Definition Render Pipeline (forward-only material), tessellated.
    SubShader
    {
        // Skipped, not compiled, in a project without this package (no missing-include errors).
        PackageRequirements
        {
            "com.unity.render-pipelines.high-definition": "14.0"
        }
        Tags { "RenderPipeline" = "HDRenderPipeline" "RenderType" = "Opaque" "Queue" = "Geometry" "GregoryTerrainDraw" = "Tessellated" }
        LOD 300
        ZWrite On
        ZTest LEqual
        Cull Back

        // Every pass: hull and domain stages (a device without tessellation hardware skips this
        // SubShader for the next one) and the package's keywords (see the top of the file).
        HLSLINCLUDE
        #pragma target 4.6
        #pragma require tessellation tessHW
        #pragma vertex vert
        #pragma hull hull_shader
        #pragma domain domain_shader
        #pragma fragment frag
        #pragma shader_feature_local GT_NOISE
        #pragma shader_feature_local GT_NOISE_TABLE
        #pragma multi_compile_local _ GT_SNOW
        #pragma multi_compile_local _ GT_RANGE_ORIGIN GT_LOD GT_VERTEX_CACHE
        ENDHLSL

        Pass
        {
            Name "SceneSelectionPass"
            Tags { "LightMode" = "SceneSelectionPass" }
            Cull Off
            HLSLPROGRAM
            // Editor only: compiled when the Scene view first needs it, not ahead (as Unity's own passes).
            #pragma editor_sync_compilation
            #define GT_PASS_SCENE_SELECTION 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/HDRPAdapter.hlsl"
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/TerrainStages.hlsl"
            ENDHLSL
        }

        Pass
        {
            Name "ScenePickingPass"
            Tags { "LightMode" = "Picking" }
            HLSLPROGRAM
            // Editor only: compiled when the Scene view first needs it, not ahead (as Unity's own passes).
            #pragma editor_sync_compilation
            #define GT_PASS_SCENE_PICKING 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/HDRPAdapter.hlsl"
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/TerrainStages.hlsl"
            ENDHLSL
        }

        Pass
        {
            Name "DepthForwardOnly"
            Tags { "LightMode" = "DepthForwardOnly" }
            // HDRP's stencil for an unlit-like forward-only material (its Unlit's values): IsUnlit (1) set,
            // TraceReflectionRay (8) cleared, so SSR and GI skip the terrain.
            Stencil
            {
                WriteMask 9
                Ref 1
                Comp Always
                Pass Replace
            }
            HLSLPROGRAM
            // MSAA: HDRP also binds the depth as a colour target (its keyword).
            #pragma multi_compile _ WRITE_MSAA_DEPTH
            // Writes HDRP's normal buffer too (SSAO, SSR and contact shadows read it).
            #define GT_PASS_DEPTH_NORMALS 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/HDRPAdapter.hlsl"
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/TerrainStages.hlsl"
            ENDHLSL
        }

        Pass
        {
            Name "ForwardOnly"
            Tags { "LightMode" = "ForwardOnly" }
            // HDRP's forward stencil: clears RequiresDeferredLighting (2) and SubsurfaceScattering (4).
            Stencil
            {
                WriteMask 6
                Ref 0
                Comp Always
                Pass Replace
            }
            HLSLPROGRAM
            #pragma shader_feature_local GT_HEIGHT_COLOR
            #pragma shader_feature_local _ GT_DEBUG_NORMALS GT_DEBUG_PATCH_ID GT_DEBUG_TESS_FACTOR
            // HDRP's shadow filtering quality (the HDRP asset's), as its Lit forward pass.
            #pragma multi_compile_fragment SHADOW_LOW SHADOW_MEDIUM SHADOW_HIGH
            #define GT_PASS_FORWARD 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/HDRPAdapter.hlsl"
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/TerrainStages.hlsl"
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
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/TerrainStages.hlsl"
            ENDHLSL
        }
    }

    // High Definition Render Pipeline, no tessellator.
    SubShader
    {
        // Skipped, not compiled, in a project without this package (no missing-include errors).
        PackageRequirements
        {
            "com.unity.render-pipelines.high-definition": "14.0"
        }
        Tags { "RenderPipeline" = "HDRenderPipeline" "RenderType" = "Opaque" "Queue" = "Geometry" "GregoryTerrainDraw" = "Fallback" }
        LOD 200
        ZWrite On
        ZTest LEqual
        Cull Back

        // Every pass: no tessellator (each tile an instanced (F+1)^2 UV grid evaluated in the vertex
        // stage) and the package's keywords (see the top of the file).
        HLSLINCLUDE
        #pragma target 4.5
        #pragma vertex vert_fallback
        #pragma fragment frag
        #pragma shader_feature_local GT_NOISE
        #pragma shader_feature_local GT_NOISE_TABLE
        #pragma multi_compile_local _ GT_SNOW
        #define GT_FALLBACK 1
        ENDHLSL

        Pass
        {
            Name "SceneSelectionPass"
            Tags { "LightMode" = "SceneSelectionPass" }
            Cull Off
            HLSLPROGRAM
            // Editor only: compiled when the Scene view first needs it, not ahead (as Unity's own passes).
            #pragma editor_sync_compilation
            #define GT_PASS_SCENE_SELECTION 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/HDRPAdapter.hlsl"
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/TerrainStages.hlsl"
            ENDHLSL
        }

        Pass
        {
            Name "ScenePickingPass"
            Tags { "LightMode" = "Picking" }
            HLSLPROGRAM
            // Editor only: compiled when the Scene view first needs it, not ahead (as Unity's own passes).
            #pragma editor_sync_compilation
            #define GT_PASS_SCENE_PICKING 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/HDRPAdapter.hlsl"
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/TerrainStages.hlsl"
            ENDHLSL
        }

        Pass
        {
            Name "DepthForwardOnly"
            Tags { "LightMode" = "DepthForwardOnly" }
            // HDRP's stencil for an unlit-like forward-only material (its Unlit's values): IsUnlit (1) set,
            // TraceReflectionRay (8) cleared, so SSR and GI skip the terrain.
            Stencil
            {
                WriteMask 9
                Ref 1
                Comp Always
                Pass Replace
            }
            HLSLPROGRAM
            // MSAA: HDRP also binds the depth as a colour target (its keyword).
            #pragma multi_compile _ WRITE_MSAA_DEPTH
            // Writes HDRP's normal buffer too (SSAO, SSR and contact shadows read it).
            #define GT_PASS_DEPTH_NORMALS 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/HDRPAdapter.hlsl"
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/TerrainStages.hlsl"
            ENDHLSL
        }

        Pass
        {
            Name "ForwardOnly"
            Tags { "LightMode" = "ForwardOnly" }
            // HDRP's forward stencil: clears RequiresDeferredLighting (2) and SubsurfaceScattering (4).
            Stencil
            {
                WriteMask 6
                Ref 0
                Comp Always
                Pass Replace
            }
            HLSLPROGRAM
            #pragma shader_feature_local GT_HEIGHT_COLOR
            #pragma shader_feature_local _ GT_DEBUG_NORMALS GT_DEBUG_PATCH_ID GT_DEBUG_TESS_FACTOR
            // HDRP's shadow filtering quality (the HDRP asset's), as its Lit forward pass.
            #pragma multi_compile_fragment SHADOW_LOW SHADOW_MEDIUM SHADOW_HIGH
            #define GT_PASS_FORWARD 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/HDRPAdapter.hlsl"
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/TerrainStages.hlsl"
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
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/TerrainStages.hlsl"
            ENDHLSL
        }
    }

    // Built-in Render Pipeline (no RenderPipeline tag), tessellated.
    SubShader
    {
        Tags { "RenderType" = "Opaque" "Queue" = "Geometry" "GregoryTerrainDraw" = "Tessellated" }
        LOD 300
        ZWrite On
        ZTest LEqual
        Cull Back

        // Every pass: hull and domain stages (a device without tessellation hardware skips this
        // SubShader for the next one) and the package's keywords (see the top of the file).
        HLSLINCLUDE
        #pragma target 4.6
        #pragma require tessellation tessHW
        #pragma vertex vert
        #pragma hull hull_shader
        #pragma domain domain_shader
        #pragma fragment frag
        #pragma shader_feature_local GT_NOISE
        #pragma shader_feature_local GT_NOISE_TABLE
        #pragma multi_compile_local _ GT_SNOW
        #pragma multi_compile_local _ GT_RANGE_ORIGIN GT_LOD GT_VERTEX_CACHE
        ENDHLSL

        Pass
        {
            Name "ForwardBase"
            Tags { "LightMode" = "ForwardBase" }
            HLSLPROGRAM
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
            ColorMask 0
            HLSLPROGRAM
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
        ZWrite On
        ZTest LEqual
        Cull Back

        // Every pass: no tessellator (each tile an instanced (F+1)^2 UV grid evaluated in the vertex
        // stage) and the package's keywords (see the top of the file).
        HLSLINCLUDE
        #pragma target 4.5
        #pragma vertex vert_fallback
        #pragma fragment frag
        #pragma shader_feature_local GT_NOISE
        #pragma shader_feature_local GT_NOISE_TABLE
        #pragma multi_compile_local _ GT_SNOW
        #define GT_FALLBACK 1
        ENDHLSL

        Pass
        {
            Name "ForwardBase"
            Tags { "LightMode" = "ForwardBase" }
            HLSLPROGRAM
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
            ColorMask 0
            HLSLPROGRAM
            #define GT_PASS_SHADOWCASTER 1
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/BuiltinAdapter.hlsl"
            #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/TerrainStages.hlsl"
            ENDHLSL
        }
    }

    Fallback Off
}
