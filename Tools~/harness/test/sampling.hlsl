// Harness self-test kernel for --image / --sampler: reads uploaded textures through separate
// samplers (as HLSL compiles Texture2D + SamplerState / SamplerComparisonState) and writes what it
// read to the storage buffer at binding 8 (u3 with --suavb 5), one float4 per probe:
//   0  _Values.Load(texel (3, 1))                    texel fetch
//   1  _Values at uv (0.5, 0.5), linear clamp         the midpoint of texels (1..2, 1..2): bilinear
//   2  _Values at uv (-0.625, 0.625), point repeat    wraps to texel (1, 2)
//   3  _Depth (row 0.25, 0.75) compared through a point sampler: x, y at texels 0 and 1 with
//      reference 0.5, z texel 1 with 0.8, w texel 0 with its own value 0.25 (strict vs or-equal)
//   4  _Layers.Load(texel (0, 0), layer 1)            the second layer of a 2D array
// compile.sh shifts t registers by 2 (t8 -> binding 10) and leaves s registers as they are;
// HarnessTests gives the inputs at bindings 10, 11, 15 (images) and 12, 13, 14 (samplers).

Texture2D<float2> _Values : register(t8);
Texture2D<float> _Depth : register(t9);
Texture2DArray<float4> _Layers : register(t13);
SamplerState _LinearClamp : register(s12);
SamplerState _PointRepeat : register(s13);
SamplerComparisonState _Compare : register(s14);

RWStructuredBuffer<float4> _Probes : register(u3);

[numthreads(1, 1, 1)]
void probe(uint3 id : SV_DispatchThreadID)
{
    _Probes[0] = float4(_Values.Load(int3(3, 1, 0)), 0, 0);
    _Probes[1] = float4(_Values.SampleLevel(_LinearClamp, float2(0.5, 0.5), 0), 0, 0);
    _Probes[2] = float4(_Values.SampleLevel(_PointRepeat, float2(-0.625, 0.625), 0), 0, 0);
    _Probes[3] = float4(_Depth.SampleCmpLevelZero(_Compare, float2(0.25, 0.25), 0.5),
                        _Depth.SampleCmpLevelZero(_Compare, float2(0.75, 0.25), 0.5),
                        _Depth.SampleCmpLevelZero(_Compare, float2(0.75, 0.25), 0.8),
                        _Depth.SampleCmpLevelZero(_Compare, float2(0.25, 0.25), 0.25));
    _Probes[4] = _Layers.Load(int4(0, 0, 1, 0));
}
