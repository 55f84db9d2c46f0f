// Universal Render Pipeline adapter (interface: see StandaloneAdapter.hlsl).
// Unity API names used: Core.hlsl (TransformWorldToHClip, GetCameraPositionWS, _ScreenParams,
// CBUFFER_START/CBUFFER_END, UNITY_REVERSED_Z, UNITY_NEAR_CLIP_VALUE, NormalizeNormalPerPixel and,
// from SRP Core's Packing.hlsl, PackNormalOctQuadEncode / PackFloat2To888), Lighting.hlsl
// (GetMainLight, Light.direction/.color/.shadowAttenuation) and Shadows.hlsl, which Lighting.hlsl
// includes (_ShadowBias, TransformWorldToShadowCoord, the _MAIN_LIGHT_SHADOWS* keywords).
// Not compiled against URP off Unity: Tools~/rig/shaderlab.py compiles it against a labelled mock
// of these names (Tools~/rig/unity-mock) to catch syntax and type errors only.
//
// Object matrix: Graphics.RenderPrimitives gives the shader no object matrix (UNITY_MATRIX_M /
// unity_ObjectToWorld are not the renderer's Transform), so GregoryTerrainRenderer sets
// _GtObjectToWorld and _GtWorldToObject and every object-space transform here uses them
// (internals.md, "Unity side").
#ifndef GT_URP_ADAPTER_INCLUDED
#define GT_URP_ADAPTER_INCLUDED

#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Lighting.hlsl"

#define GT_ADAPTER_URP 1

// Receive the main light's shadows in the forward pass when URP draws them: the forward pass
// declares `multi_compile _ _MAIN_LIGHT_SHADOWS _MAIN_LIGHT_SHADOWS_CASCADE` (and
// `multi_compile_fragment _ _SHADOWS_SOFT`). _MAIN_LIGHT_SHADOWS_SCREEN (the screen-space shadows
// renderer feature) is not declared, so with that feature the terrain is drawn unshadowed.
#if defined(GT_PASS_FORWARD) && (defined(_MAIN_LIGHT_SHADOWS) || defined(_MAIN_LIGHT_SHADOWS_CASCADE))
    #define GT_RECEIVE_SHADOWS 1
#endif
// All material constants in UnityPerMaterial, so the SRP Batcher layout stays the same for every
// material of this shader.
#define GT_CBUFFER_START(name) CBUFFER_START(UnityPerMaterial)
#define GT_CBUFFER_END CBUFFER_END
#define GT_REGISTER(r)

// Set by GregoryTerrainRenderer (MaterialPropertyBlock), only when its Transform changes.
float4x4 _GtObjectToWorld;
float4x4 _GtWorldToObject;

#if defined(GT_PASS_SHADOWCASTER)
// Set by URP for the light whose shadow map is being drawn (directional: towards the light).
float3 _LightDirection;
#endif

float3 GT_ObjectToWorld(float3 positionOS) { return mul(_GtObjectToWorld, float4(positionOS, 1.0)).xyz; }

// Normals go through the inverse transpose: n^T * WorldToObject (as URP's own
// TransformObjectToWorldNormal does with UNITY_MATRIX_I_M).
float3 GT_ObjectToWorldNormal(float3 normalOS) { return normalize(mul(normalOS, (float3x3)_GtWorldToObject)); }

float4 GT_WorldToClip(float3 positionWS) { return TransformWorldToHClip(positionWS); }

float4 GT_ObjectToClip(float3 positionOS)
{
    float3 positionWS = GT_ObjectToWorld(positionOS);
#if defined(GT_PASS_SHADOWCASTER)
    // URP's depth bias along the light (the x of _ShadowBias). The normal bias (y) needs the
    // surface normal, which a clip-space transform does not get; the tile corners used for the
    // tessellation factors have none either. Then keep the caster in front of the near plane, as
    // URP's ShadowCasterPass does, so geometry behind it still casts.
    positionWS += _LightDirection * _ShadowBias.x;
    float4 positionCS = TransformWorldToHClip(positionWS);
    #if UNITY_REVERSED_Z
    positionCS.z = min(positionCS.z, positionCS.w * UNITY_NEAR_CLIP_VALUE);
    #else
    positionCS.z = max(positionCS.z, positionCS.w * UNITY_NEAR_CLIP_VALUE);
    #endif
    return positionCS;
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
// two cascades. GetMainLight(shadowCoord, positionWS, shadowMask) also fades the shadow out towards
// the shadow distance; no baked shadow mask (1).
float GT_MainLightShadow(float3 positionWS, float4 positionSS)
{
#if defined(GT_RECEIVE_SHADOWS)
    float4 shadowCoord = TransformWorldToShadowCoord(positionWS);
    return GetMainLight(shadowCoord, positionWS, half4(1.0, 1.0, 1.0, 1.0)).shadowAttenuation;
#else
    return 1.0;
#endif
}

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

#endif // GT_URP_ADAPTER_INCLUDED
