// The terrain's shader stages, in the vertex / hull / domain / fragment style of Unity Graphics
// Programming vol. 4, chapter 6. Include a pipeline adapter (Shaders/Pipelines) first.
//
//   vert           tile mode: one 4-control-point patch per tile, no vertex buffer:
//                  tile = SV_VertexID / 4, corner = SV_VertexID % 4 (internals.md, "Shader stages")
//   hull_const     edge factors from each tile edge's chord error in pixels, frustum culling
//                  (TileFactors.hlsl); GT_VERTEX_CACHE: the factors the compute pass decided
//   hull_shader    passes the 4 corners through
//   domain_shader  tess coordinate -> TerrainVertex (TerrainVertex.hlsl); GT_VERTEX_CACHE: the
//                  vertex the compute pass stored (VertexCacheKernels.hlsl), transformed
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
//   GT_LOD                    levels of detail: L levels in one draw (LodTiles.hlsl)
#ifndef GT_TERRAIN_STAGES_INCLUDED
#define GT_TERRAIN_STAGES_INCLUDED

#include "../Terrain/TerrainVertex.hlsl"
#include "../Terrain/TerrainShading.hlsl"
#include "../Terrain/TileFactors.hlsl"
#if defined(GT_VERTEX_CACHE)
    #include "../Cache/ClippedCell.hlsl"
    #if defined(GT_EXTEND_DRAW_PATCHES) || defined(GT_EXTEND_VERTEX) || defined(GT_EXTEND_TILE_FACTORS)
        #error "GT_VERTEX_CACHE draws tiles from the cache: no other draw patches, and the cache holds the vertices and factors"
    #endif
#endif

// The vertex cache (VertexCache.hlsl) stores vertices at k / F: only integer partitioning makes
// those. Otherwise fractional_odd: factors change continuously with the view, so no popping.
// The levels' seam rule (LodTiles.hlsl) needs integer factors too: 2g coarse segments meet g + g fine.
#if !defined(GT_PARTITIONING)
    #if defined(GT_VERTEX_CACHE) || defined(GT_LOD)
        #define GT_PARTITIONING "integer"
    #else
        #define GT_PARTITIONING "fractional_odd"
    #endif
#endif

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

// The layout draw patch `drawPatch` is drawn with and its tile (slot) there: the frame's layout, or
// with GT_LOD its level's (draw patch p is tile p mod M^2 of level p / M^2, LodTiles.hlsl).
TileLayout StageTileLayout(uint drawPatch, out uint slot)
{
#if defined(GT_LOD)
    slot = LodSlotOfPatch(drawPatch, TileCountInt());
    return LodLevelLayout(LodLevelOfPatch(drawPatch, TileCountInt()));
#else
    slot = drawPatch;
    return FrameTileLayout();
#endif
}

TileCorner vert(uint vertexID : SV_VertexID)
{
    TileCorner o;
    o.drawPatch = vertexID / 4u;
#if defined(GT_VERTEX_CACHE)
    o.positionOS = float3(0.0, 0.0, 0.0);   // the factors come from the cache
#else
    uint slot;
    TileLayout l = StageTileLayout(o.drawPatch, slot);
    o.positionOS = CellCornerObjectPosition(l, slot, vertexID % 4u);
#endif
    return o;
}

#if defined(GT_EXTEND_TILE_FACTORS)
// Extension point: the entry file sees the factors hull_const returns for each drawn patch; it
// defines this after including the stages.
void ExtensionTileFactors(uint drawPatch, TileFactors f);
#endif

