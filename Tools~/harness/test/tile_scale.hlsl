// Harness self-test kernels for the compute pre-pass feeding the draw, shaped like the vertex
// cache (a first kernel's output read by a second, whose output the draw's vertex/domain stage
// reads). Compiled one entry point per module; dispatch (ceil(M^2 / 64), 1, 1) each.
//   tile_flags: binding 7 (u2), per tile (kept, tile, M, 0), kept = 1 for every third tile
//   tile_scale: reads binding 7, writes binding 8 (u3) per tile (kept, tile + 0.5, 0, 0)
// tiles.hlsl with GT_STORAGE_TEST scales each tile by binding 8's x: only the kept tiles cover
// pixels. Run in the wrong order, tile_scale reads zeros and nothing is drawn.
#include "common.hlsl"

RWStructuredBuffer<float4> _TileFlagsRW : register(u2);
RWStructuredBuffer<float4> _TileScaleRW : register(u3);

[numthreads(64, 1, 1)]
void tile_flags(uint3 id : SV_DispatchThreadID)
{
    uint m = (uint)_Tess.x;
    uint tile = id.x;
    if (tile >= m * m)
        return;
    _TileFlagsRW[tile] = float4(tile % 3 == 0 ? 1.0 : 0.0, tile, m, 0);
}

[numthreads(64, 1, 1)]
void tile_scale(uint3 id : SV_DispatchThreadID)
{
    uint m = (uint)_Tess.x;
    uint tile = id.x;
    if (tile >= m * m)
        return;
    float4 flags = _TileFlagsRW[tile];
    _TileScaleRW[tile] = float4(flags.x, flags.y + 0.5, 0, 0);
}
