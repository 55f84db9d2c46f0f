// Probe (TessellationViewTests, through Tools~/rig/shaderreads.py): the two places that turn a view
// into tessellation, the factors' pixel scale (ObjectPixelsPerUnit) and a vertex's octave count
// (VertexOctaveCount, the levels' continuous rule), compiled with one pipeline's adapter as one of
// its passes would (define PROBE_URP, PROBE_HDRP or PROBE_BUILTIN and one GT_PASS_*, with GT_NOISE
// and GT_RANGE_ORIGIN so that the octave rule is compiled), as a vertex stage: a graphics stage like
// the hull and domain stages that run them (a compute compile takes HDRP's XR paths). The entry
// returns nothing else, so what its optimised code reads is what those two read.
#if defined(PROBE_URP)
    #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/URPAdapter.hlsl"
#elif defined(PROBE_HDRP)
    #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/HDRPAdapter.hlsl"
#elif defined(PROBE_BUILTIN)
    #include "Packages/com.gregoryterrain.tessellation/Shaders/Pipelines/BuiltinAdapter.hlsl"
#else
    #error "define PROBE_URP, PROBE_HDRP or PROBE_BUILTIN"
#endif
#include "Packages/com.gregoryterrain.tessellation/Shaders/Terrain/TileFactors.hlsl"

float4 TessellationViewProbe(uint id : SV_VertexID) : SV_Position
{
    float4 v = asfloat(uint4(id, id * 3u, id * 5u, id * 7u));   // unknown to the compiler: nothing folds away
    TerrainSurfacePoint s;
    s.q = MakeTerrainPoint(v.xy, v.zw);
    s.patch = id;
    s.region = v;
    s.regionLo = v;
    s.uv = v.xy;
    s.position = v.xyz;
    s.dPdu = v.yzw;
    s.dPdv = v.zwx;
    TileLayout l = MakeTileLayout(v, v.wzyx, float4(0.0, 0.0, 0.0, 0.0), v.x);
    return float4(ObjectPixelsPerUnit(v.xyz), VertexOctaveCount(l, s), 0.0, 1.0);
}
