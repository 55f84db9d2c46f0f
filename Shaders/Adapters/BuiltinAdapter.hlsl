// Built-in render pipeline adapter (interface: see StandaloneAdapter.hlsl).
// Unity API names used: HLSLSupport.cginc (CBUFFER_START/CBUFFER_END), UnityCG.cginc
// (UnityObjectToClipPos, UnityWorldToClipPos, UnityObjectToWorldNormal, unity_ObjectToWorld,
// _WorldSpaceCameraPos, _ScreenParams, _WorldSpaceLightPos0) and UnityLightingCommon.cginc
// (_LightColor0). Use it in a pass with Tags { "LightMode" = "ForwardBase" } so Unity fills the
// main directional light. Not compiled off Unity (no Unity shader library here): checked by review only.
#ifndef GT_BUILTIN_ADAPTER_INCLUDED
#define GT_BUILTIN_ADAPTER_INCLUDED

#include "HLSLSupport.cginc"
#include "UnityCG.cginc"
#include "UnityLightingCommon.cginc"

#define GT_ADAPTER_BUILTIN 1
#define GT_CBUFFER_START(name) CBUFFER_START(UnityPerMaterial)
#define GT_CBUFFER_END CBUFFER_END
#define GT_REGISTER(r)

float3 GT_ObjectToWorld(float3 positionOS) { return mul(unity_ObjectToWorld, float4(positionOS, 1.0)).xyz; }
float3 GT_ObjectToWorldNormal(float3 normalOS) { return UnityObjectToWorldNormal(normalOS); }
float4 GT_WorldToClip(float3 positionWS) { return UnityWorldToClipPos(positionWS); }
float4 GT_ObjectToClip(float3 positionOS) { return UnityObjectToClipPos(positionOS); }
float3 GT_CameraPositionWS() { return _WorldSpaceCameraPos; }
float2 GT_ScreenSize() { return _ScreenParams.xy; }

// In ForwardBase, _WorldSpaceLightPos0.xyz is the direction towards the main directional light
// (w = 0) and _LightColor0 its colour times intensity.
void GT_MainLight(out float3 directionWS, out float3 color)
{
    directionWS = normalize(_WorldSpaceLightPos0.xyz);
    color = _LightColor0.rgb;
}

#endif // GT_BUILTIN_ADAPTER_INCLUDED
