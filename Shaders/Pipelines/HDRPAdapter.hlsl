// High Definition Render Pipeline adapter (interface: see StandaloneAdapter.hlsl).
// Unity API names used: Common.hlsl (CBUFFER_START/CBUFFER_END), ShaderVariables.hlsl
// (TransformWorldToHClip, GetCameraRelativePositionWS, _WorldSpaceCameraPos, _ScreenSize),
// LightDefinition.cs.hlsl and ShaderVariablesLightLoop.hlsl (_DirectionalLightCount,
// _DirectionalLightDatas, DirectionalLightData.forward/.color).
// Not compiled against HDRP off Unity: Tools~/rig/shaderlab.py compiles it against a labelled mock
// of these names (Tools~/rig/unity-mock) to catch syntax and type errors only.
//
// HDRP renders camera-relative: its "world space" has the camera at the origin, and so does ours
// here (GT_CameraPositionWS is the camera in that space, i.e. 0 when camera-relative is on).
// Object matrix: Graphics.RenderPrimitives gives the shader no object matrix, so
// GregoryTerrainRenderer sets _GtObjectToWorld / _GtWorldToObject (absolute world space, as
// Transform.localToWorldMatrix is); GT_ObjectToWorld makes the result camera-relative.
// Shadow bias: HDRP applies it as rasterizer depth bias from the light's shadow settings, so the
// ShadowCaster pass needs nothing here.
#ifndef GT_HDRP_ADAPTER_INCLUDED
#define GT_HDRP_ADAPTER_INCLUDED

#include "Packages/com.unity.render-pipelines.core/ShaderLibrary/Common.hlsl"
#include "Packages/com.unity.render-pipelines.high-definition/Runtime/ShaderLibrary/ShaderVariables.hlsl"
#include "Packages/com.unity.render-pipelines.high-definition/Runtime/Lighting/LightDefinition.cs.hlsl"
#include "Packages/com.unity.render-pipelines.high-definition/Runtime/Lighting/LightLoop/ShaderVariablesLightLoop.hlsl"

#define GT_ADAPTER_HDRP 1
#define GT_CBUFFER_START(name) CBUFFER_START(UnityPerMaterial)
#define GT_CBUFFER_END CBUFFER_END
#define GT_REGISTER(r)

// Set by GregoryTerrainRenderer (MaterialPropertyBlock), only when its Transform changes.
float4x4 _GtObjectToWorld;
float4x4 _GtWorldToObject;

float3 GT_ObjectToWorld(float3 positionOS)
{
    return GetCameraRelativePositionWS(mul(_GtObjectToWorld, float4(positionOS, 1.0)).xyz);
}
// Inverse transpose (a direction: no camera-relative shift).
float3 GT_ObjectToWorldNormal(float3 normalOS) { return normalize(mul(normalOS, (float3x3)_GtWorldToObject)); }
float4 GT_WorldToClip(float3 positionWS) { return TransformWorldToHClip(positionWS); }
float4 GT_ObjectToClip(float3 positionOS) { return TransformWorldToHClip(GT_ObjectToWorld(positionOS)); }
float3 GT_CameraPositionWS() { return GetCameraRelativePositionWS(_WorldSpaceCameraPos); }
float2 GT_ScreenSize() { return _ScreenSize.xy; }

// The first directional light (HDRP puts the sun first). forward is the direction the light
// travels, so the direction towards the light is its negation. No directional light: none.
void GT_MainLight(out float3 directionWS, out float3 color)
{
    directionWS = float3(0.0, 1.0, 0.0);
    color = float3(0.0, 0.0, 0.0);
    if (_DirectionalLightCount > 0)
    {
        DirectionalLightData light = _DirectionalLightDatas[0];
        directionWS = -light.forward.xyz;
        color = light.color;
    }
}

// Not received in HDRP: its directional shadows are read through the light loop's HDShadowContext
// (the shadow atlas, cascade data and filtering of the HDRP version), which a forward-only custom
// pass would have to include and set up as HDRP's Lit does. GT_RECEIVE_SHADOWS is not defined, so
// the shading never calls this; the terrain still casts shadows (ShadowCaster pass).
float GT_MainLightShadow(float3 positionWS, float4 positionSS) { return 1.0; }

// HDRP has no DepthNormals pass for this material (its normal buffer is written by the
// DepthForwardOnly pass of its Lit shaders only); defined for the interface, unused.
float4 GT_EncodeDepthNormal(float3 normalWS) { return float4(normalize(normalWS), 0.0); }

#endif // GT_HDRP_ADAPTER_INCLUDED
