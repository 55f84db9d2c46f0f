// Universal Render Pipeline adapter (interface: see StandaloneAdapter.hlsl).
// Unity API names used: Core.hlsl (TransformWorldToHClip, GetCameraPositionWS, _ScreenParams,
// CBUFFER_START/CBUFFER_END, UNITY_REVERSED_Z, UNITY_NEAR_CLIP_VALUE, NormalizeNormalPerPixel,
// GetNormalizedScreenSpaceUV, InitializeInputDataFog, MixFog and, from SRP Core's Packing.hlsl,
// PackNormalOctQuadEncode / PackFloat2To888), Lighting.hlsl (GetMainLight, Light.direction/.color/
// .shadowAttenuation, GetScreenSpaceAmbientOcclusion) and Shadows.hlsl, which Lighting.hlsl includes
// (_ShadowBias, ApplyShadowBias, TransformWorldToShadowCoord, the _MAIN_LIGHT_SHADOWS* and _SHADOWS_SOFT* keywords).
// Compiled against URP 14's real ShaderLibrary off Unity by the rig (Tools~/rig/shaderlab.py).
//
// Object matrix: _GtObjectToWorld / _GtWorldToObject (UnityAdapterCommon.hlsl says why), never
// UNITY_MATRIX_M / unity_ObjectToWorld.
#ifndef GT_URP_ADAPTER_INCLUDED
#define GT_URP_ADAPTER_INCLUDED

#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Lighting.hlsl"

#define GT_ADAPTER_URP 1

// The forward pass's effects that URP switches with its own keywords (declared by the pass):
// received main-light shadows (shadow map, cascades or the screen-space shadows feature; their
// soft-shadow filter quality, _SHADOWS_SOFT*, is read by Shadows.hlsl), fog (all of URP 14's fog
// modes, evaluated per pixel from the world position, _FOG_FRAGMENT) and screen-space ambient occlusion.
#if defined(GT_PASS_FORWARD)
    #if defined(_MAIN_LIGHT_SHADOWS) || defined(_MAIN_LIGHT_SHADOWS_CASCADE) || defined(_MAIN_LIGHT_SHADOWS_SCREEN)
        #define GT_RECEIVE_SHADOWS 1
    #endif
    #if defined(FOG_LINEAR) || defined(FOG_EXP) || defined(FOG_EXP2)
        #define GT_FOG 1
    #endif
    #if defined(_SCREEN_SPACE_OCCLUSION)
        #define GT_AMBIENT_OCCLUSION 1
    #endif
#endif
// URP's rendering-layers target (decal layers): with _WRITE_RENDERING_LAYERS URP binds a second colour
// target to the forward pass (DrawObjectsWithRenderingLayersPass) or the depth-normals pass (DepthNormalOnlyPass).
#if defined(_WRITE_RENDERING_LAYERS) && (defined(GT_PASS_FORWARD) || defined(GT_PASS_DEPTH_NORMALS))
    #define GT_WRITE_RENDERING_LAYERS 1
#endif
#if defined(GT_RECEIVE_SHADOWS) || defined(GT_FOG)
    #define GT_VARYINGS_POSITION_WS 1
#endif
// Material constants, the object matrices, normals, the editor's selection passes.
#include "UnityAdapterCommon.hlsl"

#if defined(GT_PASS_SHADOWCASTER)
// Set by URP for the light whose shadow map is being drawn (ShadowUtils.SetupShadowCasterConstantBuffer):
// a directional light's direction towards the light, a spot or point light's position
// (_CASTING_PUNCTUAL_LIGHT_SHADOW, URP's keyword for those: per vertex in the fallback, as URP's Lit;
// for every stage when tessellated, since the hull and domain stages transform vertices too).
float3 _LightDirection;
float3 _LightPosition;
#endif

float3 GT_ObjectToWorld(float3 positionOS) { return mul(_GtObjectToWorld, float4(positionOS, 1.0)).xyz; }
float4 GT_WorldToClip(float3 positionWS) { return TransformWorldToHClip(positionWS); }

#if defined(GT_PASS_SHADOWCASTER)
// Towards the light whose shadow map is drawn: per vertex for a spot or point light.
float3 ShadowCasterLightDirection(float3 positionWS)
{
    #if defined(_CASTING_PUNCTUAL_LIGHT_SHADOW)
    return normalize(_LightPosition - positionWS);
    #else
    return _LightDirection;
    #endif
}

// Clamped to the near plane as URP's ShadowCasterPass does, so geometry behind it still casts.
float4 ShadowCasterWorldToClip(float3 positionWS)
{
    float4 positionCS = TransformWorldToHClip(positionWS);
    #if UNITY_REVERSED_Z
    positionCS.z = min(positionCS.z, UNITY_NEAR_CLIP_VALUE);
    #else
    positionCS.z = max(positionCS.z, UNITY_NEAR_CLIP_VALUE);
    #endif
    return positionCS;
}

