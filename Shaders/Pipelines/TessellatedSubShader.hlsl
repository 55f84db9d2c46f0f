// The stages of every pass of a tessellated SubShader of GregoryTerrain.shader: its HLSLINCLUDE reads
// this file with #include_with_pragmas, so these pragmas are each pass's own. Hull and domain stages (a
// device without tessellation hardware skips the SubShader for the next, the fallback). The package's
// keywords are Core's ShaderKeywords, generated into ShaderKeywords.Tessellated.cs.hlsl (read next).
#pragma target 4.6
#pragma require tessellation tessHW
#pragma vertex vert
#pragma hull hull_shader
#pragma domain domain_shader
#pragma fragment frag
