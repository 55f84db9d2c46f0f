// The vertex cache's layout (GT_VERTEX_CACHE; Documentation~/internals.md, "Vertex cache"): where
// each vertex the tessellator makes at a tile's integer factors is stored, and how a record packs a
// TerrainVertexAttributes. Written by VertexCacheKernels.hlsl (compute), read by the domain stage.
// Mirrors Runtime/Core/Cache/VertexCache.cs name for name.
//
// Why integer factors: with "integer" partitioning the tessellator puts a factor-F edge's vertices at
// exactly k / F and the inside grid at (i / Iu, j / Iv), so every vertex has a slot known in advance
// and the compute pass can evaluate it before the draw.
#ifndef GT_VERTEX_CACHE_INCLUDED
#define GT_VERTEX_CACHE_INCLUDED

#include "../Terrain/TerrainVertex.hlsl"
#include "../Terrain/TileFactors.hlsl"

// Hardware limit of a tessellation factor (Vulkan maxTessellationGenerationLevel >= 64, D3D 64).
#define GT_VERTEX_CACHE_MAX_FACTOR 64.0

#if defined(GT_SNOW)
    #define GT_VERTEX_CACHE_RECORD_UINT4S 2u
#else
    #define GT_VERTEX_CACHE_RECORD_UINT4S 1u
#endif

// L: the largest integer factor this frame's settings can produce: the uniform factor when set,
// else the maximum factor; slots are reserved for it.
uint VertexCacheFactorLimit()
{
    float f = UsesUniformTessFactor() ? UniformTessFactor() : MaxTessFactor();
    return (uint)clamp(ceil(f), 1.0, GT_VERTEX_CACHE_MAX_FACTOR);
}

// (L + 1)^2 slots of the inside grid, then 4 edges of L + 1.
uint VertexCacheSlotsPerTile(uint limit) { return (limit + 1u) * (limit + 1u) + 4u * (limit + 1u); }

// Lanes of a CacheTileFactors group (a group a tile, a lane for each of its GT_TILE_FACTOR_SAMPLES);
// lanes of a CacheTileVertices group, and the most passes it makes over its tile's points (why 128 x 4:
// Tools~/bench/records.md, "Choices in the shaders, measured").
#define GT_VERTEX_CACHE_GROUP 64u
#define GT_VERTEX_CACHE_VERTEX_GROUP 128u
#define GT_VERTEX_CACHE_PASSES 4u

// The most points a tile at factors <= L has: anchored, its cell's whole (L + 1)^2 grid (the
// border too: ClippedCell.hlsl blends a clipped tile's edge from it) and 4 edges of L + 1.
uint VertexCacheMaxTilePoints(uint limit) { return (limit + 1u) * (limit + 1u) + 4u * (limit + 1u); }

// Groups that share one tile's points (dispatch z): with one group a tile the pass lasts as long as
// its largest tile while most units idle.
uint VertexCacheGroupsPerTile(uint limit)
{
    uint perGroup = GT_VERTEX_CACHE_VERTEX_GROUP * GT_VERTEX_CACHE_PASSES;
    return (VertexCacheMaxTilePoints(limit) + perGroup - 1u) / perGroup;
}

// _TileFactors: a TileFactorRecord a tile (T x T tiles, T = TilesAcrossInt(): M, or M + 1
// anchored), the draw's factors and the keys its slots and cell were written at (CellRecordKey),
// which the renderer zeroes together. _TileCells: a TileCellRecord a tile, the cell's samples (a
// camera move evaluates no surface) and float factors with their FactorInput (an anchored pan, the
// camera still, evaluates nothing). Two buffers: that upload is 64 bytes a tile (a whole record; the keys alone would be 32), not 992. A tile
// whose factors and slot key its slots hold keeps them (a camera move that leaves its integer
// factors alone; anchored, a pan that leaves the tile whole).
#define GT_FACTOR_INPUTS 5u

// Inside grid point (i, j) of a tile whose inside factor along u is insideU.
uint VertexCacheInteriorSlot(uint2 ij, uint insideU) { return ij.x + ij.y * (insideU + 1u); }

// Point k (from the edge's lower tess coordinate) of edge e (0: u = 0, 1: v = 0, 2: u = 1, 3: v = 1).
uint VertexCacheEdgeSlot(uint edge, uint k, uint limit)
{
    return (limit + 1u) * (limit + 1u) + edge * (limit + 1u) + k;
}

// Tess coordinate of point k of edge e at factor f.
float2 VertexCacheEdgeTess(uint edge, uint k, float f)
{
    float s = (float)k / f;
    if (edge == 0u) return float2(0.0, s);
    if (edge == 1u) return float2(s, 0.0);
    if (edge == 2u) return float2(1.0, s);
    return float2(s, 1.0);
}

