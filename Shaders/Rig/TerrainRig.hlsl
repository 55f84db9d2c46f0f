// Entry file the off-Unity rig compiles (Tools~/rig/shaders.sh): the standalone adapter, then the
// pipeline-agnostic stages. Entry points: vert, hull_shader, domain_shader, frag, vert_fallback.
#ifndef GT_TERRAIN_RIG_INCLUDED
#define GT_TERRAIN_RIG_INCLUDED
#include "../Pipelines/StandaloneAdapter.hlsl"
#include "../Pipelines/TerrainStages.hlsl"
#if defined(GT_VERTEX_CACHE)
    #include "../Cache/VertexCacheKernels.hlsl"   // entry points CacheTileFactors, CacheTileVertices
#endif
#endif
