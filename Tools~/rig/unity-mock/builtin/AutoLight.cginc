// MOCK (Tools~/rig/unity-mock/README.md): not Unity's AutoLight.cginc. Only what the adapter uses,
// with the documented signature; the body is a minimal stand-in (no shadow-map sampling).
#ifndef GT_MOCK_AUTO_LIGHT
#define GT_MOCK_AUTO_LIGHT
#if defined(SHADOWS_SCREEN)
// UnityShadowLibrary.cginc / AutoLight.cginc: screen-space shadow texture (desktop) or the shadow
// map (UNITY_NO_SCREENSPACE_SHADOWS); both sampled by unitySampleShadow.
Texture2D _ShadowMapTexture;
SamplerState sampler_ShadowMapTexture;
float4 unitySampleShadow(float4 shadowCoord)
{
    return _ShadowMapTexture.Sample(sampler_ShadowMapTexture, shadowCoord.xy / shadowCoord.w).rrrr;
}
#endif
#endif