// The slot (within its tile) of the vertex the tessellator put at tess. Edge vertices have a tess
// coordinate of exactly 0 or 1 (the tessellator guarantees it: that is what keeps tiles watertight);
// inside vertices never do. round() absorbs a fixed-point tessellator's error (far below 1 / (2 * 64)).
uint VertexCacheSlot(float2 tess, float4 edge, float2 inside, uint limit)
{
    if (tess.x == 0.0) return VertexCacheEdgeSlot(0u, (uint)round(tess.y * edge.x), limit);
    if (tess.y == 0.0) return VertexCacheEdgeSlot(1u, (uint)round(tess.x * edge.y), limit);
    if (tess.x == 1.0) return VertexCacheEdgeSlot(2u, (uint)round(tess.y * edge.z), limit);
    if (tess.y == 1.0) return VertexCacheEdgeSlot(3u, (uint)round(tess.x * edge.w), limit);
    return VertexCacheInteriorSlot((uint2)round(tess * inside), (uint)inside.x);
}

// Integer factors as the tessellator draws them: an inside factor of 1 is 2 unless all six are 1
// (Vulkan spec, quad tessellation; D3D11 likewise), and the slot grid must be the one it draws.
TileFactorSet VertexCacheDrawnFactors(TileFactorSet f)
{
    bool allOnes = all(f.edge == 1.0) && all(f.inside == 1.0);
    if (!allOnes) f.inside = max(f.inside, 2.0);
    return f;
}

// The factors the cache is built for: each rounded up to an integer (the segments of "integer"
// partitioning; rounding up keeps the error bound of the fractional factor), as drawn
// (VertexCacheDrawnFactors). Culled (all 0) stays 0.
TileFactorSet VertexCacheIntegerFactors(TileFactorSet f)
{
    if (TileFactorsCulled(f)) return f;
    f.edge = ceil(clamp(f.edge, 1.0, GT_VERTEX_CACHE_MAX_FACTOR));
    f.inside = ceil(clamp(f.inside, 1.0, GT_VERTEX_CACHE_MAX_FACTOR));
    return VertexCacheDrawnFactors(f);
}

// The fragment's one interpolant (TerrainVaryings.normalAndHeightWeight: the Lambert-encoded world
// normal e, |e| <= 2, and the height weight s in [0, 1]) in 32 bits: 11 bits for each of e.x and
// e.y, in steps of 2 / 1023 with 0 exact (a flat terrain stays flat), and 10 bits for s, in steps of
// 1 / 1023: a 16-byte record instead of 32 (the cost: internals.md, "Vertex cache"). Positions are
// never packed: shared edge vertices must stay bit-identical (no cracks), and deep zoom needs their float.
uint PackCachedVaryings(float3 normalAndHeightWeight)
{
    float2 e = round(clamp(normalAndHeightWeight.xy, -2.0, 2.0) * 511.5) + 1023.0;   // 0 .. 2046
    float s = round(saturate(normalAndHeightWeight.z) * 1023.0);                     // 0 .. 1023
    return (uint)e.x | ((uint)e.y << 11u) | ((uint)s << 22u);
}

float3 UnpackCachedVaryings(uint bits)
{
    float2 e = float2(bits & 2047u, (bits >> 11u) & 2047u) - 1023.0;
    return float3(e * (2.0 / 1023.0), (float)(bits >> 22u) * (1.0 / 1023.0));
}

// Record = GT_VERTEX_CACHE_RECORD_UINT4S uint4: (positionOS bits, PackCachedVaryings), [GT_SNOW:
// (snowDepth bits, 0, 0, 0)]. The kernel computes what the fragment needs (the world normal through
// the adapter's GT_ObjectToWorldNormal, encoded; the height weight), so the domain stage only
// projects the position. uint4, not float4: the packed word is any bit pattern, NaNs included, and
// integer loads and stores keep every bit. 16 bytes: the cached draw's cost is its reads
// (Tools~/bench/records.md, "Choices in the shaders, measured"). The patch index is not kept (the
// GT_DEBUG_PATCH_ID view finds it in the domain stage).
uint4 VertexCacheRecordPart(TerrainVertexAttributes a, uint part)
{
    if (part == 0u)
        return uint4(asuint(a.positionOS), PackCachedVaryings(TerrainNormalAndHeightWeight(a, GT_ObjectToWorldNormal(a.normalOS))));
    return uint4(asuint(a.snowDepth), 0u, 0u, 0u);
}

#if defined(GT_VERTEX_CACHE) || defined(GT_LOD)
// The varyings of a slot's record (tile base included): what the domain stage returns.
TerrainVaryings CachedTerrainVaryings(uint slot, float tessFactor)
{
    uint i = GT_VERTEX_CACHE_RECORD_UINT4S * slot;
    uint4 r = _VertexCache[i];
    #if defined(GT_SNOW)
    float snowDepth = asfloat(_VertexCache[i + 1u].x);
    #else
    float snowDepth = 0.0;
    #endif
    return TerrainVaryingsOf(asfloat(r.xyz), UnpackCachedVaryings(r.w), snowDepth, 0u, tessFactor);
}
#endif

#endif // GT_VERTEX_CACHE_INCLUDED
