// Universal Render Pipeline adapter (interface: see StandaloneAdapter.hlsl).
// Unity API names used: Core.hlsl (TransformObjectToWorld, TransformObjectToWorldNormal,
// TransformWorldToHClip, TransformObjectToHClip, GetCameraPositionWS, _ScreenParams,
// CBUFFER_START/CBUFFER_END) and Lighting.hlsl (GetMainLight, Light.direction, Light.color).
// Not compiled off Unity (no Unity shader library here): checked by review only.
#ifndef GT_URP_ADAPTER_INCLUDED
#define GT_URP_ADAPTER_INCLUDED

#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Lighting.hlsl"

#define GT_ADAPTER_URP 1
// All material constants in UnityPerMaterial, so the SRP Batcher keeps the terrain batched.
#define GT_CBUFFER_START(name) CBUFFER_START(UnityPerMaterial)
#define GT_CBUFFER_END CBUFFER_END
#define GT_REGISTER(r)

float3 GT_ObjectToWorld(float3 positionOS) { return TransformObjectToWorld(positionOS); }
float3 GT_ObjectToWorldNormal(float3 normalOS) { return TransformObjectToWorldNormal(normalOS); }
float4 GT_WorldToClip(float3 positionWS) { return TransformWorldToHClip(positionWS); }
float4 GT_ObjectToClip(float3 positionOS) { return TransformObjectToHClip(positionOS); }
float3 GT_CameraPositionWS() { return GetCameraPositionWS(); }
float2 GT_ScreenSize() { return _ScreenParams.xy; }

void GT_MainLight(out float3 directionWS, out float3 color)
{
    Light light = GetMainLight();   // direction: towards the light
    directionWS = light.direction;
    color = light.color;
}

#endif // GT_URP_ADAPTER_INCLUDED
