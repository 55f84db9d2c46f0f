// What every pass of a tessellated SubShader of GregoryTerrain.shader compiles with: its HLSLINCLUDE
// reads this file with #include_with_pragmas, so these pragmas are each pass's own. Hull and domain
// stages (a device without tessellation hardware skips the SubShader for the next, the fallback) and
// the package's keywords that change the shape or where it comes from (a pass adds only its own).
// The material's toggles are shader_feature_local. Those a script switches at run time are
// multi_compile_local, so a player build keeps them though no saved material has them on: GT_SNOW
// (SnowSimulator) and where the vertices come from: GT_RANGE_ORIGIN (the deep-zoom code, while the
// renderer sends an origin), GT_LOD (the renderer's levels) or GT_VERTEX_CACHE (the domain stage
// reads the vertices TerrainCache.compute evaluated). The levels and the cache compile the origin's
// code too and never draw together, so one set: at most one is on
// (RelativeSurface.NeedsRangeOriginKeyword) and no combination is compiled that is never drawn.
#pragma target 4.6
#pragma require tessellation tessHW
#pragma vertex vert
#pragma hull hull_shader
#pragma domain domain_shader
#pragma fragment frag
#pragma shader_feature_local GT_NOISE
#pragma shader_feature_local GT_NOISE_TABLE
#pragma multi_compile_local _ GT_SNOW
#pragma multi_compile_local _ GT_RANGE_ORIGIN GT_LOD GT_VERTEX_CACHE