#if defined(GT_LOD)
// The seams of draw patch p's tile (LodTiles.hlsl): coarseMask, its edges on the rim of the finer
// level (none on level 0), fineMask, its edges on its own level's boundary where a coarser level
// lies beyond (none on the last level); inside: wholly inside the finer level (culled). ab: the
// finer level's offset in this level's cells, abUp this level's in the coarser one's.
void LodTileSeams(uint drawPatch, out uint coarseMask, out uint fineMask, out bool inside, out int2 ab, out int2 abUp)
{
    uint m = TileCountInt();
    uint level = LodLevelOfPatch(drawPatch, m), slot = LodSlotOfPatch(drawPatch, m);
    int2 tile = int2(slot % m, slot / m);
    coarseMask = 0u;
    fineMask = 0u;
    inside = false;
    ab = int2(0, 0);
    abUp = int2(0, 0);
    if (level > 0u)
    {
        ab = FinerOffsetCells(LodRange(level), LodRange(level - 1u), TileCount());
        inside = TileInsideFiner(tile, ab, (int)m);
        coarseMask = CoarseSeamEdges(tile, ab, (int)m);
    }
    if (level + 1u < LodLevelCount())
    {
        abUp = FinerOffsetCells(LodRange(level + 1u), LodRange(level), TileCount());
        fineMask = FineSeamEdges(tile, abUp, (int)m);
    }
}

// The factor of edge `edge` (0..3) of the coarse tile across a fine seam edge: what that coarse
// tile's hull computes for it (the same function of the same inputs), uniform or adaptive.
float CoarseSeamEdgeFactor(uint drawPatch, uint edgeBit, int2 abUp)
{
    if (UsesUniformTessFactor()) return UniformTessFactor();
    uint m = TileCountInt();
    uint level = LodLevelOfPatch(drawPatch, m), slot = LodSlotOfPatch(drawPatch, m);
    uint coarseEdge;
    int upperHalf;
    int2 coarseTile = FineSeamCoarseTile(edgeBit, int2(slot % m, slot / m), abUp, coarseEdge, upperHalf);
    uint coarseSlot = (uint)coarseTile.y * m + (uint)coarseTile.x;
    TileLayout coarse = LodLevelLayout(level + 1u);
    float3 cornerOS[4];
    [unroll] for (uint c = 0; c < 4; c++)
        cornerOS[c] = CellCornerObjectPosition(coarse, coarseSlot, c);
    uint piece = coarseEdge == GT_EDGE_U0 ? 0u : (coarseEdge == GT_EDGE_V0 ? 1u : (coarseEdge == GT_EDGE_U1 ? 2u : 3u));
    return max(TileFactorPiece(coarse, coarseSlot, piece, cornerOS), 1.0);
}

// The seam rule on a tile's factors: tiles inside the finer level culled; a coarse seam edge of
// factor f draws 2g, each fine one g, g = SeamHalfFactor of the coarse edge's factor.
TileFactorSet LodTileFactors(uint drawPatch, TileFactorSet set)
{
    uint coarseMask, fineMask;
    bool inside;
    int2 ab, abUp;
    LodTileSeams(drawPatch, coarseMask, fineMask, inside, ab, abUp);
    if (inside) return CulledTileFactors();
    if (TileFactorsCulled(set)) return set;
    float edge[4] = { set.edge.x, set.edge.y, set.edge.z, set.edge.w };
    [unroll] for (uint i = 0u; i < 4u; i++)
    {
        uint bit = 1u << i;
        if ((coarseMask & bit) != 0u) edge[i] = 2.0 * SeamHalfFactor(edge[i], MaxTessFactor());
        else if ((fineMask & bit) != 0u) edge[i] = SeamHalfFactor(CoarseSeamEdgeFactor(drawPatch, bit, abUp), MaxTessFactor());
    }
    set.edge = float4(edge[0], edge[1], edge[2], edge[3]);
    return set;
}

