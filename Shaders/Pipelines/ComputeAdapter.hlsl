// Compute adapter: the terrain's evaluation path in a compute shader (SnowField.compute), where
// there is no camera and no light. It implements the adapter interface of StandaloneAdapter.hlsl
// with terrain-to-itself transforms, so what TerrainVertex returns is the terrain-space vertex:
//   positionCS = (object position, 1)   (object = terrain (x, z, y): Unity is Y-up)
//   normalWS   = object normal, as computed (already unit length)
// Material constants are a plain cbuffer at b0; resources keep their registers (the rig compiles
// with the terrain stages' shifts: internals.md, "Snow"). Unity binds by name and ignores both.
#ifndef GT_COMPUTE_ADAPTER_INCLUDED
#define GT_COMPUTE_ADAPTER_INCLUDED

#define GT_ADAPTER_COMPUTE 1
#define GT_CBUFFER_START(name) cbuffer name : register(b0) {
#define GT_CBUFFER_END };
#define GT_REGISTER(r) : register(r)

// The camera: none here; LodCameraComputeAdapter.hlsl defines GT_COMPUTE_CAMERA and its own three
// functions before it includes this file for the rest.
#ifndef GT_COMPUTE_CAMERA
float3 GT_ObjectToWorldNormal(float3 normalOS) { return normalOS; }
float4 GT_ObjectToClip(float3 positionOS) { return float4(positionOS, 1.0); }
float2 GT_ScreenSize() { return float2(1.0, 1.0); }
#endif

// World space is object space in a kernel: the terrain's transform belongs to the draw.
float3 GT_ObjectToWorld(float3 positionOS) { return positionOS; }
float4 GT_WorldToClip(float3 positionWS) { return GT_ObjectToClip(positionWS); }
float3 GT_CameraPositionWS() { return float3(0.0, 0.0, 0.0); }
float4 GT_TessObjectToClip(float3 positionOS) { return GT_ObjectToClip(positionOS); }
float2 GT_TessScreenSize() { return GT_ScreenSize(); }
void GT_MainLight(out float3 directionWS, out float3 color)
{
    directionWS = float3(0.0, 1.0, 0.0);
    color = float3(1.0, 1.0, 1.0);
}

#endif // GT_COMPUTE_ADAPTER_INCLUDED
