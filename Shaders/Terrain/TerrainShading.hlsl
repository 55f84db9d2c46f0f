// Fragment colour of the terrain: Lambert lighting from the adapter's main light, the height
// colour of eq. 14-15 (GT_HEIGHT_COLOR), snow blended by depth (GT_SNOW), what the pipeline adds
// when its adapter says so (received shadows GT_RECEIVE_SHADOWS, screen-space occlusion
// GT_AMBIENT_OCCLUSION, fog GT_FOG, pre-exposure GT_PRE_EXPOSE, sky light GT_AMBIENT_PROBE; none of
// them in the off-Unity rig)
// and the debug views (each replaces the lit colour):
//   GT_DEBUG_NORMALS      world normal as RGB (n * 0.5 + 0.5)
//   GT_DEBUG_PATCH_ID     one flat colour per Gregory patch
//   GT_DEBUG_TESS_FACTOR  tessellation factor, blue (1) to red (maxFactor)
#ifndef GT_TERRAIN_SHADING_INCLUDED
#define GT_TERRAIN_SHADING_INCLUDED

#include "TerrainVertex.hlsl"

static const float3 GT_DEFAULT_ALBEDO = float3(0.55, 0.55, 0.5);
// Light from the sky on faces turned away from the main light, so slopes never go black (against a
// main light of colour 1; GT_AMBIENT_PROBE: the pipeline's own).
static const float GT_AMBIENT = 0.2;

// A stable, well-spread colour per patch index (integer hash to three bytes).
float3 PatchIdColor(uint patch)
{
    uint h = patch * 0x9E3779B1u;
    h ^= h >> 15;
    h *= 0x85EBCA77u;
    h ^= h >> 13;
    return float3(h & 0xFFu, (h >> 8) & 0xFFu, (h >> 16) & 0xFFu) * (1.0 / 255.0);
}

float3 TessFactorColor(float factor)
{
    float t = saturate((factor - 1.0) / max(MaxTessFactor() - 1.0, 1.0));
    return lerp(float3(0.1, 0.2, 1.0), float3(1.0, 0.15, 0.1), t);
}

#if defined(GT_SNOW)
// The snow variant wraps the ground albedo below (compiled as TerrainGroundAlbedo) with the snow
// blend; the text of the snow-off build stays exactly what it was, and so does its SPIR-V.
    #define TerrainAlbedo TerrainGroundAlbedo
#endif
float3 TerrainAlbedo(TerrainVaryings i)
{
#if defined(GT_HEIGHT_COLOR)
    // Eq. 15 of the weight s the vertex stage computed (eq. 14, TerrainHeightWeight).
    return HeightColorOfWeight(VaryingsHeightWeight(i), HeightColorLow(), HeightColorHigh());
#else
    return GT_DEFAULT_ALBEDO;
#endif
}
#if defined(GT_SNOW)
    #undef TerrainAlbedo
// The ground under snow, blended by the vertex's snow depth.
float3 TerrainAlbedo(TerrainVaryings i)
{
    return lerp(TerrainGroundAlbedo(i), GT_SNOW_ALBEDO, SnowMapCoverage(i.snowDepth, SnowDepthCap()));
}
#endif

float4 TerrainFragmentColor(TerrainVaryings i)
{
    float3 normalWS = normalize(VaryingsNormalWS(i));
#if defined(GT_DEBUG_NORMALS)
    return float4(normalWS * 0.5 + 0.5, 1.0);
#elif defined(GT_DEBUG_PATCH_ID)
    return float4(PatchIdColor(i.patch), 1.0);
#elif defined(GT_DEBUG_TESS_FACTOR)
    return float4(TessFactorColor(i.tessFactor), 1.0);
#else
    float3 lightDirectionWS, lightColor;
    GT_MainLight(lightDirectionWS, lightColor);
    float lambert = saturate(dot(normalWS, lightDirectionWS));
    #if defined(GT_AMBIENT_PROBE)
    float3 ambient = GT_AmbientProbe(normalWS);
    #else
    float ambient = GT_AMBIENT;
    #endif
    #if defined(GT_RECEIVE_SHADOWS)
    // 1 = lit, 0 = in the main light's shadow; the ambient term stays.
    lambert *= GT_MainLightShadow(i.positionWS, i.positionCS, normalWS);
    #endif
    #if defined(GT_AMBIENT_OCCLUSION)
    // The pipeline's screen-space occlusion: (indirect, direct), 1 = none.
    float2 occlusion = GT_AmbientOcclusion(i.positionCS);
    ambient *= occlusion.x;
    lambert *= occlusion.y;
    #endif
    float3 color = TerrainAlbedo(i) * (ambient + lightColor * lambert);
    #if defined(GT_FOG)
    color = GT_ApplyFog(color, i.positionWS);
    #endif
    #if defined(GT_PRE_EXPOSE)
    // Lit colour in the pipeline's exposed range (the debug views above are shown as they are).
    color *= GT_ExposureMultiplier();
    #endif
    return float4(color, 1.0);
#endif
}

// The depth-normals output (URP's DepthNormals pass, HDRP's normal buffer): the world normal as
// the pipeline packs it (GT_EncodeDepthNormal, adapter). No lighting, no albedo.
#if defined(GT_PASS_DEPTH_NORMALS)
float4 TerrainDepthNormal(TerrainVaryings i)
{
    return GT_EncodeDepthNormal(VaryingsNormalWS(i));
}
#endif

#endif // GT_TERRAIN_SHADING_INCLUDED
