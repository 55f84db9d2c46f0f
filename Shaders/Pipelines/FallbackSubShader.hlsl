// The stages of every pass of a fallback SubShader of GregoryTerrain.shader: its HLSLINCLUDE reads this
// file with #include_with_pragmas, so these pragmas are each pass's own. No tessellator: each tile an
// instanced (F+1)^2 UV grid evaluated in the vertex stage. The package's keywords are Core's
// ShaderKeywords, generated into ShaderKeywords.Fallback.cs.hlsl (read next): not the vertex source's
// set, as there is no hull or domain stage to feed, and GT_FALLBACK keeps the range origin's run-time branch.
#pragma target 4.5
#pragma vertex vert_fallback
#pragma fragment frag
#define GT_FALLBACK 1
