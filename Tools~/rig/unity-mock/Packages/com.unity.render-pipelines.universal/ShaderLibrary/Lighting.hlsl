// MOCK (Tools~/rig/unity-mock/README.md): not URP's Lighting.hlsl / Shadows.hlsl.
#ifndef GT_MOCK_URP_LIGHTING
#define GT_MOCK_URP_LIGHTING
float4 _ShadowBias;   // Shadows.hlsl: x depth bias, y normal bias
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
#endif
