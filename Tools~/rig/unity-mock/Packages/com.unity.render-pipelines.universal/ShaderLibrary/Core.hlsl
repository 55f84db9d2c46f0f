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
// Core.hlsl
float3 NormalizeNormalPerPixel(float3 normalWS) { return normalize(normalWS); }
// SRP Core Packing.hlsl (included by Core.hlsl): octahedral encoding and 2 x 12 bits in 3 x 8.
float2 PackNormalOctQuadEncode(float3 n)
{
    n *= rcp(max(dot(abs(n), 1.0), 1e-6));
    float t = saturate(-n.z);
    return n.xy + float2(n.x >= 0.0 ? t : -t, n.y >= 0.0 ? t : -t);
}
float3 PackFloat2To888(float2 f)
{
    uint2 i = (uint2)(f * 4095.5);
    uint2 hi = i >> 8;
    uint2 lo = i & 255;
    return float3(lo, hi.x | (hi.y << 4)) / 255.0;
}
#endif
