// MOCK (Tools~/rig/unity-mock/README.md): not URP's Core.hlsl. Only what URPAdapter.hlsl uses.
#ifndef GT_MOCK_URP_CORE
#define GT_MOCK_URP_CORE
#define CBUFFER_START(name) cbuffer name {
#define CBUFFER_END };
#define UNITY_REVERSED_Z 1
#define UNITY_NEAR_CLIP_VALUE (1.0)
float4x4 unity_MatrixVP;
#define UNITY_MATRIX_VP unity_MatrixVP
float3 _WorldSpaceCameraPos;
float4 _ScreenParams;
float4x4 GetWorldToHClipMatrix() { return UNITY_MATRIX_VP; }
float4 TransformWorldToHClip(float3 positionWS) { return mul(GetWorldToHClipMatrix(), float4(positionWS, 1.0)); }
float3 GetCameraPositionWS() { return _WorldSpaceCameraPos; }
#endif
