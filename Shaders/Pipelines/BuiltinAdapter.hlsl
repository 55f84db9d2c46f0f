// Built-in render pipeline adapter (interface: see StandaloneAdapter.hlsl).
// Unity API names used: HLSLSupport.cginc (CBUFFER_START/CBUFFER_END), UnityCG.cginc
// (UnityWorldToClipPos, UnityWorldSpaceLightDir, UnityApplyLinearShadowBias, _WorldSpaceCameraPos,
// _ScreenParams, _WorldSpaceLightPos0, unity_LightShadowBias, unity_WorldToShadow), UnityLightingCommon.cginc (_LightColor0) and
// AutoLight.cginc (unitySampleShadow, the SHADOWS_SCREEN keyword). Use it in a pass with
// Tags { "LightMode" = "ForwardBase" } so Unity fills the main directional light.
// Compiled against the real 2022.3 CGIncludes off Unity by the rig (Tools~/rig/shaderlab.py).
//
// Object matrix: _GtObjectToWorld / _GtWorldToObject (UnityAdapterCommon.hlsl says why), so never
// UnityObjectToClipPos or UnityObjectToWorldNormal.
// Shadows: the ShadowCaster pass declares multi_compile_shadowcaster and the caster does per variant what
// UnityCG.cginc's TRANSFER_SHADOW_CASTER_NOPOS / SHADOW_CASTER_FRAGMENT do (UnityCG.cginc:962-982):
//   SHADOWS_DEPTH (directional, spot) and SHADOWS_CUBE (point) get the normal offset, then
//   UnityApplyLinearShadowBias, which leaves a depth cube map's bias out (UnityCG.cginc:942): the receiver
//   subtracts it from the distance (UnitySampleShadowmap, UnityShadowLibrary.cginc:113). Unity's colour-distance
//   cube caster (no SHADOWS_CUBE_IN_DEPTH_TEX, UnityCG.cginc:48-51) is not written: every API whose list there
//   lacks it is one that runs no target 4.5 SubShader (GLES2).
#ifndef GT_BUILTIN_ADAPTER_INCLUDED
#define GT_BUILTIN_ADAPTER_INCLUDED

#include "HLSLSupport.cginc"
#include "UnityCG.cginc"
#include "UnityLightingCommon.cginc"
#include "AutoLight.cginc"

#define GT_ADAPTER_BUILTIN 1

// Receive the main directional light's shadow in ForwardBase when Unity draws one (SHADOWS_SCREEN:
// the pass declares `multi_compile _ SHADOWS_SCREEN` rather than multi_compile_fwdbase, whose
// lightmap and vertex-light variants the terrain does not use).
#if defined(GT_PASS_FORWARD) && defined(SHADOWS_SCREEN)
    #define GT_RECEIVE_SHADOWS 1
#endif
#if defined(GT_PASS_FORWARD) && (defined(FOG_LINEAR) || defined(FOG_EXP) || defined(FOG_EXP2))
    #define GT_FOG 1
#endif
#if defined(GT_RECEIVE_SHADOWS) || defined(GT_FOG)
    #define GT_VARYINGS_POSITION_WS 1   // read by shadows' mobile path and the fog
#endif
// Material constants, the object matrices, normals, the editor's selection passes.
#include "UnityAdapterCommon.hlsl"

float3 GT_ObjectToWorld(float3 positionOS) { return mul(_GtObjectToWorld, float4(positionOS, 1.0)).xyz; }
float4 GT_WorldToClip(float3 positionWS) { return UnityWorldToClipPos(positionWS); }

float4 GT_ObjectToClip(float3 positionOS)
{
    float4 positionCS = UnityWorldToClipPos(GT_ObjectToWorld(positionOS));
#if defined(GT_PASS_SHADOWCASTER)
    // The light's depth bias (unity_LightShadowBias.x) in clip space, clamped to the near plane.
    positionCS = UnityApplyLinearShadowBias(positionCS);
#endif
    return positionCS;
}

#if defined(GT_PASS_SHADOWCASTER)
// Built-in's normal offset (UnityClipSpaceShadowCasterPos, in world space: it reads unity_ObjectToWorld),
// then the depth bias. Only where z != 0, as Unity: the camera depth pass may have no light (NaN).
#define GT_SHADOW_CASTER_NORMAL_BIAS 1
float4 GT_ObjectToShadowClip(float3 positionOS, float3 normalWS)
{
    float3 positionWS = GT_ObjectToWorld(positionOS);
    if (unity_LightShadowBias.z != 0.0)
    {
        float c = dot(normalWS, normalize(UnityWorldSpaceLightDir(positionWS)));
        positionWS -= normalWS * (unity_LightShadowBias.z * sqrt(saturate(1.0 - c * c)));
    }
    return UnityApplyLinearShadowBias(UnityWorldToClipPos(positionWS));
}
#endif

float3 GT_CameraPositionWS() { return _WorldSpaceCameraPos; }
float2 GT_ScreenSize() { return _ScreenParams.xy; }

// In ForwardBase, _WorldSpaceLightPos0.xyz is the direction towards the main directional light
// (w = 0) and _LightColor0 its colour times intensity.
void GT_MainLight(out float3 directionWS, out float3 color)
{
    directionWS = normalize(_WorldSpaceLightPos0.xyz);
    color = _LightColor0.rgb;
}

// The SHADOW_COORDS / TRANSFER_SHADOW macros expect a v2f with a `pos` member and the vertex in
// unity_ObjectToWorld space, which the domain stage does not have; the coordinate they would pass
// on is rebuilt here instead. Desktop: Unity's screen-space shadow texture at this pixel (the
// fragment's SV_Position over the screen size; single-pass stereo not handled). Without screen-space
// shadows (UNITY_NO_SCREENSPACE_SHADOWS, mobile): the shadow map through unity_WorldToShadow[0]
// (one cascade there).
float GT_MainLightShadow(float3 positionWS, float4 positionSS, float3 normalWS)
{
#if defined(GT_RECEIVE_SHADOWS)
    #if defined(UNITY_NO_SCREENSPACE_SHADOWS)
    float4 shadowCoord = mul(unity_WorldToShadow[0], float4(positionWS, 1.0));
    #else
    float4 shadowCoord = float4(positionSS.xy / _ScreenParams.xy, 0.0, 1.0);
    #endif
    return unitySampleShadow(shadowCoord);
#else
    return 1.0;
#endif
}

#if defined(GT_FOG)
// Built-in's fog (UNITY_TRANSFER_FOG + UNITY_APPLY_FOG): the factor from the clip-space depth, per pixel as on
// desktop, lerped towards unity_FogColor (ForwardBase's colour; ForwardAdd would use black).
float3 GT_ApplyFog(float3 color, float3 positionWS)
{
    UNITY_CALC_FOG_FACTOR(UnityWorldToClipPos(positionWS).z);
    float4 fogged = float4(color, 1.0);
    UNITY_FOG_LERP_COLOR(fogged, unity_FogColor, unityFogFactor);
    return fogged.rgb;
}
#endif

// The stages, after the interface above: a pass of GregoryTerrain.shader includes its adapter only.
#include "TerrainStages.hlsl"

#endif // GT_BUILTIN_ADAPTER_INCLUDED
