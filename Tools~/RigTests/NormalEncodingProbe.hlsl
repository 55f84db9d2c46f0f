// Test kernel (NormalEncodingGpuTests): Shaders/Library/NormalEncoding.hlsl on the GPU, for Core's mirror.
// Binding 0: the normals (float4, w unused); binding 1: per normal (encoded, 0, 0), (decoded, 0).
#include "../../Shaders/Library/NormalEncoding.hlsl"

StructuredBuffer<float4> _Normals : register(t0);
RWStructuredBuffer<float4> _Encoded : register(u1);

[numthreads(64, 1, 1)]
void NormalEncodingProbe(uint3 id : SV_DispatchThreadID)
{
    float2 e = LambertEncodeNormal(_Normals[id.x].xyz);
    _Encoded[2u * id.x] = float4(e, 0.0, 0.0);
    _Encoded[2u * id.x + 1u] = float4(LambertDecodeNormal(e), 0.0);
}
