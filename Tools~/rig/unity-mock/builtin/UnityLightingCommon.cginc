// MOCK (Tools~/rig/unity-mock/README.md): not Unity's UnityLightingCommon.cginc.
#ifndef GT_MOCK_UNITY_LIGHTING_COMMON
#define GT_MOCK_UNITY_LIGHTING_COMMON
float4 _LightColor0;   // fixed4 in Unity; fixed is float off the mobile compilers
#endif