// The domain stage's vertex: a seam vertex's q is the coarse tile's point (SeamCoarsePoint), formed
// alike on both sides; any other vertex its tile's own point.
TerrainVaryings LodDomainVertex(uint drawPatch, float2 tess, float4 edgeFactors, float tessFactor)
{
    uint slot;
    TileLayout l = StageTileLayout(drawPatch, slot);
    uint m = TileCountInt();
    uint level = LodLevelOfPatch(drawPatch, m);
    int2 tile = int2(slot % m, slot / m);
    uint coarseMask, fineMask;
    bool inside;
    int2 ab, abUp;
    LodTileSeams(drawPatch, coarseMask, fineMask, inside, ab, abUp);
    TerrainPoint q = TileToTerrainPoint(l, slot, tess);
    uint coarseEdge = SeamEdgeAt(coarseMask, tess), fineEdge = SeamEdgeAt(fineMask, tess);
    float factors[4] = { edgeFactors.x, edgeFactors.y, edgeFactors.z, edgeFactors.w };
    if (coarseEdge != 0u)
        q = SeamCoarsePoint(false, coarseEdge, tess, 0.5 * factors[firstbitlow(coarseEdge)], tile, l.range, l.range, ab, l.origin, TileCount());
    else if (fineEdge != 0u)
        q = SeamCoarsePoint(true, fineEdge, tess, factors[firstbitlow(fineEdge)], tile, l.range, LodRange(level + 1u), abUp, l.origin, TileCount());
    return TerrainVertexAtPoint(l, drawPatch, tess, q, tessFactor);
}
#endif

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

#if defined(GT_VERTEX_CACHE)
// The cell's factors, decided by CacheTileFactors, already integers (culled: all 0): what its
// slots hold. hull_const clips them to the part of the cell the tile keeps; the domain stage reads
// them again for a clipped tile's records.
TileFactorSet CachedCellFactors(uint patch)
{
    TileFactorSet set;
    set.edge = _TileFactors[VertexCacheFactorIndex(patch)];
    set.inside = _TileFactors[VertexCacheFactorIndex(patch) + 1u].xy;
    return set;
}
#endif

TileFactorSet TileFactorsOf(InputPatch<TileCorner, 4> corners)
{
    uint patch = corners[0].drawPatch;
    TileFactorSet set;
#if defined(GT_VERTEX_CACHE)
    set = CachedCellFactors(patch);
#else
    float3 cornerOS[4];
    [unroll] for (uint c = 0; c < 4; c++)
        cornerOS[c] = corners[c].positionOS;
    uint slot;
    TileLayout l = StageTileLayout(patch, slot);
    set = ComputeTileFactors(l, slot, cornerOS);
    #if defined(GT_LOD)
    set = LodTileFactors(patch, set);
    #endif
#endif
    return set;
}

TileFactors hull_const(InputPatch<TileCorner, 4> corners)
{
#if defined(GT_VERTEX_CACHE)
    // Anchored, the cache holds the tile's whole cell: draw the part of it the tile keeps
    // (ClippedCell.hlsl), and tell the domain stage which part that is.
    float4 kept = TileKeptCellSpan(FrameTileLayout(), corners[0].drawPatch);
    TileFactors f = ToTileFactors(ClippedTileFactors(TileFactorsOf(corners), kept));
    f.keptCellSpan = kept;
#else
    TileFactors f = ToTileFactors(TileFactorsOf(corners));
#endif
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
#if defined(GT_VERTEX_CACHE)
    // The compute pass evaluated this vertex into its slot: only the camera transform is left.
    float4 edge = float4(factors.edge[0], factors.edge[1], factors.edge[2], factors.edge[3]);
    float2 inside = float2(factors.inside[0], factors.inside[1]);
    uint limit = VertexCacheFactorLimit();
    uint base = corners[0].drawPatch * VertexCacheSlotsPerTile(limit);
    if (!CellKeptWhole(factors.keptCellSpan))
    {
        TileFactorSet tile;
        tile.edge = edge;
        tile.inside = inside;
        TileFactorSet cell = CachedCellFactors(corners[0].drawPatch);
        return CachedCellPointVaryings(base, CellPoint(tess, tile, cell, factors.keptCellSpan, limit), tessFactor);
    }
    return CachedTerrainVaryings(base + VertexCacheSlot(tess, edge, inside, limit), tessFactor);
#elif defined(GT_LOD)
    return LodDomainVertex(corners[0].drawPatch, tess, float4(factors.edge[0], factors.edge[1], factors.edge[2], factors.edge[3]), tessFactor);
#else
    return TerrainVertex(FrameTileLayout(), corners[0].drawPatch, tess, tessFactor);
#endif
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
#else
float4 frag(TerrainVaryings i) : SV_Target
{
    return TerrainFragmentColor(i);
}
#endif

#endif // GT_TERRAIN_STAGES_INCLUDED
