// Harness self-test shaders for --static-mesh: float3 position at location 0, camera at b1.
#include "common.hlsl"

struct Fragment
{
    float4 positionCS : SV_Position;
    float3 color : COLOR0;
};

Fragment vert(float3 position : POSITION)
{
    Fragment f;
    f.positionCS = mul(_RigObjectToClip, float4(position, 1));
    f.color = float3(0.3, 0.6, 0.2) + 0.4 * position.xzx;
    return f;
}

float4 frag(Fragment f) : SV_Target
{
    return float4(f.color, 1);
}
