// Harness self-test kernel for --compute / --storage / --dump-storage: writes a known pattern
// into the storage buffer at binding 8 (u3 with --suavb 5), reading bindings 0 and 2 on the way
// so the pre-pass is seen to share the draw's descriptor set.
//
// Dispatch exactly (4, 2, 3) groups of 64: record i = x + 256 (y + 2 z) for SV_DispatchThreadID
// (x, y, z), 1,536 records of uint4
//   (i, i * 2654435761 mod 2^32, bits of _Tess.x, bits of _ControlPoints[i % 1280].x)
// A run that ignored GY or GZ would leave records 256.. zero.
#include "common.hlsl"

RWStructuredBuffer<uint4> _PatternRW : register(u3);

[numthreads(64, 1, 1)]
void pattern(uint3 id : SV_DispatchThreadID)
{
    uint i = id.x + 256 * (id.y + 2 * id.z);
    _PatternRW[i] = uint4(i, i * 2654435761u, asuint(_Tess.x), asuint(ControlPointFloat4(i % 1280).x));
}
