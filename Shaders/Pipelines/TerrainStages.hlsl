// The terrain's shader stages, in the vertex / hull / domain / fragment style of Unity Graphics
// Programming vol. 4, chapter 6. Include a pipeline adapter (Shaders/Pipelines) first.
//
//   vert           tile mode: one 4-control-point patch per tile, no vertex buffer:
//                  tile = SV_VertexID / 4, corner = SV_VertexID % 4 (internals.md, "Shader stages")
//   hull_const     the tile's factors from its vertex source (VertexSource.*.hlsl, one per mode)
//   hull_shader    passes the 4 corners through
//   domain_shader  tess coordinate -> the vertex source's TerrainVaryings
//   vert_fallback  no tessellator: a (F+1)^2 UV grid per instance (= tile), same TerrainVertex
//   frag           TerrainShading.hlsl: colour (forward), packed normal (GT_PASS_DEPTH_NORMALS),
//                  depth (GT_PASS_DEPTH), nothing (GT_PASS_SHADOWCASTER), the editor's selection
//                  colours (GT_PASS_SCENE_SELECTION, GT_PASS_SCENE_PICKING)
//
// Keywords (Tools~/rig/shader_variants.txt lists the combinations that are compiled):
//   GT_NOISE, GT_HEIGHT_COLOR, GT_SNOW                effects; off means not compiled at all
//   GT_VERTEX_CACHE                                   vertices evaluated by a compute pre-pass
//   GT_DEBUG_NORMALS, GT_DEBUG_PATCH_ID, GT_DEBUG_TESS_FACTOR   debug views
//
// Extension points for an entry file outside the package (the off-Unity rig,
// Tools~/rig/TerrainRig.hlsl; internals.md, "Extension points"); no Unity build defines them:
//   GT_EXTEND_DRAW_PATCHES, GT_EXTEND_VERTEX    TerrainVertex.hlsl
//   GT_EXTEND_TILE_FACTORS    hull_const hands each patch's factors to ExtensionTileFactors
//   GT_PARTITIONING           defined before this file: the hull stage's partitioning
// GT_LOD and GT_VERTEX_CACHE are the package's keywords: they pick the vertex source below.
#ifndef GT_TERRAIN_STAGES_INCLUDED
#define GT_TERRAIN_STAGES_INCLUDED

#include "../Terrain/TerrainVertex.hlsl"
#include "../Terrain/TerrainShading.hlsl"
#include "../Terrain/TileFactors.hlsl"

// vert -> hull -> domain: one corner of a tile (or of an extension's draw patch).
struct TileCorner
{
    // Surface point at the corner without noise, object space: input of the edge factors and of
    // the tile's bounding box.
    float3 positionOS : INTERNALTESSPOS;
    uint drawPatch : TEXCOORD0;   // tile index, or the extension's draw patch
};

// Quad domain: edge[0] is u = 0, edge[1] v = 0, edge[2] u = 1, edge[3] v = 1;
// inside[0] subdivides along u, inside[1] along v.
struct TileFactors
{
    float edge[4] : SV_TessFactor;
    float inside[2] : SV_InsideTessFactor;
#if defined(GT_VERTEX_CACHE)
    // The part of its cell the tile keeps (TileKeptCellSpan): the domain stage reads the cell's records.
    float4 keptCellSpan : TEXCOORD1;
#endif
};

TileFactors ToTileFactors(TileFactorSet set)
{
    TileFactors f;
    f.edge[0] = set.edge.x;
    f.edge[1] = set.edge.y;
    f.edge[2] = set.edge.z;
    f.edge[3] = set.edge.w;
    f.inside[0] = set.inside.x;
    f.inside[1] = set.inside.y;
    return f;
}

TileFactorSet FromTileFactors(TileFactors f)
{
    TileFactorSet set;
    set.edge = float4(f.edge[0], f.edge[1], f.edge[2], f.edge[3]);
    set.inside = float2(f.inside[0], f.inside[1]);
    return set;
}

// The factors of tile `slot` of layout l from its corners' surface points (vert).
TileFactorSet CornerTileFactors(TileLayout l, uint slot, InputPatch<TileCorner, 4> corners)
{
    float3 cornerOS[4];
    [unroll] for (uint c = 0; c < 4; c++)
        cornerOS[c] = corners[c].positionOS;
    return ComputeTileFactors(l, slot, cornerOS);
}

// Where a tile's factors and vertices come from: one file each, the same stage shape
// (StageTileLayout, StageCornerPosition, StageTileFactors, StageDomainVertex; VertexSource.Domain.hlsl).
#if defined(GT_VERTEX_CACHE)
    #include "VertexSource.Cache.hlsl"
#elif defined(GT_LOD)
    #include "VertexSource.Levels.hlsl"
#else
    #include "VertexSource.Domain.hlsl"
#endif

#if !defined(GT_PARTITIONING)
    #define GT_PARTITIONING GT_STAGE_PARTITIONING
#endif

TileCorner vert(uint vertexID : SV_VertexID)
{
    TileCorner o;
    o.drawPatch = vertexID / 4u;
    o.positionOS = StageCornerPosition(o.drawPatch, vertexID % 4u);
    return o;
}

