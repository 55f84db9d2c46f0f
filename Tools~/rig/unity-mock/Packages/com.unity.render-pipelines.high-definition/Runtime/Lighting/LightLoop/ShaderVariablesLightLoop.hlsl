// MOCK (Tools~/rig/unity-mock/README.md): not HDRP's light loop variables.
#ifndef GT_MOCK_HDRP_LIGHT_LOOP
#define GT_MOCK_HDRP_LIGHT_LOOP
uint _DirectionalLightCount;
StructuredBuffer<DirectionalLightData> _DirectionalLightDatas;
#endif
