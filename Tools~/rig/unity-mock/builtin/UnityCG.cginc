// MOCK (Tools~/rig/unity-mock/README.md): not Unity's UnityCG.cginc. Only what the adapter uses,
// with the documented signatures; the bodies are minimal stand-ins.
#ifndef GT_MOCK_UNITY_CG
#define GT_MOCK_UNITY_CG
// UnityShaderVariables.cginc (included by UnityCG.cginc)
float4x4 unity_MatrixVP;
#define UNITY_MATRIX_VP unity_MatrixVP
float3 _WorldSpaceCameraPos;
float4 _ScreenParams;
float4 _WorldSpaceLightPos0;
float4 unity_LightShadowBias;
float4x4 unity_WorldToShadow[4];
#define UNITY_REVERSED_Z 1
#define UNITY_NEAR_CLIP_VALUE (1.0)
// UnityCG.cginc
inline float4 UnityWorldToClipPos(in float3 pos) { return mul(UNITY_MATRIX_VP, float4(pos, 1.0)); }
float4 UnityApplyLinearShadowBias(float4 clipPos)
{
    clipPos.z += saturate(unity_LightShadowBias.x / clipPos.w);
    clipPos.z = min(clipPos.z, clipPos.w * UNITY_NEAR_CLIP_VALUE);
    return clipPos;
}
#endif
