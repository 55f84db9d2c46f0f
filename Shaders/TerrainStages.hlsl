// The terrain's shader stages, in the vertex / hull / domain / fragment style of Unity Graphics
// Programming vol. 4, chapter 6. Include a pipeline adapter (Shaders/Adapters) first.
//
//   vert           tile mode: one 4-control-point patch per tile, no vertex buffer:
//                  tile = SV_VertexID / 4, corner = SV_VertexID % 4 (internals.md, "Draw modes")
//   hull_const     edge factors from each tile edge's chord error in pixels, frustum culling
//   hull_shader    passes the 4 corners through
//   domain_shader  tess coordinate -> TerrainVertex (TerrainVertex.hlsl)
//   vert_fallback  no tessellator: a (F+1)^2 UV grid per instance (= tile), same TerrainVertex
//   vert_static    rig only (GT_STATIC_MESH): the terrain's vertices baked once, the fallback's index grid
//   frag           TerrainShading.hlsl: colour (forward), packed normal (GT_PASS_DEPTH_NORMALS),
//                  nothing (GT_PASS_SHADOWCASTER, GT_PASS_DEPTH)
//
// Keywords (Tools~/rig/shader_variants.txt lists the combinations that are compiled):
//   GT_NOISE, GT_HEIGHT_COLOR, GT_SNOW                effects; off means not compiled at all
//   GT_DEBUG_NORMALS, GT_DEBUG_PATCH_ID, GT_DEBUG_TESS_FACTOR   debug views
//   GT_PAPER_MODE, GT_READBACK, GT_FACTOR_READBACK    off-Unity rig only
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

#if defined(GT_FACTOR_READBACK)
// Rig only (internals.md, "Rig-only readback"): hull_const writes each drawn patch's factors,
// 2 float4 per patch: (edge[0..3]), (inside[0..1], culled 1/0, 0). Partitioning stays
// fractional_odd: these are the factors the shipped shader uses.
    #if !defined(GT_READBACK)
RWStructuredBuffer<float4> _Readback GT_REGISTER(u0);
    #endif
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
#if defined(GT_SNOW)
    hi.y += SnowDepthCap();   // snow only raises the surface, by at most the cap
#endif
    float4 boxCS[8];
    [unroll] for (uint k = 0; k < 8; k++)
    {
        float3 p = float3((k & 1u) ? hi.x : lo.x, (k & 2u) ? hi.y : lo.y, (k & 4u) ? hi.z : lo.z);
        boxCS[k] = GT_ObjectToClip(p);
    }
    // The height margin is already in the box (object units), so no clip-space margin on top.
    return BoxOutsideFrustum(boxCS, 0.0);
}

// Object point -> pixels per object unit there (TessellationFactors.hlsl, PixelsPerUnit).
float ObjectPixelsPerUnit(float3 p)
{
    return PixelsPerUnit(GT_ObjectToClip(p), GT_ObjectToClip(p + float3(1.0, 0.0, 0.0)),
                         GT_ObjectToClip(p + float3(0.0, 1.0, 0.0)), GT_ObjectToClip(p + float3(0.0, 0.0, 1.0)),
                         GT_ScreenSize());
}

// Object position of the Gregory surface (no noise) at a tess coordinate of the drawn patch.
float3 SurfaceObjectPosition(uint drawPatch, float2 tess)
{
    return TerrainToObject(EvaluateSurface(drawPatch, tess).position);
}

// Factor of the edge from tess coordinate a to b (a the lower one) whose end points are pa, pb:
// the surface (no noise) is evaluated at the GT_EDGE_SEGMENTS - 1 inner points of the edge
// (SampledEdgeSagittaPixels), and the bound of the noise the frame draws is added (noiseCurvature,
// 0 without GT_NOISE; edgeLength in terrain units). A neighbour sharing the edge forms the same
// global points bit for bit (RangeCoordinate adds the integer tile index first), so it gets the
// same factor: no cracks.
float EdgeErrorTessFactor(uint drawPatch, float2 a, float2 b, float3 pa, float3 pb, float edgeLength, float noiseCurvature,
                          float targetPixelError, float maxFactor)
{
    float3 p[GT_EDGE_SEGMENTS + 1];
    float k[GT_EDGE_SEGMENTS + 1];
    p[0] = pa;
    p[GT_EDGE_SEGMENTS] = pb;
    k[0] = k[GT_EDGE_SEGMENTS] = 0.0;
    float kMax = 0.0;
    [unroll] for (uint i = 1u; i < GT_EDGE_SEGMENTS; i++)
    {
        p[i] = SurfaceObjectPosition(drawPatch, lerp(a, b, (float)i / (float)GT_EDGE_SEGMENTS));
        k[i] = ObjectPixelsPerUnit(p[i]);
        kMax = max(kMax, k[i]);
    }
    float sagitta = SampledEdgeSagittaPixels(p, k) + NoiseSagittaPixels(noiseCurvature, edgeLength, kMax);
    return ErrorTessFactor(sagitta, targetPixelError, maxFactor);
}

