// MOCK (Tools~/rig/unity-mock/README.md): not HDRP's generated LightDefinition.cs.hlsl; only the
// fields the adapter reads, with their types.
#ifndef GT_MOCK_HDRP_LIGHT_DEFINITION
#define GT_MOCK_HDRP_LIGHT_DEFINITION
struct DirectionalLightData
{
    float3 positionRWS;
    uint lightLayers;
    float3 forward;
    float3 color;
};
#endif
