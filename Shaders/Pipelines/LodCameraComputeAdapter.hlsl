// LOD-camera compute adapter: the vertex cache's kernels in Unity (TerrainCache.compute). They
// decide the tessellation, so unlike ComputeAdapter.hlsl they need a camera: the one whose view the
// factors are computed for (GregoryTerrainRenderer's LOD camera), set by the renderer as globals:
//   _GT_LodObjectToClip   GPU projection * view * the terrain's object-to-world (what the draw uses)
//   _GT_LodScreenSize     (width, height, 1 / width, 1 / height) of that camera's target, in pixels
//   _GtWorldToObject      the terrain's world-to-object (the draw's own, UnityAdapterCommon.hlsl): the cache
//                         stores world normals, so the domain stage skips that transform
// The rest of the adapter interface (StandaloneAdapter.hlsl lists it) is ComputeAdapter.hlsl's, what
// the kernels never call: lighting, shadows and world space belong to the draw, which reads the
// cached object-space vertices. Material constants are a plain cbuffer (Unity sets its members by name).
#ifndef GT_LOD_CAMERA_COMPUTE_ADAPTER_INCLUDED
#define GT_LOD_CAMERA_COMPUTE_ADAPTER_INCLUDED

#define GT_COMPUTE_CAMERA 1

float4x4 _GT_LodObjectToClip;
float4 _GT_LodScreenSize;
float4x4 _GtWorldToObject;

// Normals go with the inverse transpose: n^T W (W = world-to-object), as the graphics adapters do.
float3 GT_ObjectToWorldNormal(float3 normalOS) { return normalize(mul(normalOS, (float3x3)_GtWorldToObject)); }
float4x4 GT_ObjectToClipMatrix() { return _GT_LodObjectToClip; }
float4 GT_ObjectToClip(float3 positionOS) { return mul(GT_ObjectToClipMatrix(), float4(positionOS, 1.0)); }
float2 GT_ScreenSize() { return _GT_LodScreenSize.xy; }

#include "ComputeAdapter.hlsl"

#endif // GT_LOD_CAMERA_COMPUTE_ADAPTER_INCLUDED
