// Rig only, never shipped (issue 38, a vertex cache for the Horizon levels, measured before it is
// built): the levels' draw with a domain stage that reads prepared vertices instead of evaluating
// them, the draw cost a cache of the levels would have (a lower bound: the records are the
// harness's zero-filled storage, so the picture is the flat floor's). Compiled with GT_LOD GT_NOISE
// GT_HEIGHT_COLOR (Tools~/rig/lod_cache_ab.py says how), entry points:
//   domain_cached        one 16-byte record a vertex (the single-range cache's: position bits, packed
//                        normal and height weight) at the record LevelVertexCacheRecord gives
//                        (the tile's own slot rule), as VertexSource.Cache.hlsl reads it
//   domain_cached_blend  two records a vertex: the first as above (the position with the octaves
//                        every camera on the tile's key draws), the second the octave window's
//                        heights and slopes (two octaves, as halves) faded in with the
//                        continuous octave rule at the vertex's pixel scale, as a cache that keeps
//                        the rule continuous would
//   domain_cached_switch domain_cached behind a uniform branch (levels L > 0, true in every levels job)
//                        beside the levels' own full domain stage: what one GT_LOD variant holding both
//                        paths costs (the unused path's registers) against a variant of its own
// The record is added to the floor's flat position, so the fetch stays in the program; the factors
// are rounded up as the cache's integer factors are. Binding: t6 (rig binding 8), S(LOD_CACHE_LIMIT) records a tile.
#include "TerrainRig.hlsl"
#include "../../Shaders/Cache/LevelVertexCache.hlsl"

// The records: the product's _VertexCache (t6), which GT_LOD declares for its own cache.

#ifndef LOD_CACHE_LIMIT
    #define LOD_CACHE_LIMIT 64u   // slots for the largest factor (lod_cache_ab.py sizes the buffer for it)
#endif

float3 FlatPosition(const OutputPatch<TileCorner, 4> corners, float2 tess)
{
    float3 low = lerp(corners[0].positionOS, corners[1].positionOS, tess.x);
    float3 high = lerp(corners[2].positionOS, corners[3].positionOS, tess.x);
    return lerp(low, high, tess.y);
}

// The single range's fixed S(L) a tile (the compact layout's largest block for every tile: its
// records are spread no less than the compact layout's).
uint LevelCacheSlot(TileFactors factors, uint drawPatch, float2 tess)
{
    TileFactorSet f;
    f.edge = ceil(float4(factors.edge[0], factors.edge[1], factors.edge[2], factors.edge[3]));
    f.inside = ceil(float2(factors.inside[0], factors.inside[1]));
    return LevelVertexCacheRecord(drawPatch * VertexCacheSlotsPerTile(LOD_CACHE_LIMIT), tess, f);
}

TerrainVaryings CachedVaryings(TileFactors factors, const OutputPatch<TileCorner, 4> corners, float2 tess)
{
    uint4 r = _VertexCache[LevelCacheSlot(factors, corners[0].drawPatch, tess)];
    float3 positionOS = FlatPosition(corners, tess) + asfloat(r.xyz);
    return TerrainVaryingsOf(positionOS, UnpackCachedVaryings(r.w), 0.0, 0u, max(factors.inside[0], factors.inside[1]));
}

[domain("quad")]
TerrainVaryings domain_cached(TileFactors factors, const OutputPatch<TileCorner, 4> corners,
                              float2 tess : SV_DomainLocation)
{
    return CachedVaryings(factors, corners, tess);
}

[domain("quad")]
TerrainVaryings domain_cached_switch(TileFactors factors, const OutputPatch<TileCorner, 4> corners,
                                     float2 tess : SV_DomainLocation)
{
    if (LodLevelCount() > 0u) return CachedVaryings(factors, corners, tess);
    return domain_shader(factors, corners, tess);
}

[domain("quad")]
TerrainVaryings domain_cached_blend(TileFactors factors, const OutputPatch<TileCorner, 4> corners,
                                    float2 tess : SV_DomainLocation)
{
    uint slot = 2u * LevelCacheSlot(factors, corners[0].drawPatch, tess);
    uint4 r = _VertexCache[slot];
    uint4 w = _VertexCache[slot + 1u];   // (the two window octaves' heights, slopes of the first, of the second, the first's index): halves
    float3 positionOS = FlatPosition(corners, tess) + asfloat(r.xyz);
    float3 surface = TerrainToObject(positionOS);   // object (x, height, y) -> terrain space, as the rule reads it
    float count = OctaveCountAtPixelScale(SurfacePixelScale(surface), NoiseSegmentPixels(), NoiseSettings(), MaxNoiseOctaves());
    float2 fade = saturate(count - ((float)w.w + float2(0.0, 1.0)));
    float2 heights = f16tof32(uint2(w.x, w.x >> 16u));
    float2 slope0 = f16tof32(uint2(w.y, w.y >> 16u)), slope1 = f16tof32(uint2(w.z, w.z >> 16u));
    positionOS.y += dot(fade, heights);
    float3 shading = UnpackCachedVaryings(r.w);
    shading.xy += fade.x * slope0 + fade.y * slope1;
    return TerrainVaryingsOf(positionOS, shading, 0.0, 0u, max(factors.inside[0], factors.inside[1]));
}
