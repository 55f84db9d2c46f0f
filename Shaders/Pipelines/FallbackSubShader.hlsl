// What every pass of a fallback SubShader of GregoryTerrain.shader compiles with: its HLSLINCLUDE
// reads this file with #include_with_pragmas, so these pragmas are each pass's own. No tessellator:
// each tile an instanced (F+1)^2 UV grid evaluated in the vertex stage. The keywords of
// TessellatedSubShader.hlsl but the vertex source's set: there is no hull or domain stage to feed,
// and GT_FALLBACK keeps the range origin's run-time branch.
#pragma target 4.5
#pragma vertex vert_fallback
#pragma fragment frag
#pragma shader_feature_local GT_NOISE
#pragma shader_feature_local GT_NOISE_TABLE
#pragma multi_compile_local _ GT_SNOW
#define GT_FALLBACK 1
