// Entry file the off-Unity rig compiles (Tools~/rig/shaders.sh, gt bench, the GPU tests): the
// standalone adapter, then the product's pipeline-agnostic stages, unchanged. Entry points: vert,
// hull_shader, domain_shader, frag, vert_fallback; GT_VERTEX_CACHE adds the cache's kernels
// (CacheTileFactors, CacheTileVertices), GT_STATIC_MESH adds vert_static.
//
// The rig-only keywords live here and nowhere under Shaders/ (RigKeywordTests checks it; the list
// is RigKeywords.RigOnly in Tools~/RigTests). Each turns on one of the product's neutral extension
// points (internals.md, "Extension points") and defines the function it declares:
//   GT_PAPER_MODE        GT_EXTEND_DRAW_PATCHES: draw patches are Gregory patches over the whole range
//   GT_READBACK          GT_EXTEND_VERTEX: every vertex to _Readback; integer partitioning
//   GT_FACTOR_READBACK   GT_EXTEND_TILE_FACTORS: every patch's factors to _Readback
//   GT_STATIC_MESH       vert_static, the fair static mesh of gt bench
#ifndef GT_TERRAIN_RIG_INCLUDED
#define GT_TERRAIN_RIG_INCLUDED

#if defined(GT_VERTEX_CACHE) && (defined(GT_PAPER_MODE) || defined(GT_READBACK) || defined(GT_FACTOR_READBACK))
    #error "GT_VERTEX_CACHE draws tiles from the cache: no paper mode, and the cache itself is the readback"
#endif
#if defined(GT_PAPER_MODE)
    #define GT_EXTEND_DRAW_PATCHES
#endif
#if defined(GT_READBACK)
    #define GT_EXTEND_VERTEX
    // The readback indexes vertices as an (F+1) x (F+1) grid: only integer partitioning makes those.
    #define GT_PARTITIONING "integer"
#endif
#if defined(GT_FACTOR_READBACK)
    // Partitioning stays the product's fractional_odd: these are the factors the shipped shader uses.
    #define GT_EXTEND_TILE_FACTORS
#endif

#include "../../Shaders/Pipelines/StandaloneAdapter.hlsl"
#include "../../Shaders/Pipelines/TerrainStages.hlsl"
#if defined(GT_VERTEX_CACHE)
    #include "../../Shaders/Cache/VertexCacheKernels.hlsl"   // entry points CacheTileFactors, CacheTileVertices
#elif defined(GT_LOD)
    #include "../../Shaders/Cache/LevelFactorKernels.hlsl"   // entry points LodFactorPieces, LodFactorSeams
    #include "../../Shaders/Cache/LevelVertexCacheKernels.hlsl"   // entry points LodVertexSlots, LodCacheVertices
#endif

#if defined(GT_READBACK) || defined(GT_FACTOR_READBACK)
// Tools~/rig/README.md, "Rig-only readback".
RWStructuredBuffer<float4> _Readback GT_REGISTER(u0);
#endif

#if defined(GT_PAPER_MODE)
// The paper's method: every Gregory patch is tessellated over the whole range (one "tile"), with
// the corrected eq. 10 and u, v clamped, so the part outside the patch collapses onto its boundary.
// drawPatch is the Gregory patch. Core's mirror: TerrainVertex.Evaluate with paper mode on.
TerrainSurfacePoint ExtensionSurface(uint drawPatch, float2 tess)
{
    TerrainSurfacePoint s;
    s.q = RangeToTerrainPoint(_Range, _RangeOrigin, 1.0, uint2(0, 0), tess);
    s.patch = drawPatch;
    s.region = PatchRegion(s.patch);
    s.regionLo = PatchRegionLo(s.patch);
    s.uv = saturate(PatchLocalUV(s.q, s.region, s.regionLo));
    float3 cp[20];
    LoadGregoryPatch(s.patch, cp);
    float3 relative;
    GregoryEvaluate(cp, s.uv, relative, s.dPdu, s.dPdv);
    s.position = PatchReference(s.patch) + relative;
    return s;
}

