// MOCK (Tools~/rig/unity-mock/README.md): not HDRP's ShaderVariables.hlsl.
#ifndef GT_MOCK_HDRP_SHADER_VARIABLES
#define GT_MOCK_HDRP_SHADER_VARIABLES
float4x4 _ViewProjMatrix;
#define UNITY_MATRIX_VP _ViewProjMatrix
float4 _WorldSpaceCameraPos_Internal;
#define _WorldSpaceCameraPos _WorldSpaceCameraPos_Internal.xyz
float4 _ScreenSize;   // (w, h, 1/w, 1/h)
float4 TransformWorldToHClip(float3 positionRWS) { return mul(UNITY_MATRIX_VP, float4(positionRWS, 1.0)); }
float3 GetCameraRelativePositionWS(float3 positionWS) { return positionWS - _WorldSpaceCameraPos; }
#endif
