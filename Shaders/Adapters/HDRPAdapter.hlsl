// High Definition Render Pipeline adapter (interface: see StandaloneAdapter.hlsl).
// Unity API names used: Common.hlsl (CBUFFER_START/CBUFFER_END), ShaderVariables.hlsl
// (TransformObjectToWorld, TransformObjectToWorldNormal, TransformWorldToHClip,
// TransformObjectToHClip, GetCameraRelativePositionWS, _WorldSpaceCameraPos, _ScreenSize),
// LightDefinition.cs.hlsl and ShaderVariablesLightLoop.hlsl (_DirectionalLightCount,
// _DirectionalLightDatas, DirectionalLightData.forward/.color).
// Not compiled off Unity (no Unity shader library here): checked by review only.
//
// HDRP renders camera-relative: its "world space" has the camera at the origin, and so does ours
// here (GT_CameraPositionWS is the camera in that space, i.e. 0 when camera-relative is on).
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

float3 GT_ObjectToWorld(float3 positionOS) { return TransformObjectToWorld(positionOS); }
float3 GT_ObjectToWorldNormal(float3 normalOS) { return TransformObjectToWorldNormal(normalOS); }
float4 GT_WorldToClip(float3 positionWS) { return TransformWorldToHClip(positionWS); }
float4 GT_ObjectToClip(float3 positionOS) { return TransformObjectToHClip(positionOS); }
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

#endif // GT_HDRP_ADAPTER_INCLUDED
