// MOCK (Tools~/rig/unity-mock/README.md): not URP's Lighting.hlsl / Shadows.hlsl.
#ifndef GT_MOCK_URP_LIGHTING
#define GT_MOCK_URP_LIGHTING
float4 _ShadowBias;   // Shadows.hlsl: x depth bias, y normal bias
float4x4 _MainLightWorldToShadow[5];   // Shadows.hlsl (the cascade choice is left out here)
float4 TransformWorldToShadowCoord(float3 positionWS)
{
    return float4(mul(_MainLightWorldToShadow[0], float4(positionWS, 1.0)).xyz, 0.0);
}
float4 _MainLightPosition;
float4 _MainLightColor;
struct Light
{
    half3 direction;
    half3 color;
    float distanceAttenuation;
    half shadowAttenuation;
    uint layerMask;
};
Light GetMainLight()
{
    Light light;
    light.direction = (half3)_MainLightPosition.xyz;
    light.color = (half3)_MainLightColor.rgb;
    light.distanceAttenuation = 1.0;
    light.shadowAttenuation = 1.0;
    light.layerMask = 0xFFFFFFFFu;
    return light;
}
// RealtimeLights.hlsl overload with shadows (URP 12+): here the shadow term is a stand-in that
// reads its inputs, not a shadow-map lookup.
Light GetMainLight(float4 shadowCoord, float3 positionWS, half4 shadowMask)
{
    Light light = GetMainLight();
    light.shadowAttenuation = (half)saturate(shadowCoord.z + shadowMask.x + positionWS.y * 0.0);
    return light;
}
#endif
