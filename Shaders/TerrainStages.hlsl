// The terrain's shader stages, in the vertex / hull / domain / fragment style of Unity Graphics
// Programming vol. 4, chapter 6. Include a pipeline adapter (Shaders/Adapters) first.
//
//   vert           tile mode: one 4-control-point patch per tile, no vertex buffer:
//                  tile = SV_VertexID / 4, corner = SV_VertexID % 4 (internals.md, "Draw modes")
//   hull_const     edge factors from the screen length of each tile edge, frustum culling
//   hull_shader    passes the 4 corners through
//   domain_shader  tess coordinate -> TerrainVertex (TerrainVertex.hlsl)
//   vert_fallback  no tessellator: a (F+1)^2 UV grid per instance (= tile), same TerrainVertex
//   frag           TerrainShading.hlsl: colour (forward), packed normal (GT_PASS_DEPTH_NORMALS),
//                  nothing (GT_PASS_SHADOWCASTER, GT_PASS_DEPTH)
//
// Keywords (Tools~/rig/shader_variants.txt lists the combinations that are compiled):
//   GT_NOISE, GT_HEIGHT_COLOR                         effects; off means not compiled at all
//   GT_DEBUG_NORMALS, GT_DEBUG_PATCH_ID, GT_DEBUG_TESS_FACTOR   debug views
//   GT_PAPER_MODE, GT_READBACK                        off-Unity rig only
#ifndef GT_TERRAIN_STAGES_INCLUDED
#define GT_TERRAIN_STAGES_INCLUDED

#include "TerrainVertex.hlsl"
#include "TerrainShading.hlsl"
#include "TessellationFactors.hlsl"

// The readback indexes vertices as an (F+1) x (F+1) grid, which only integer partitioning makes.
// Otherwise fractional_odd: factors change continuously with the view, so no popping.
#if defined(GT_READBACK)
    #define GT_PARTITIONING "integer"
#else
    #define GT_PARTITIONING "fractional_odd"
#endif

// vert -> hull -> domain: one corner of a tile (or, in paper mode, of a Gregory patch's range).
struct TileCorner
{
    // Surface point at the corner without noise, object space: input of the edge factors and of
    // the tile's bounding box.
    float3 positionOS : INTERNALTESSPOS;
    uint drawPatch : TEXCOORD0;   // tile index, or the Gregory patch in paper mode
};

// Quad domain: edge[0] is u = 0, edge[1] v = 0, edge[2] u = 1, edge[3] v = 1;
// inside[0] subdivides along u, inside[1] along v.
struct TileFactors
{
    float edge[4] : SV_TessFactor;
    float inside[2] : SV_InsideTessFactor;
};

// Corner c sits at tess coordinate (c & 1, c >> 1).
float2 CornerTessCoordinate(uint corner) { return float2(corner & 1u, corner >> 1u); }

TileCorner vert(uint vertexID : SV_VertexID)
{
    TileCorner o;
    o.drawPatch = vertexID / 4u;
    // Corners depend only on (tile, corner) integers, so a corner shared by neighbouring tiles is
    // evaluated from identical inputs: identical positions, identical edge factors.
    TerrainSurfacePoint s = EvaluateSurface(o.drawPatch, CornerTessCoordinate(vertexID % 4u));
    o.positionOS = TerrainToObject(OutputSurfacePosition(s));
    return o;
}

// True when the tile's box lies outside the view. The box is the corners' bounds, grown in height
// by the noise bound (GT_NOISE) plus the corners' own height spread: a cheap allowance for the
// surface rising between corners, which the corners alone cannot see. (Takes the corners as an
// array, not the InputPatch: not every HLSL compiler accepts an InputPatch as a helper argument.)
bool TileCulled(float3 cornerOS[4])
{
    float3 lo = cornerOS[0], hi = lo;
    [unroll] for (uint c = 1; c < 4; c++)
    {
        lo = min(lo, cornerOS[c]);
        hi = max(hi, cornerOS[c]);
    }
    float margin = hi.y - lo.y;
#if defined(GT_NOISE)
    margin += NoiseHeightBound();
#endif
    lo.y -= margin;
    hi.y += margin;
    float4 boxCS[8];
    [unroll] for (uint k = 0; k < 8; k++)
    {
        float3 p = float3((k & 1u) ? hi.x : lo.x, (k & 2u) ? hi.y : lo.y, (k & 4u) ? hi.z : lo.z);
        boxCS[k] = GT_ObjectToClip(p);
    }
    // The height margin is already in the box (object units), so no clip-space margin on top.
    return BoxOutsideFrustum(boxCS, 0.0);
}

