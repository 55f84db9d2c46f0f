// Standalone adapter: the off-Unity rig's pipeline (Vulkan harness, glslang's HLSL front end).
// Include it before TerrainStages.hlsl. Every pipeline adapter implements the same interface:
//
//   GT_CBUFFER_START(name) / GT_CBUFFER_END / GT_REGISTER(r)   (see TerrainInputs.hlsl)
//   float3 GT_ObjectToWorld(float3 positionOS)
//   float3 GT_ObjectToWorldNormal(float3 normalOS)      unit length
//   float4 GT_WorldToClip(float3 positionWS)
//   float4 GT_ObjectToClip(float3 positionOS)
//   float4x4 GT_ObjectToClipMatrix()                    the matrix GT_ObjectToClip applies: only
//                                                       adapters of the vertex cache's kernels (a
//                                                       key of the factors they keep)
//   float3 GT_CameraPositionWS()
//   float2 GT_ScreenSize()                              render target size in pixels
//   float4 GT_TessObjectToClip(float3 positionOS)       the drawing camera's view, also in a
//   float2 GT_TessScreenSize()                          shadow pass: what the factors read
//   void   GT_MainLight(out float3 directionWS, out float3 color)
//                                                       directionWS: unit, from the surface TOWARDS
//                                                       the light (the convention of URP's Light)
//   float  GT_MainLightShadow(float3 positionWS, float4 positionSS, float3 normalWS)
//                                                       main light's shadow, 1 = lit, 0 = shadowed;
//                                                       positionSS: the fragment's SV_Position,
//                                                       normalWS: its unit normal (a lookup bias).
//                                                       The shading calls it only when the adapter
//                                                       defines GT_RECEIVE_SHADOWS
//
// Optional, each only where the adapter defines its switch (never in the rig):
//   GT_VARYINGS_POSITION_WS   the varyings carry positionWS (GT_ObjectToWorld of the vertex): for
//                             received shadows and fog
//   float3 GT_ApplyFog(float3 color, float3 positionWS)             with GT_FOG
//   float2 GT_AmbientOcclusion(float4 positionSS)  (indirect, direct) occlusion, with GT_AMBIENT_OCCLUSION
//   float  GT_ExposureMultiplier()                 the lit colour's scale, with GT_PRE_EXPOSE
//   float3 GT_AmbientProbe(float3 normalWS)        sky light, with GT_AMBIENT_PROBE (else GT_AMBIENT)
//   float4 GT_EncodeDepthNormal(float3 normalWS)   the depth-normals output of a world normal
//                                                  (the pipeline's packing), in GT_PASS_DEPTH_NORMALS
//   GT_WRITE_DEPTH_COLOR      the depth-normals pass writes the depth as colour first (HDRP MSAA)
//   float4 GT_RenderingLayers()  with GT_WRITE_RENDERING_LAYERS: the forward or depth-normals pass's
//                             second target, the draw's rendering layers (URP's decal layers)
//   float4 GT_EditorSelectionColor()               GT_PASS_SCENE_SELECTION / GT_PASS_SCENE_PICKING
//   float4 GT_ObjectToShadowClip(float3 positionOS, float3 normalWS)
//                             with GT_SHADOW_CASTER_NORMAL_BIAS: the shadow caster's vertex
//                             position with the pipeline's normal bias (URP, Built-in)
//
// Here the camera comes from the cbuffer RigCamera at b1 (Tools~/rig/README.md, "Descriptor bindings").
#ifndef GT_STANDALONE_ADAPTER_INCLUDED
#define GT_STANDALONE_ADAPTER_INCLUDED

#define GT_ADAPTER_STANDALONE 1
#define GT_CBUFFER_START(name) cbuffer name : register(b0) {
#define GT_CBUFFER_END };
#define GT_REGISTER(r) : register(r)

// HLSL default packing (column_major): each matrix is stored column after column, and mul(M, v)
// is M times the column vector v. M[r][c] is row r, column c.
cbuffer RigCamera : register(b1)
{
    float4x4 _RigObjectToClip;
    float4x4 _RigObjectToWorld;
    float4 _RigCameraPosition;   // xyz: world position; w unused
    float4 _RigScreenSize;       // (w, h, 1/w, 1/h) in pixels
    float4 _RigLightDirection;   // xyz: towards the light, world space; w unused
};

// The columns of object-to-world: the images of the object axes, and the translation. (Indexed,
// not with ._m00_m10_m20 swizzles, which glslang's HLSL front end does not implement.)
void RigObjectToWorldColumns(out float3 c0, out float3 c1, out float3 c2, out float3 t)
{
    float4x4 m = _RigObjectToWorld;
    c0 = float3(m[0][0], m[1][0], m[2][0]);
    c1 = float3(m[0][1], m[1][1], m[2][1]);
    c2 = float3(m[0][2], m[1][2], m[2][2]);
    t = float3(m[0][3], m[1][3], m[2][3]);
}

float3 GT_ObjectToWorld(float3 positionOS)
{
    return mul(_RigObjectToWorld, float4(positionOS, 1.0)).xyz;
}

// Normals transform with the inverse transpose of the upper 3x3. Its columns are, up to the factor
// 1/det, the cross products of the matrix's columns (the cofactor matrix), so no inverse is needed;
// the sign of det keeps the normal on the outer side when the transform mirrors. Exact for the
// non-uniform scale a terrain Transform usually has (metres across, metres of height).
float3 GT_ObjectToWorldNormal(float3 normalOS)
{
    float3 c0, c1, c2, t;
    RigObjectToWorldColumns(c0, c1, c2, t);
    float3 x0 = cross(c1, c2), x1 = cross(c2, c0), x2 = cross(c0, c1);
    float3 n = x0 * normalOS.x + x1 * normalOS.y + x2 * normalOS.z;
    return normalize(dot(c0, x0) < 0.0 ? -n : n);
}

float4x4 GT_ObjectToClipMatrix() { return _RigObjectToClip; }

float4 GT_ObjectToClip(float3 positionOS)
{
    return mul(GT_ObjectToClipMatrix(), float4(positionOS, 1.0));
}

// RigCamera carries object-to-clip and object-to-world only, so world-to-clip maps back to object
// space first (object-to-world is affine; a terrain Transform is invertible) rather than add a
// third matrix to the contract. p_os = A^-1 (p_ws - t), A^-1 = transpose(cofactor) / det.
float4 GT_WorldToClip(float3 positionWS)
{
    float3 c0, c1, c2, t;
    RigObjectToWorldColumns(c0, c1, c2, t);
    float3 x0 = cross(c1, c2), x1 = cross(c2, c0), x2 = cross(c0, c1);
    float3 d = positionWS - t;
    return GT_ObjectToClip(float3(dot(x0, d), dot(x1, d), dot(x2, d)) / dot(c0, x0));
}

float3 GT_CameraPositionWS() { return _RigCameraPosition.xyz; }

float2 GT_ScreenSize() { return _RigScreenSize.xy; }

float4 GT_TessObjectToClip(float3 positionOS) { return GT_ObjectToClip(positionOS); }
float2 GT_TessScreenSize() { return GT_ScreenSize(); }

void GT_MainLight(out float3 directionWS, out float3 color)
{
    directionWS = normalize(_RigLightDirection.xyz);
    color = float3(1.0, 1.0, 1.0);
}

// No shadow maps in the rig: always lit (GT_RECEIVE_SHADOWS is not defined here).
float GT_MainLightShadow(float3 positionWS, float4 positionSS, float3 normalWS) { return 1.0; }

#endif // GT_STANDALONE_ADAPTER_INCLUDED
