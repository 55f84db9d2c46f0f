// High Definition Render Pipeline adapter (interface: see StandaloneAdapter.hlsl).
// Unity API names used: Common.hlsl (CBUFFER_START/CBUFFER_END), ShaderVariables.hlsl, which also
// brings the light loop's globals (TransformWorldToHClip, GetCameraRelativePositionWS,
// _WorldSpaceCameraPos, _ScreenSize, GetCurrentExposureMultiplier, _DirectionalLightCount,
// _DirectionalShadowIndex, _DirectionalLightDatas, DirectionalLightData, unity_SelectionID),
// LightLoop/HDShadow.hlsl (HDShadowContext, InitShadowContext, GetDirectionalShadowAttenuation),
// Material/NormalBuffer.hlsl (NormalData, EncodeIntoNormalBuffer) and SphericalHarmonics.hlsl.
// Compiled against HDRP 14's real includes off Unity by the rig (Tools~/rig/shaderlab.py).
//
// HDRP renders camera-relative: its "world space" has the camera at the origin, and so does ours
// here (GT_CameraPositionWS is the camera in that space, i.e. 0 when camera-relative is on).
// Object matrix: _GtObjectToWorld (UnityAdapterCommon.hlsl) is absolute world space;
// GT_ObjectToWorld makes the result camera-relative.
// Shadow bias: HDRP applies it as rasterizer depth bias from the light's shadow settings, so the
// ShadowCaster pass needs nothing here.
#ifndef GT_HDRP_ADAPTER_INCLUDED
#define GT_HDRP_ADAPTER_INCLUDED

#include "Packages/com.unity.render-pipelines.core/ShaderLibrary/Common.hlsl"
// HDRP's includes read the pass kind (SHADERPASS), as in every HDRP shader: which camera position
// and projection test to use (the shadow pass's camera is the light's).
#include "Packages/com.unity.render-pipelines.high-definition/Runtime/RenderPipeline/ShaderPass/ShaderPass.cs.hlsl"
#if defined(GT_PASS_SHADOWCASTER)
    #define SHADERPASS SHADERPASS_SHADOWS
#elif defined(GT_PASS_FORWARD)
    #define SHADERPASS SHADERPASS_FORWARD
#else
    #define SHADERPASS SHADERPASS_DEPTH_ONLY   // depth prepass, and the editor's passes as HDRP's own
#endif
// ShaderVariables.hlsl includes LightLoop/ShaderVariablesLightLoop.hlsl itself (that file has no
// include guard: including it again declares every light-loop global twice).
#include "Packages/com.unity.render-pipelines.high-definition/Runtime/ShaderLibrary/ShaderVariables.hlsl"
#if defined(GT_PASS_FORWARD) && defined(SHADER_STAGE_FRAGMENT)
    // The filter quality is one of the pass's SHADOW_* keywords; HDRP's shadow code has no default
    // for the fragment stage, so a compile without one (never one of Unity's variants) gets HDRP's
    // default for the other stages, medium.
    #if !defined(SHADOW_LOW) && !defined(SHADOW_MEDIUM) && !defined(SHADOW_HIGH)
        #define SHADOW_MEDIUM
    #endif
    #if !defined(AREA_SHADOW_LOW) && !defined(AREA_SHADOW_MEDIUM) && !defined(AREA_SHADOW_HIGH)
        #define AREA_SHADOW_MEDIUM   // unused here: HDShadowAlgorithms.hlsl wants one
    #endif
    #include "Packages/com.unity.render-pipelines.high-definition/Runtime/Lighting/LightLoop/HDShadow.hlsl"
#endif
#if defined(GT_PASS_FORWARD)
    #include "Packages/com.unity.render-pipelines.core/ShaderLibrary/SphericalHarmonics.hlsl"
#endif
#if defined(GT_PASS_DEPTH_NORMALS)
    #include "Packages/com.unity.render-pipelines.high-definition/Runtime/Material/NormalBuffer.hlsl"
#endif

#define GT_ADAPTER_HDRP 1

// The forward pass receives the main directional light's shadow, through HDRP's own shadow code
// (the cascades, filtering and fade of the HDRP asset), and pre-exposes its lit colour as every
// HDRP lit material does. Fog on opaque surfaces is HDRP's own full-screen pass, not the material's.
#if defined(GT_PASS_FORWARD)
    #define GT_RECEIVE_SHADOWS 1
    #define GT_VARYINGS_POSITION_WS 1
    #define GT_PRE_EXPOSE 1
    #define GT_AMBIENT_PROBE 1
#endif
// The depth prepass also writes the normal buffer (SSAO, SSR, contact shadows read it); with MSAA
// HDRP binds the depth as a colour target first (WRITE_MSAA_DEPTH, HDRP's keyword).
#if defined(GT_PASS_DEPTH_NORMALS) && defined(WRITE_MSAA_DEPTH)
    #define GT_WRITE_DEPTH_COLOR 1
#endif
// Material constants, the object matrices, normals, the editor's selection passes.
#include "UnityAdapterCommon.hlsl"