TileFactors ComputeTileFactors(InputPatch<TileCorner, 4> corners)
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
    // The knob is the target screen-space error in pixels (_Tess.z): each edge gets the segment
    // count whose chord error is that many pixels (TessellationPolicy.ErrorTessFactor). Each factor
    // depends only on its edge (end points and seven points of the surface on it), taken lower tess
    // coordinate first by both tiles that share it: their factors agree bit for bit (no cracks).
    uint patch = corners[0].drawPatch;
    float target = TargetPixelError(), maxFactor = MaxTessFactor();
    float2 edgeLength = (_Range.zw - _Range.xy) / TileCount();   // along u (x) and along v (y), terrain units
    float noiseCurvature = 0.0;
#if defined(GT_NOISE)
    // The octaves this frame draws (the count TerrainVertex uses): the knob counts the noise it shows.
    noiseCurvature = NoiseCurvatureBound(NoiseSettings(), OctaveCount(RangeWidth(), NoiseVerticesAcross(), NoiseSettings(), MaxNoiseOctaves()));
#endif
    f.edge[0] = EdgeErrorTessFactor(patch, float2(0, 0), float2(0, 1), cornerOS[0], cornerOS[2], edgeLength.y, noiseCurvature, target, maxFactor);   // u = 0
    f.edge[1] = EdgeErrorTessFactor(patch, float2(0, 0), float2(1, 0), cornerOS[0], cornerOS[1], edgeLength.x, noiseCurvature, target, maxFactor);   // v = 0
    f.edge[2] = EdgeErrorTessFactor(patch, float2(1, 0), float2(1, 1), cornerOS[1], cornerOS[3], edgeLength.y, noiseCurvature, target, maxFactor);   // u = 1
    f.edge[3] = EdgeErrorTessFactor(patch, float2(0, 1), float2(1, 1), cornerOS[2], cornerOS[3], edgeLength.x, noiseCurvature, target, maxFactor);   // v = 1
    // Inside factors follow the edges they run along: inside[0] subdivides along u, like the
    // v = 0 and v = 1 edges. They match no neighbour, so they may look inside: the tile's two
    // midlines (bumps between the edges) and the centre's deviation from the diagonals (a twist
    // bends the diagonals, not the edges).
    float midU = EdgeErrorTessFactor(patch, float2(0, 0.5), float2(1, 0.5), SurfaceObjectPosition(patch, float2(0, 0.5)),
                                     SurfaceObjectPosition(patch, float2(1, 0.5)), edgeLength.x, noiseCurvature, target, maxFactor);
    float midV = EdgeErrorTessFactor(patch, float2(0.5, 0), float2(0.5, 1), SurfaceObjectPosition(patch, float2(0.5, 0)),
                                     SurfaceObjectPosition(patch, float2(0.5, 1)), edgeLength.y, noiseCurvature, target, maxFactor);
    float3 centre = SurfaceObjectPosition(patch, float2(0.5, 0.5));
    float diagonal = InsideErrorTessFactor(DiagonalSagittaPixels(cornerOS[0], cornerOS[1], cornerOS[2], cornerOS[3],
                                                                 centre, ObjectPixelsPerUnit(centre)), target, maxFactor);
    float2 inside = max(max(TessInsideFactors(f.edge[0], f.edge[1], f.edge[2], f.edge[3]), float2(midU, midV)), diagonal);
    f.inside[0] = inside.x;
    f.inside[1] = inside.y;
    return f;
}

TileFactors hull_const(InputPatch<TileCorner, 4> corners)
{
    TileFactors f = ComputeTileFactors(corners);
#if defined(GT_FACTOR_READBACK)
    uint p = corners[0].drawPatch;
    _Readback[2 * p + 0] = float4(f.edge[0], f.edge[1], f.edge[2], f.edge[3]);
    _Readback[2 * p + 1] = float4(f.inside[0], f.inside[1], f.edge[0] == 0.0 ? 1.0 : 0.0, 0.0);
#endif
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

#if defined(GT_STATIC_MESH)
// Rig only (gt bench, "the fair static mesh"): the terrain baked into the static mesh a user could
// draw instead, drawn with the same frag. Per vertex 2 float4, (object position, 1), (object normal, 0)
// (Tools~/rig/bench_static_mesh.py packs them from the GT_READBACK vertices of M x M tiles at the
// uniform factor F = _Tess.w), read from the _ControlPoints binding through the fallback grid's
// index buffer: vertex = instance (F+1)^2 + SV_VertexID. Nothing is evaluated.
TerrainVaryings vert_static(uint vertexID : SV_VertexID, uint instanceID : SV_InstanceID)
{
    uint f = max((uint)UniformTessFactor(), 1u);
    uint v = instanceID * (f + 1u) * (f + 1u) + vertexID;
    TerrainVaryings o = (TerrainVaryings)0;
    o.positionCS = GT_ObjectToClip(_ControlPoints[2u * v].xyz);
    o.normalWS = GT_ObjectToWorldNormal(_ControlPoints[2u * v + 1u].xyz);
    return o;
}
#endif

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