#if defined(GT_EXTEND_TILE_FACTORS)
// Extension point: the entry file sees the factors hull_const returns for each drawn patch; it
// defines this after including the stages.
void ExtensionTileFactors(uint drawPatch, TileFactors f);
#endif

TileFactors hull_const(InputPatch<TileCorner, 4> corners)
{
    TileFactors f = StageTileFactors(corners);
#if defined(GT_EXTEND_TILE_FACTORS)
    ExtensionTileFactors(corners[0].drawPatch, f);
#endif
    return f;
}

// Winding: tess u -> object x, v -> object z. The domain's origin is its upper left with v growing
// down, so its counter-clockwise triangles are clockwise seen from above: Unity's front face (Cull
// Back keeps them), as the fallback's index buffer (v, v + row, v + 1) is.
[domain("quad")]
[partitioning(GT_PARTITIONING)]
[outputtopology("triangle_ccw")]
[patchconstantfunc("hull_const")]
[outputcontrolpoints(4)]
TileCorner hull_shader(InputPatch<TileCorner, 4> corners, uint id : SV_OutputControlPointID)
{
    return corners[id];
}

// The patch index comes from the control points (SV_VertexID / 4), not from SV_PrimitiveID:
// SV_PrimitiveID restarts at 0 in every draw when the rig splits a draw
// (lavapipe's vertex limit) while SV_VertexID keeps counting from firstVertex.
[domain("quad")]
TerrainVaryings domain_shader(TileFactors factors, const OutputPatch<TileCorner, 4> corners,
                              float2 tess : SV_DomainLocation)
{
    float tessFactor = max(factors.inside[0], factors.inside[1]);
    return StageDomainVertex(factors, corners[0].drawPatch, tess, tessFactor);
}

// No tessellator: draw an index buffer over a (F+1) x (F+1) vertex grid, F = the uniform factor
// (_Tess.w, an integer >= 1), one instance per tile. Vertex i + j (F+1) sits at tess (i, j) / F.
TerrainVaryings vert_fallback(uint vertexID : SV_VertexID, uint instanceID : SV_InstanceID)
{
    uint f = max((uint)UniformTessFactor(), 1u);
    uint2 grid = uint2(vertexID % (f + 1u), vertexID / (f + 1u));
    // GT_LOD: each instance is a tile of its level; a uniform grid cannot follow the seam rule
    // (2g against g + g), so the fallback's level seams keep T-junctions.
    uint slot;
    TileLayout l = StageTileLayout(instanceID, slot);
    return TerrainVertex(l, slot, (float2)grid / (float)f, (float)f);
}

// One fragment entry for every pass; the pass's GT_PASS_* define (set by GregoryTerrain.shader)
// picks the output. Depth, shadow and editor passes evaluate no albedo, lighting or shadow lookup.
// No GT_PASS_* (the off-Unity rig) = the colour.
#if defined(GT_PASS_SHADOWCASTER)
float4 frag(TerrainVaryings i) : SV_Target
{
    return 0.0;   // ColorMask 0: depth only
}
#elif defined(GT_PASS_DEPTH)
// URP's DepthOnly convention: the depth also as colour (ColorMask R), for a colour depth target.
float4 frag(TerrainVaryings i) : SV_Target
{
    return i.positionCS.zzzz;
}
#elif defined(GT_PASS_DEPTH_NORMALS) && defined(GT_WRITE_DEPTH_COLOR)
// HDRP with MSAA: the depth as colour in target 0, then the normal buffer.
void frag(TerrainVaryings i, out float4 depthColor : SV_Target0, out float4 normal : SV_Target1)
{
    depthColor = float4(i.positionCS.zzz, 1.0);
    normal = TerrainDepthNormal(i);
}
#elif defined(GT_PASS_DEPTH_NORMALS) && defined(GT_WRITE_RENDERING_LAYERS)
void frag(TerrainVaryings i, out float4 normal : SV_Target0, out float4 renderingLayers : SV_Target1)
{
    normal = TerrainDepthNormal(i);
    renderingLayers = GT_RenderingLayers();
}
#elif defined(GT_PASS_DEPTH_NORMALS)
float4 frag(TerrainVaryings i) : SV_Target
{
    return TerrainDepthNormal(i);
}
#elif defined(GT_PASS_SCENE_SELECTION) || defined(GT_PASS_SCENE_PICKING)
// The Scene view's selection outline or picking ID (adapter).
float4 frag(TerrainVaryings i) : SV_Target
{
    return GT_EditorSelectionColor();
}
#elif defined(GT_WRITE_RENDERING_LAYERS)
// The colour, and the rendering layers in the pipeline's second target.
void frag(TerrainVaryings i, out float4 color : SV_Target0, out float4 renderingLayers : SV_Target1)
{
    color = TerrainFragmentColor(i);
    renderingLayers = GT_RenderingLayers();
}
#else
float4 frag(TerrainVaryings i) : SV_Target
{
    return TerrainFragmentColor(i);
}
#endif

#endif // GT_TERRAIN_STAGES_INCLUDED