// A clamped vertex sits on the patch boundary, so it takes the noise of that boundary point.
TerrainPoint ExtensionNoisePoint(TerrainSurfacePoint s)
{
    TerrainPoint noisePoint = s.q;
    if (any(s.uv != PatchLocalUV(s.q, s.region, s.regionLo)))
    {
        noisePoint.originHi = float2(0.0, 0.0);
        noisePoint.local = lerp(s.region.xy, s.region.zw, s.uv);
    }
    return noisePoint;
}

// The snow map is read at the patch point the vertex collapsed onto.
float2 ExtensionSnowPoint(TerrainSurfacePoint s)
{
    return lerp(s.region.xy, s.region.zw, s.uv);
}
#endif

#if defined(GT_READBACK)
// 3 float4 per vertex at the index of an integer uniform factor F. The domain stage may run more
// than once per vertex; it writes the same values.
void ExtensionVertex(uint drawPatch, float2 tess, TerrainSurfacePoint s, TerrainVertexAttributes a)
{
    uint f = (uint)UniformTessFactor();
    uint2 grid = (uint2)round(tess * (float)f);
    uint vertex = drawPatch * (f + 1) * (f + 1) + grid.y * (f + 1) + grid.x;
    _Readback[3 * vertex + 0] = float4(a.positionOS, 1.0);
    _Readback[3 * vertex + 1] = float4(a.normalOS, 0.0);
    _Readback[3 * vertex + 2] = float4(TerrainPointApprox(s.q), s.uv);
}
#endif

#if defined(GT_FACTOR_READBACK)
// 2 float4 per patch: (edge[0..3]), (inside[0..1], culled 1/0, 0).
void ExtensionTileFactors(uint drawPatch, TileFactors f)
{
    _Readback[2 * drawPatch + 0] = float4(f.edge[0], f.edge[1], f.edge[2], f.edge[3]);
    _Readback[2 * drawPatch + 1] = float4(f.inside[0], f.inside[1], f.edge[0] == 0.0 ? 1.0 : 0.0, 0.0);
}
#endif

#if defined(GT_STATIC_MESH)
// gt bench, "the fair static mesh": the terrain baked into the static mesh a user could draw
// instead, drawn with the same frag. Per vertex 2 float4, (object position, 1), (object normal, 0)
// (Tools~/rig/bench_static_mesh.py packs them from the GT_READBACK vertices of M x M tiles at the
// uniform factor F = _Tess.w), read from the _ControlPoints binding through the fallback grid's
// index buffer: vertex = instance (F+1)^2 + SV_VertexID. Nothing is evaluated.
TerrainVaryings vert_static(uint vertexID : SV_VertexID, uint instanceID : SV_InstanceID)
{
    uint f = max((uint)UniformTessFactor(), 1u);
    uint v = instanceID * (f + 1u) * (f + 1u) + vertexID;
    TerrainVaryings o = (TerrainVaryings)0;
    // Float4s 2v and 2v + 1 of the records read as one array: both in record v / 10 (20 is even).
    // Indexed in place, never copied: a local copy indexed by k could spill the whole record.
    uint r = v / 10u;
    uint k = 2u * (v % 10u);
    o.positionCS = GT_ObjectToClip(_ControlPoints[r].points[k].xyz);
    // The baked height (object y; the benchmark draws no range origin) and no colour noise: the frag
    // does the same work, the vertex stage less than the terrain's.
    float heightWeight = TerrainHeightWeight(_ControlPoints[r].points[k].y, 0.0);
    o.normalAndHeightWeight = PackNormalAndHeightWeight(GT_ObjectToWorldNormal(_ControlPoints[r].points[k + 1u].xyz), heightWeight);
    return o;
}
#endif

#endif // GT_TERRAIN_RIG_INCLUDED
