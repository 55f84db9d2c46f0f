// Harness self-test shaders: the tile draw of Tools~/rig/README.md "Draw modes" reduced to what the
// harness must get right. The surface is flat (height from _ControlPoints, so binding 2 is
// read); the point is which tile and tess coordinate each vertex gets.
//
// Readback (GT_READBACK), 3 float4 per vertex at
//   vertex = tile * (F+1)^2 + round(t*F) * (F+1) + round(s*F)      (internals.md)
//   [0] (object position x, y, z, 1)    object = (q.x, height, q.y)
//   [1] (s, t, tile, SV_PrimitiveID)    tile from SV_VertexID / 4; the hull stage's PrimitiveID,
//                                       only reported: it restarts at 0 in every draw
//   [2] (_ControlPoints[tile].x, _Regions[tile].y, _GridLines[tile], M)   binding checks
//
// GT_STORAGE_TEST: each tile is scaled about its corner by _TileScale[tile].x, a storage buffer at
// binding 8 that the --compute pre-pass (tile_scale.hlsl) writes: a tile whose scale is 0
// collapses to a point and covers no pixel.
#include "common.hlsl"

#ifdef GT_STORAGE_TEST
StructuredBuffer<float4> _TileScale : register(t6);

float TileScale(uint tile) { return _TileScale[tile].x; }
#else
float TileScale(uint tile) { return 1.0; }
#endif

struct TileVertex
{
    uint tile : TILE;      // from SV_VertexID / 4: respects firstVertex of a split draw
    uint corner : CORNER;
};

struct TileFactors
{
    float edges[4] : SV_TessFactor;
    float inside[2] : SV_InsideTessFactor;
    uint primitive : PRIMITIVE_ID;  // SV_PrimitiveID of the hull stage, for the readback
};

struct Fragment
{
    float4 positionCS : SV_Position;
    float3 color : COLOR0;
};

TileVertex vert(uint id : SV_VertexID)
{
    TileVertex v;
    v.tile = id / 4;
    v.corner = id % 4;
    return v;
}

TileFactors hull_constant(InputPatch<TileVertex, 4> patch, uint primitive : SV_PrimitiveID)
{
    TileFactors f;
    f.primitive = primitive;
    float factor = _Tess.w;  // uniform integer factor
    f.edges[0] = f.edges[1] = f.edges[2] = f.edges[3] = factor;
    f.inside[0] = f.inside[1] = factor;
    return f;
}

[domain("quad")]
[partitioning("integer")]
// s -> object x, t -> object z: triangle_ccw in the domain (origin upper left, t down) is
// clockwise seen from above, Unity's front face (the harness culls as Unity does).
[outputtopology("triangle_ccw")]
[outputcontrolpoints(4)]
[patchconstantfunc("hull_constant")]
TileVertex hull_shader(InputPatch<TileVertex, 4> patch, uint i : SV_OutputControlPointID)
{
    return patch[i];
}

float3 TileColor(uint tile)
{
    uint h = tile * 2654435761u;
    return float3((h >> 8) & 255, (h >> 16) & 255, (h >> 24) & 255) / 255.0 * 0.7 + 0.15;
}

[domain("quad")]
Fragment domain_shader(TileFactors factors, float2 st : SV_DomainLocation, const OutputPatch<TileVertex, 4> patch)
{
    uint primitive = factors.primitive;
    uint tile = patch[0].tile;
    float tiles = _Tess.x;
    uint m = (uint)tiles;
    float2 tileIJ = float2(tile % m, tile / m);
    float2 o = (tileIJ + st * TileScale(tile)) / tiles;        // range coordinate
    float2 q = _Range.xy + o * (_Range.zw - _Range.xy);        // global point
    float height = ControlPointFloat4(0u).z;
    float3 object = float3(q.x, height, q.y);

#ifdef GT_READBACK
    uint F = (uint)_Tess.w;
    uint vertex = tile * (F + 1) * (F + 1) + (uint)round(st.y * F) * (F + 1) + (uint)round(st.x * F);
    _Readback[3 * vertex + 0] = float4(object, 1);
    _Readback[3 * vertex + 1] = float4(st, tile, primitive);
    _Readback[3 * vertex + 2] = float4(ControlPointFloat4(tile).x, _Regions[tile].y, _GridLines[tile], tiles);
#endif

    Fragment f;
    f.positionCS = mul(_RigObjectToClip, float4(object, 1));
    f.color = TileColor(tile) * (0.75 + 0.25 * st.x);
    return f;
}

// Fallback: grid vertex from SV_VertexID, tile from SV_InstanceID; same readback layout
// (SV_PrimitiveID slot holds 0).
Fragment vert_fallback(uint id : SV_VertexID, uint instance : SV_InstanceID)
{
    uint F = (uint)_Tess.w;
    float2 st = float2(id % (F + 1), id / (F + 1)) / (float)F;
    uint tile = instance;
    float tiles = _Tess.x;
    uint m = (uint)tiles;
    float2 o = (float2(tile % m, tile / m) + st * TileScale(tile)) / tiles;
    float2 q = _Range.xy + o * (_Range.zw - _Range.xy);
    float3 object = float3(q.x, ControlPointFloat4(0u).z, q.y);
#ifdef GT_READBACK
    uint vertex = tile * (F + 1) * (F + 1) + id;
    _Readback[3 * vertex + 0] = float4(object, 1);
    _Readback[3 * vertex + 1] = float4(st, tile, 0);
    _Readback[3 * vertex + 2] = float4(ControlPointFloat4(tile).x, _Regions[tile].y, _GridLines[tile], tiles);
#endif
    Fragment f;
    f.positionCS = mul(_RigObjectToClip, float4(object, 1));
    f.color = TileColor(tile) * (0.75 + 0.25 * st.x);
    return f;
}

float4 frag(Fragment f) : SV_Target
{
    return float4(f.color, 1);
}