TileFactors hull_const(InputPatch<TileCorner, 4> corners)
{
    TileFactors f;
    if (UsesUniformTessFactor())
    {
        // Tests and benchmarks: every tile, every edge the same, nothing culled, so the vertex
        // count is known in advance.
        float u = UniformTessFactor();
        f.edge[0] = f.edge[1] = f.edge[2] = f.edge[3] = u;
        f.inside[0] = f.inside[1] = u;
        return f;
    }
    float3 cornerOS[4];
    [unroll] for (uint c = 0; c < 4; c++)
        cornerOS[c] = corners[c].positionOS;
    if (TileCulled(cornerOS))
    {
        f.edge[0] = f.edge[1] = f.edge[2] = f.edge[3] = 0.0;   // a zero edge factor drops the patch
        f.inside[0] = f.inside[1] = 0.0;
        return f;
    }
    float4 cornerCS[4];
    [unroll] for (uint k = 0; k < 4; k++)
        cornerCS[k] = GT_ObjectToClip(cornerOS[k]);
    // Each factor depends only on its edge's two endpoints, taken in the same order (lower tess
    // coordinate first) by both tiles that share the edge: their factors agree bit for bit, so the
    // tessellated edges match (no cracks).
    float2 screen = GT_ScreenSize();
    float pixels = TargetPixelsPerSegment(), maxFactor = MaxTessFactor();
    f.edge[0] = EdgeTessFactor(cornerCS[0], cornerCS[2], screen, pixels, maxFactor);   // u = 0
    f.edge[1] = EdgeTessFactor(cornerCS[0], cornerCS[1], screen, pixels, maxFactor);   // v = 0
    f.edge[2] = EdgeTessFactor(cornerCS[1], cornerCS[3], screen, pixels, maxFactor);   // u = 1
    f.edge[3] = EdgeTessFactor(cornerCS[2], cornerCS[3], screen, pixels, maxFactor);   // v = 1
    // Inside factors follow the edges they run along: inside[0] subdivides along u, like the
    // v = 0 and v = 1 edges.
    float2 inside = TessInsideFactors(f.edge[0], f.edge[1], f.edge[2], f.edge[3]);
    f.inside[0] = inside.x;
    f.inside[1] = inside.y;
    return f;
}

[domain("quad")]
[partitioning(GT_PARTITIONING)]
[outputtopology("triangle_cw")]
[patchconstantfunc("hull_const")]
[outputcontrolpoints(4)]
TileCorner hull_shader(InputPatch<TileCorner, 4> corners, uint id : SV_OutputControlPointID)
{
    return corners[id];
}

// The patch index comes from the control points (SV_VertexID / 4), not from SV_PrimitiveID: in
// paper mode too, because SV_PrimitiveID restarts at 0 in every draw when the rig splits a draw
// (lavapipe's vertex limit) while SV_VertexID keeps counting from firstVertex.
[domain("quad")]
TerrainVaryings domain_shader(TileFactors factors, const OutputPatch<TileCorner, 4> corners,
                              float2 tess : SV_DomainLocation)
{
    return TerrainVertex(corners[0].drawPatch, tess, max(factors.inside[0], factors.inside[1]));
}

// No tessellator: draw an index buffer over a (F+1) x (F+1) vertex grid, F = the uniform factor
// (_Tess.w, an integer >= 1), one instance per tile. Vertex i + j (F+1) sits at tess (i, j) / F.
TerrainVaryings vert_fallback(uint vertexID : SV_VertexID, uint instanceID : SV_InstanceID)
{
    uint f = max((uint)UniformTessFactor(), 1u);
    uint2 grid = uint2(vertexID % (f + 1u), vertexID / (f + 1u));
    return TerrainVertex(instanceID, (float2)grid / (float)f, (float)f);
}

// One fragment entry for every pass; the pass's GT_PASS_* define (set by GregoryTerrain.shader)
// picks the output. Depth and shadow passes write no colour (ColorMask 0), so they evaluate nothing
// here: no albedo, no lighting, no shadow lookup. No GT_PASS_* (the off-Unity rig) = the colour.
float4 frag(TerrainVaryings i) : SV_Target
{
#if defined(GT_PASS_SHADOWCASTER) || defined(GT_PASS_DEPTH)
    return 0.0;
#elif defined(GT_PASS_DEPTH_NORMALS)
    return TerrainDepthNormal(i);
#else
    return TerrainFragmentColor(i);
#endif
}

#endif // GT_TERRAIN_STAGES_INCLUDED
