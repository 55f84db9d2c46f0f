// MOCK (Tools~/rig/unity-mock/README.md): not Unity's HLSLSupport.cginc. Only what the adapter uses.
#ifndef GT_MOCK_HLSL_SUPPORT
#define GT_MOCK_HLSL_SUPPORT
#define CBUFFER_START(name) cbuffer name {
#define CBUFFER_END };
#endif