// The translation is made camera-relative before the object position is added: both it and the
// camera may be kilometres from the world origin, and mul(M, p) would round the sum there (4 mm at
// 50 km) before the subtraction could cancel it. (M t - C) is the difference of two large floats,
// then the small rotated position joins it.
float3 GT_ObjectToWorld(float3 positionOS)
{
    // Rows' w: the translation column (a matrix swizzle such as _m03_m13_m23 miscompiles in glslang).
    float3 translation = GetCameraRelativePositionWS(float3(_GtObjectToWorld[0].w, _GtObjectToWorld[1].w, _GtObjectToWorld[2].w));
    return mul((float3x3)_GtObjectToWorld, positionOS) + translation;
}
float4 GT_WorldToClip(float3 positionWS) { return TransformWorldToHClip(positionWS); }
float4 GT_ObjectToClip(float3 positionOS) { return TransformWorldToHClip(GT_ObjectToWorld(positionOS)); }
float3 GT_CameraPositionWS() { return GetCameraRelativePositionWS(_WorldSpaceCameraPos); }
float2 GT_ScreenSize() { return _ScreenSize.xy; }

// The camera's view, also in a shadow pass: HDRP's shadow atlas replaces only the view matrices
// (_ViewProjMatrix, ...), as its own tessellation assumes (TessellationShare.hlsl).
float4 GT_TessObjectToClip(float3 positionOS) { return mul(_CameraViewProjMatrix, float4(GT_ObjectToWorld(positionOS), 1.0)); }
float2 GT_TessScreenSize() { return _ScreenSize.xy; }

// HDRP has no "main light"; the sun is the directional light that casts the cascaded shadows
// (_DirectionalShadowIndex, -1 when none does). Without one: the first directional light that
// lights diffuse surfaces (diffuseDimmer > 0). None: -1.
int MainDirectionalLightIndex()
{
    if (_DirectionalShadowIndex >= 0)
        return _DirectionalShadowIndex;
    for (uint k = 0; k < _DirectionalLightCount; k++)
    {
        if (_DirectionalLightDatas[k].diffuseDimmer > 0.0)
            return (int)k;
    }
    return -1;
}

// forward is the direction the light travels, so the direction towards the light is its negation.
// The colour: what a white Lambertian surface facing it reflects, lux * Lambert() (1/pi), as Lit.
void GT_MainLight(out float3 directionWS, out float3 color)
{
    directionWS = float3(0.0, 1.0, 0.0);
    color = float3(0.0, 0.0, 0.0);
    int index = MainDirectionalLightIndex();
    if (index >= 0)
    {
        DirectionalLightData light = _DirectionalLightDatas[index];
        directionWS = -light.forward;
        color = light.color * (light.diffuseDimmer * INV_PI);
    }
}

#if defined(GT_PASS_FORWARD)
// HDRP's cascaded directional shadow at this pixel, as its light loop reads it
// (GetDirectionalShadowAttenuation: cascade choice, the asset's filtering, normal bias), faded by
// the light's shadow dimmer. positionWS is camera-relative; the normal biases the lookup and
// flips towards the light, so the geometric normal of the pixel is enough. Only the light that
// casts the cascades has a shadow here.
float GT_MainLightShadow(float3 positionWS, float4 positionSS, float3 normalWS)
{
    #if !defined(SHADER_STAGE_FRAGMENT)
    return 1.0;   // only the fragment stage reads shadows (HDShadow.hlsl is included there only)
    #else
    int index = MainDirectionalLightIndex();
    if (index < 0 || index != _DirectionalShadowIndex)
        return 1.0;
    DirectionalLightData light = _DirectionalLightDatas[index];
    if (light.shadowIndex < 0 || light.shadowDimmer <= 0.0)
        return 1.0;
    HDShadowContext context = InitShadowContext();
    float shadow = GetDirectionalShadowAttenuation(context, positionSS.xy, positionWS, normalWS, light.shadowIndex, -light.forward);
    return lerp(1.0, shadow, light.shadowDimmer);
    #endif
}
#endif

// The pre-exposure of HDRP's lit colours (its exposure texture), so the terrain matches an
// exposed scene: light intensities are physical (lux), the exposure brings them to display range.
float GT_ExposureMultiplier() { return GetCurrentExposureMultiplier(); }

#if defined(GT_PASS_FORWARD)
// The sky's light as HDRP's light loop gives it without lightmaps (in lux / pi, as the sun's).
float3 GT_AmbientProbe(float3 normalWS)
{
    return SampleSH9(_AmbientProbeData, normalWS) * GetIndirectDiffuseMultiplier(GetMeshRenderingLightLayer());
}
#endif

#if defined(GT_PASS_DEPTH_NORMALS)
// HDRP's normal buffer (EncodeIntoNormalBuffer: octahedral normal, perceptual roughness). The
// terrain is diffuse only: roughness 1, so SSR never traces it (its stencil bit is clear too).
float4 GT_EncodeDepthNormal(float3 normalWS)
{
    NormalData normalData;
    normalData.normalWS = normalize(normalWS);
    normalData.perceptualRoughness = 1.0;
    float4 encoded;
    EncodeIntoNormalBuffer(normalData, encoded);
    return encoded;
}
#endif

// The stages, after the interface above: a pass of GregoryTerrain.shader includes its adapter only.
#include "TerrainStages.hlsl"

#endif // GT_HDRP_ADAPTER_INCLUDED
