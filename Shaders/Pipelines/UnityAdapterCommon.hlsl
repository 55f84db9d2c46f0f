// What the three Unity adapters (Builtin, URP, HDRP) share, included by each after its pipeline's
// own libraries (CBUFFER_START/CBUFFER_END come from them).
//
// Material constants: all in UnityPerMaterial, so the SRP Batcher layout stays the same for every
// material of this shader. Registers: Unity binds by name, so none are written.
//
// Object matrix: Graphics.RenderPrimitives gives the shader no object matrix of the renderer's
// Transform (the pipelines' unity_ObjectToWorld / UNITY_MATRIX_M are not it), so
// GregoryTerrainRenderer sets these (MaterialPropertyBlock, absolute world space), only when its
// Transform changes (deep-zoom offset included; C# names: ShaderIds.ObjectToWorld / WorldToObject).
#ifndef GT_UNITY_ADAPTER_COMMON_INCLUDED
#define GT_UNITY_ADAPTER_COMMON_INCLUDED

#define GT_CBUFFER_START(name) CBUFFER_START(UnityPerMaterial)
#define GT_CBUFFER_END CBUFFER_END
#define GT_REGISTER(r)

float4x4 _GtObjectToWorld;
float4x4 _GtWorldToObject;

// Normals go through the inverse transpose, n^T * WorldToObject (as URP's own
// TransformObjectToWorldNormal does with UNITY_MATRIX_I_M); a direction, so HDRP's camera-relative
// shift does not apply.
float3 GT_ObjectToWorldNormal(float3 normalOS) { return normalize(mul(normalOS, (float3x3)_GtWorldToObject)); }

#if !defined(GT_ADAPTER_HDRP)
// The drawing camera's view, which the renderer sets per camera (ShaderIds.TessObjectToClip,
// TessScreenSize): in a shadow pass URP's and Built-in's own view is the light's. (HDRP: its own.)
float4x4 _GtTessObjectToClip;
float4 _GtTessScreenSize;
float4 GT_TessObjectToClip(float3 positionOS) { return mul(_GtTessObjectToClip, float4(positionOS, 1.0)); }
float2 GT_TessScreenSize() { return _GtTessScreenSize.xy; }
#endif

// The Scene view's selection outline and picking (URP's SelectionPickingPass, HDRP's
// ShaderPassDepthOnly; the built-in adapter has no such pass).
#if defined(GT_PASS_SCENE_SELECTION)
// Set by the editor for the Scene view's selection outline.
int _ObjectId;
int _PassValue;
float4 GT_EditorSelectionColor() { return float4(_ObjectId, _PassValue, 1.0, 1.0); }
#endif
#if defined(GT_PASS_SCENE_PICKING)
// Read as unity_SelectionID (URP's UniversalDOTSInstancing.hlsl, HDRP's ShaderVariables.hlsl).
float4 _SelectionID;
float4 GT_EditorSelectionColor() { return unity_SelectionID; }
#endif

#endif // GT_UNITY_ADAPTER_COMMON_INCLUDED