// The terrain's vertices in the shadow map: URP's ApplyShadowBias, as its ShadowCasterPass does
// (depth bias _ShadowBias.x along the light, normal bias _ShadowBias.y along the normal, scaled by
// 1 - N.L so surfaces facing the light move least). TerrainVaryingsOf calls this instead of
// GT_ObjectToClip when the adapter defines GT_SHADOW_CASTER_NORMAL_BIAS.
#define GT_SHADOW_CASTER_NORMAL_BIAS 1
float4 GT_ObjectToShadowClip(float3 positionOS, float3 normalWS)
{
    float3 positionWS = GT_ObjectToWorld(positionOS);
    return ShadowCasterWorldToClip(ApplyShadowBias(positionWS, normalWS, ShadowCasterLightDirection(positionWS)));
}
#endif

float4 GT_ObjectToClip(float3 positionOS)
{
    float3 positionWS = GT_ObjectToWorld(positionOS);
#if defined(GT_PASS_SHADOWCASTER)
    // What the shadow pass's culling sees (tile bounding boxes, which have no normal): the light's
    // view with the depth bias only; the factors read the camera's (GT_TessObjectToClip). The
    // vertices get the normal bias too (GT_ObjectToShadowClip); it moves them by a few shadow-map
    // texels, well inside a tile.
    return ShadowCasterWorldToClip(positionWS + ShadowCasterLightDirection(positionWS) * _ShadowBias.x);
#else
    return TransformWorldToHClip(positionWS);
#endif
}

float3 GT_CameraPositionWS() { return GetCameraPositionWS(); }
float2 GT_ScreenSize() { return _ScreenParams.xy; }

void GT_MainLight(out float3 directionWS, out float3 color)
{
    Light light = GetMainLight();   // direction: towards the light
    directionWS = light.direction;
    color = light.color;
}

// The shadow coordinate is computed per pixel from the world position (TransformWorldToShadowCoord
// picks the cascade there), not interpolated from the vertices: a tessellated triangle can span
// two cascades. With the screen-space shadows feature it is the pixel's screen position.
// GetMainLight(shadowCoord, positionWS, shadowMask) also fades the shadow out towards the shadow
// distance; no baked shadow mask (1).
float GT_MainLightShadow(float3 positionWS, float4 positionSS, float3 normalWS)
{
#if defined(GT_RECEIVE_SHADOWS)
    #if defined(_MAIN_LIGHT_SHADOWS_SCREEN)
    float4 shadowCoord = float4(GetNormalizedScreenSpaceUV(positionSS), 0.0, 1.0);
    #else
    float4 shadowCoord = TransformWorldToShadowCoord(positionWS);
    #endif
    return GetMainLight(shadowCoord, positionWS, half4(1.0, 1.0, 1.0, 1.0)).shadowAttenuation;
#else
    return 1.0;
#endif
}

#if defined(GT_FOG)
// URP's per-pixel fog (InitializeInputDataFog: the view depth of the world position).
float3 GT_ApplyFog(float3 color, float3 positionWS)
{
    return MixFog(color, InitializeInputDataFog(float4(positionWS, 1.0), 0.0));
}
#endif

#if defined(GT_AMBIENT_OCCLUSION)
// URP's SSAO texture at this pixel: (indirect, direct) occlusion, 1 = none.
float2 GT_AmbientOcclusion(float4 positionSS)
{
    AmbientOcclusionFactor occlusion = GetScreenSpaceAmbientOcclusion(GetNormalizedScreenSpaceUV(positionSS));
    return float2(occlusion.indirectAmbientOcclusion, occlusion.directAmbientOcclusion);
}
#endif

// URP's DepthNormals convention (its own DepthNormalsPass): the world-space normal, normalized per
// pixel, in rgb; with _GBUFFER_NORMALS_OCT (deferred renderer, accurate G-buffer normals) the
// octahedral encoding remapped to [0, 1] and packed into three 8-bit channels.
float4 GT_EncodeDepthNormal(float3 normalWS)
{
#if defined(_GBUFFER_NORMALS_OCT)
    float3 n = normalize(normalWS);
    float2 octahedral = PackNormalOctQuadEncode(n);            // [-1, 1]^2
    float2 remapped = saturate(octahedral * 0.5 + 0.5);        // [0, 1]^2
    return float4(PackFloat2To888(remapped), 0.0);
#else
    return float4(NormalizeNormalPerPixel(normalWS), 0.0);
#endif
}

#if defined(GT_WRITE_RENDERING_LAYERS)
// The draw's rendering layer mask (unity_RenderingLayer, from RenderParams.renderingLayerMask), encoded
// for the target's format as URP's own passes write it (_RenderingLayerMaxInt, _RenderingLayerRcpMaxInt).
float4 GT_RenderingLayers()
{
    return float4(EncodeMeshRenderingLayer(GetMeshRenderingLayer()), 0.0, 0.0, 0.0);
}
#endif

// The stages, after the interface above: a pass of GregoryTerrain.shader includes its adapter only.
#include "TerrainStages.hlsl"

#endif // GT_URP_ADAPTER_INCLUDED
