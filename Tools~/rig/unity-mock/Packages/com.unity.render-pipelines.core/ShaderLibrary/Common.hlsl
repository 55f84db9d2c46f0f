// MOCK (Tools~/rig/unity-mock/README.md): not SRP Core's Common.hlsl.
#ifndef GT_MOCK_SRP_COMMON
#define GT_MOCK_SRP_COMMON
#define CBUFFER_START(name) cbuffer name {
#define CBUFFER_END };
#endif
