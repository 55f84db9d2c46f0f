#ifndef GT_HARNESS_TEST_COMMON_INCLUDED
#define GT_HARNESS_TEST_COMMON_INCLUDED
// Test-only declarations matching Tools~/rig/README.md "Descriptor bindings".
// The harness self-test uses these shaders to prove the harness (bindings, split draws,
// readback, stats); they are not the package's shaders.

// The package's TerrainParams block: its generated members (Core's TerrainParams declares them).
cbuffer TerrainParams : register(b0)
{
#include "../../../Shaders/Terrain/TerrainParams.cs.hlsl"
};

cbuffer RigCamera : register(b1)
{
    float4x4 _RigObjectToClip;
    float4x4 _RigObjectToWorld;
    float4 _RigCameraPosition;
    float4 _RigScreenSize;
    float4 _RigLightDirection;
};

// The package's patch record (Core's GregoryPatchRecord, generated): 20 float4, stride 320.
#include "../../../Shaders/Terrain/GregoryPatchRecord.cs.hlsl"
StructuredBuffer<GregoryPatchRecord> _ControlPoints : register(t0);
// Float4 i of the control points read as one array (the tests fill it float4 by float4).
float4 ControlPointFloat4(uint i) { return _ControlPoints[i / 20u].points[i % 20u]; }
StructuredBuffer<float4> _Regions : register(t1);
StructuredBuffer<float> _GridLines : register(t2);
#ifdef GT_READBACK
RWStructuredBuffer<float4> _Readback : register(u0);
#endif
#endif
