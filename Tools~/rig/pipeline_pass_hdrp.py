#!/usr/bin/env python3
"""gt pipeline_pass_hdrp: HDRP's DepthForwardOnly and ForwardOnly of Shaders/GregoryTerrain.shader in the harness.

The tessellated HDRP SubShader's two passes, compiled as `gt shaderlab` compiles them (glslang against
../shared/unity-shaderlib/hdrp-14.0.12) and drawn by pipeline_pass.py's machinery: every binding from
spirv-cross --reflect, filled by name from the scene URP's pictures use (the sample grid, RigScene's zoom
view, a sun 30 degrees up) in HDRP's units and conventions: camera-relative matrices, the sun in lux
through a fixed exposure, the ambient probe as HDRP's SH buffer, one directional light with its
cascade shadow data over an atlas at the far plane (nothing occludes). The structured buffers are
filled member by member at glslang's offsets, their unset members listed as named defaults, and the
members the stages read (access chains) checked like the uniform blocks' ("defaulted_read").

Pictures (OUT/<picture>.png, OUT/<picture>/manifest.json as pipeline_pass.py writes them):
  lit          URP's ForwardLit, base variant (pipeline_pass.py's), to compare with
  hdrp_depth   HDRP's DepthForwardOnly, base variant: the normal buffer (EncodeIntoNormalBuffer:
               octahedral normal in RGB 8:8:8, perceptual roughness 1 in A); its depth in
               OUT/hdrp_depth_depth.f32 and its view in OUT/hdrp_depth_view.json
  hdrp_lit     HDRP's ForwardOnly, base variant (SHADOW_LOW: its multi_compile_fragment set has no '_'),
               drawn as HDRP draws it: over DepthForwardOnly's depth (--depth-in hdrp_depth_depth.f32;
               its own depth after the pass in OUT/hdrp_lit_depth.f32), with the pass's ZTest and ZWrite
               Each HDRP pass draws with its Stencil block; DepthForwardOnly's stencil (cleared to 0) is
               OUT/hdrp_depth_stencil.u8, ForwardOnly starts from it and leaves OUT/hdrp_lit_stencil.u8
  hdrp_lit_far the same pass on a cleared depth, the whole scene 50 km from the world's origin
  hdrp_lit_near the same at the origin, positions rounded as float32 rounds them 50 km away

  gt pipeline_pass_hdrp [--out DIR] [--only PICTURE]... [--sun-elevation DEG] [--sun-azimuth DEG]
      [--light-color R,G,B] [--leave-default NAME]... [--flip-light-forward]
      [--depth-nudge-ulps N] [--depth-pass-factor F] [--break-stencil write-mask|pass-keep]
--leave-default NAME leaves a member, buffer or image of HDRP's scene to its default (_ExposureTexture:
pipeline_pass.py's 1x1 texel of multiplier 1); --flip-light-forward writes the light's forward with the
wrong sign (towards the sun); --depth-nudge-ulps moves every written depth of the prepass N float32 steps
(positive: nearer, under reversed depth) before ForwardOnly loads it; --depth-pass-factor draws
DepthForwardOnly with the uniform tessellation factor F instead of the scene's; --break-stencil draws both
HDRP passes' Stencil blocks without their WriteMask, or with Pass Keep: the tests' broken inputs.
"""
import argparse
import json
import math
import os
import shutil
import struct
import sys
import types

RIG_DIR = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, RIG_DIR)
import options  # noqa: E402
import pipeline_pass as pp  # noqa: E402
import render_state  # noqa: E402

HDRP_PACKAGES = ["com.unity.render-pipelines.core", "com.unity.render-pipelines.high-definition",
                 "com.unity.render-pipelines.high-definition-config"]
HDRP = "../shared/unity-shaderlib/hdrp-14.0.12/com.unity.render-pipelines.high-definition/"

# The samples' HDRP sun (Samples~/TerrainFlyover/SampleSun.cs: hdrpLux 100000, hdrpExposure 15 EV100).
SUN_LUX = 100000.0
SUN_EV100 = 15.0
# The sky's share of the sun in the ambient probe: the package's GT_AMBIENT against a light of 1, so
# the picture is URP's scaled by one number where the models agree (a clear sky's diffuse light is
# 10-25 % of the direct sun's).
SKY_SHARE = pp.GT_AMBIENT_LEVEL
CASCADE_RADIUS = 3.0         # the one cascade's sphere around the camera's target: all the visible terrain
SHADOW_DEPTH = 10.0          # the cascade's ortho depth range along the light, metres of the rig's units


def exposure_multiplier(ev100):
    """GetCurrentExposureMultiplier's texel: HDRP's fixed exposure (Exposure.compute KFixedExposure writes
    float2(ConvertEV100ToExposure(ev100 - compensation, LensImperfectionExposureScale), ev100) to the
    exposure texture); PhysicalCamera.hlsl:42-58: 1 / (scale * 2^EV100), scale 1.2 (78 / (100 * 0.65))."""
    return 1.0 / (1.2 * 2.0 ** ev100)


def float_bits(u):
    """A uint's bits read as the float member that carries them (asuint in the shader)."""
    return struct.unpack("<f", struct.pack("<I", u))[0]


def f32(x):
    return struct.unpack("<f", struct.pack("<f", x))[0]


def moved(v):
    """A world position as the scene writes it: moved by Setting.world_offset, or with Setting.rounded_at
    the float32 rounding of v + rounded_at, moved back to the origin (exact: the difference of two
    float32 values near the offset is one, Sterbenz), so the camera-relative differences are the far
    scene's to the bit."""
    if Setting.rounded_at:
        return [f32(x + d) - d for x, d in zip(v, Setting.rounded_at)]
    return [x + d for x, d in zip(v, Setting.world_offset or [0.0] * 3)]


def without_translation(m):
    return [m[0][:3] + [0.0], m[1][:3] + [0.0], m[2][:3] + [0.0], [0.0, 0.0, 0.0, 1.0]]


# ---------------------------------------------------------------------------------------------
# Structured buffers, images and samplers filled by the scene (pipeline_pass.prepare's hook)


def struct_layout(name, spvs):
    """(element members or None for a vector buffer, element type, stride) of the structured buffer
    NAME as the stages that declare it lay it out (spirv-cross --reflect; every stage must agree)."""
    found = None
    for stage, spv in spvs.items():
        refl = pp.reflect(spv)
        for u in refl.get("ssbos", []):
            if u["name"] != name:
                continue
            data = refl["types"][u["type"]]["members"][0]          # the runtime array ("@data")
            members = refl["types"][data["type"]]["members"] if data["type"].startswith("_") else None
            layout = ([{k: m.get(k) for k in ("name", "type", "offset", "array", "array_stride")} for m in members]
                      if members else None, data["type"] if not members else "struct", data["array_stride"])
            if found is not None and found != layout:
                raise SystemExit(f"pipeline-pass-hdrp: error: '{name}' has another element layout in the {stage} stage")
            found = layout
    if found is None:
        raise SystemExit(f"pipeline-pass-hdrp: error: no stage declares the structured buffer '{name}'")
    return found


def structured_buffer(elements, defaults=None):
    """The hook for a StructuredBuffer: ELEMENTS is a list of {member: value} (structs) or of values
    (a vector buffer); unset struct members get DEFAULTS[member] or zero, each listed."""
    def fill(name, kind, size, binding, path, spvs, report):
        members, elem_type, stride = struct_layout(name, spvs)
        data = bytearray()
        for i, element in enumerate(elements):
            one = bytearray(stride)
            if members is None:
                b = pp.element_bytes({"name": name, "type": elem_type}, element)
                one[:len(b)] = b
            else:
                for m in members:
                    label = f"{name}[{i}].{m['name']}"
                    if m["name"] in element:
                        value = element[m["name"]]
                        report["filled"].append(label)
                    else:
                        value = (defaults or {}).get(m["name"], pp.zero_value(m))
                        report["defaults"].append(f"{label}={pp.show(value)}")
                    b = pp.member_bytes(m, value)
                    one[m["offset"]:m["offset"] + len(b)] = b
            data += one
        if members is None:
            report["filled"].append(f"{name}[0..{len(elements) - 1}]")
        with open(path, "wb") as f:
            f.write(data)
        return {"name": name, "binding": binding, "kind": kind, "bytes": len(data), "file": path,
                "stride": stride, "members": [m["name"] for m in members] if members else None}
    return fill


def image(fmt, texel, why):
    """The hook for a 1x1 image of the scene (pipeline_pass.py binds 1x1 images)."""
    def fill(name, kind, size, binding, path, spvs, report):
        with open(path, "wb") as f:
            f.write(struct.pack(f"<{len(texel)}f", *texel))
        report["filled"].append(f"{name}={fmt}({','.join(pp.show(x) for x in texel)}) ({why})")
        return {"name": name, "binding": binding, "kind": kind, "format": fmt, "file": path,
                "bytes": 4 * len(texel), "arrayed": "Array" in size, "size": [1, 1]}
    return fill


def sampler(value, why):
    def fill(name, kind, size, binding, path, spvs, report):
        report["filled"].append(f"{name}={value} ({why})")
        return {"name": name, "binding": binding, "kind": kind, "sampler": value, "bytes": 0}
    return fill


# ---------------------------------------------------------------------------------------------
# The scene in HDRP's terms


class Setting:
    """The sun's HDRP units, and what main() sets before drawing (the scene functions have
    pipeline_pass.py's signature)."""
    lux, ev100, flip_forward = SUN_LUX, SUN_EV100, False
    world_offset = None     # the scene moved by this (hdrp_lit_far); camera-relative values stay
    shadow = None           # an HdrpCascade: the shadowed frame's cascade (hdrp_shadow_map, hdrp_lit_shadows)
    atlas = None            # the cascade atlas's texels (rows in texture order) hdrp_lit_shadows samples
    rounded_at = None       # the scene at the origin as float32 holds it moved by this (hdrp_lit_near)


def light_view(sun, center_rws):
    """The directional light's shadow view, camera-relative, as a Unity camera looking along the
    light (forward = -sun) from SHADOW_DEPTH / 2 before the cascade's centre: rows right, up, -forward
    and the translation column (HDShadowAlgorithms.hlsl:57-93 reads them as rot0..2 and pos)."""
    f = [-x for x in sun]
    up = [0.0, 0.0, 1.0] if abs(f[1]) > 0.99 else [0.0, 1.0, 0.0]
    r = pp.normalize(pp.cross(up, f))
    u = pp.cross(f, r)
    eye = [c - SHADOW_DEPTH / 2 * x for c, x in zip(center_rws, f)]
    return f, r, u, [r + [-pp.dot(r, eye)], u + [-pp.dot(u, eye)], [-x for x in f] + [pp.dot(f, eye)], [0.0, 0.0, 0.0, 1.0]]


# HDRP's directional cascade, as HDRP 14's C# sets it up (Runtime/Lighting/Shadow/HDShadowUtils.cs
# ExtractDirectionalLightData; Runtime/Lighting/Light/HDAdditionalLightData.cs UpdateShadowRequest;
# Runtime/Lighting/Shadow/HDShadowAtlas.cs RenderShadows; HDShadowManager.cs CreateShadowData):
# - the light's view and orthographic projection come from Unity's
#   CullingResults.ComputeDirectionalShadowMatricesAndCullingPrimitives, the call URP makes:
#   pipeline_pass.MainLightShadow's sphere and matrices, one cascade over the shadow distance;
# - deviceProjection = GL.GetGPUProjectionMatrix(projection, false) (reversed depth); the atlas is rendered
#   with deviceProjectionYFlip (the rig draws y unflipped and reverses the rows, as for URP);
# - RenderShadows: cmd.SetGlobalDepthBias(1.0f, shadowRequest.slopeBias) with slopeBias =
#   HDShadowUtils.GetSlopeBias(baseBias 5 (not High filtering), light.slopeBias 0.5) = 2.5; cmd.SetGlobalFloat(
#   _ZClip, shadowRequest.zClip ? 1 : 0) with zClip false for a directional light; _ViewMatrix, _ProjMatrix,
#   _ViewProjMatrix and their inverses replaced in the camera's ShaderVariablesGlobal, the rest (_CameraViewProjMatrix,
#   _ScreenSize: the adapter's tessellation) kept;
# - HDShadowData: rot0..2 and pos the view's rows (camera-relative), proj (m00, m11, m22, m23) of deviceProjection,
#   worldTexelSize = 2 / deviceProjectionYFlip.m00 / resolution x sqrt(2), normalBias the light's 0.75.
HDRP_SHADOW_RESOLUTION = 2048   # the HDRP asset's directional shadow resolution, Ultra tier (URP's map: the same)
HDRP_DEPTH_BIAS = (1.0, 5.0 * 0.5)
HDRP_NORMAL_BIAS = 0.75


class HdrpCascade:
    """One cascade of the sun's shadow in HDRP's camera-relative terms (see above)."""

    def __init__(self, cam, sun, resolution=HDRP_SHADOW_RESOLUTION):
        unity = pp.MainLightShadow(cam, sun, resolution)
        self.resolution, self.sun, self.distance = resolution, sun, unity.distance
        translate = [[1.0, 0, 0, cam.eye[0]], [0, 1.0, 0, cam.eye[1]], [0, 0, 1.0, cam.eye[2]], [0, 0, 0, 1.0]]
        self.view = pp.mat_mul(unity.view, translate)          # camera-relative positions in
        self.proj = unity.gpu_proj                             # deviceProjection (reversed depth)
        self.view_proj = pp.mat_mul(self.proj, self.view)
        self.center = [c - e for c, e in zip(unity.center, cam.eye)]
        self.radius = unity.radius
        self.world_texel = 2.0 / self.proj[0][0] / resolution * math.sqrt(2.0)
        self.texel = 2.0 / self.proj[0][0] / resolution        # one texel across, world units

    def caster_values(self):
        return {"_ViewMatrix": self.view, "_InvViewMatrix": pp.affine_inverse(self.view), "_ProjMatrix": self.proj,
                "_InvProjMatrix": pp.general_inverse(self.proj), "_ViewProjMatrix": self.view_proj,
                "_InvViewProjMatrix": pp.general_inverse(self.view_proj)}


def atlas_image(path, n):
    """The hook for the cascade atlas the ShadowCaster pass drew: N x N D32, rows in texture order."""
    def fill(name, kind, size, binding, out, spvs, report):
        report["filled"].append(f"{name}=D32 {n}x{n} (the ShadowCaster pass's depth from the sun)")
        return {"name": name, "binding": binding, "kind": kind, "format": "D32", "file": path,
                "bytes": 4 * n * n, "arrayed": "Array" in size, "size": [n, n]}
    return fill


def hdrp_globals(cam, o2w, o2c, sun, light_color):
    """ShaderVariablesGlobal, UnityPerDraw, $Global members and the light loop's buffers, images and
    samplers by name, each with where its value and layout come from. Paths are under HDRP (above)
    unless named; ShaderVariablesGlobal.cs.hlsl is Runtime/ShaderLibrary/ShaderVariablesGlobal.cs.hlsl."""
    w, h, n, f = cam.width, cam.height, cam.near, cam.far
    t = moved([row[3] for row in o2w[:3]])
    o2w = [row[:3] + [t[i]] for i, row in enumerate(o2w[:3])] + [o2w[3]]
    eye = moved(cam.eye)
    # SHADEROPTIONS_CAMERA_RELATIVE_RENDERING is 1 (high-definition-config ShaderConfig.cs.hlsl:11):
    # HDCamera's view matrices drop the camera's translation, and the shader's world space has the
    # camera at the origin (ShaderVariables.hlsl:23 _WorldSpaceCameraPos = _WorldSpaceCameraPos_Internal.xyz,
    # GetCameraRelativePositionWS subtracts it).
    view = without_translation(cam.view)
    view_proj = pp.mat_mul(cam.proj, view)
    inv_view_proj = pp.general_inverse(view_proj)
    target = [0.0, -0.05, 0.0]                                    # pipeline_pass.rig_camera's target
    center = [t - e for t, e in zip(target, cam.eye)]             # camera-relative
    forward, right, up, lview = light_view(sun, center)
    exposure = exposure_multiplier(Setting.ev100)
    sky = SKY_SHARE * Setting.lux / math.pi
    res = 1.0                                                     # the atlas pipeline_pass.py binds is 1x1
    radius, proj, texel, normal_bias = CASCADE_RADIUS, [1.0 / CASCADE_RADIUS, 1.0 / CASCADE_RADIUS, 1.0 / SHADOW_DEPTH, 1.0], 2.0 * CASCADE_RADIUS / res, 0.75
    cascade = Setting.shadow
    if cascade:
        res, lview, center, radius = float(cascade.resolution), cascade.view, cascade.center, cascade.radius
        proj = [cascade.proj[0][0], cascade.proj[1][1], cascade.proj[2][2], cascade.proj[2][3]]
        texel, normal_bias = cascade.world_texel, HDRP_NORMAL_BIAS
    values = {
        # ShaderVariablesGlobal.cs.hlsl:20-30; UNITY_MATRIX_V/VP are _ViewMatrix/_ViewProjMatrix
        # (ShaderVariablesMatrixDefsHDCamera.hlsl:22-26): the GPU projection (reversed depth, as URP's scene).
        "_ViewMatrix": view, "_CameraViewMatrix": view, "_InvViewMatrix": pp.affine_inverse(view),
        "_ProjMatrix": cam.proj, "_InvProjMatrix": pp.general_inverse(cam.proj),
        "_ViewProjMatrix": view_proj, "_CameraViewProjMatrix": view_proj, "_InvViewProjMatrix": inv_view_proj,
        "_NonJitteredViewProjMatrix": view_proj, "_PrevViewProjMatrix": view_proj, "_PrevInvViewProjMatrix": inv_view_proj,
        # ShaderVariablesGlobal.cs.hlsl:31-32: the camera's absolute position; the previous frame's,
        # camera-relative, is the same place (a still camera): 0.
        "_WorldSpaceCameraPos_Internal": eye + [0.0], "_PrevCamPosRWS_Internal": [0.0, 0.0, 0.0, 0.0],
        # ShaderVariablesGlobal.cs.hlsl:33-: width, height, 1/width, 1/height; RTHandle scales 1
        # (the target is the camera's size); the same projection and z parameters as URP's scene.
        "_ScreenSize": [w, h, 1.0 / w, 1.0 / h], "_PostProcessScreenSize": [w, h, 1.0 / w, 1.0 / h],
        "_RTHandleScale": [1.0] * 4, "_RTHandleScaleHistory": [1.0] * 4,
        "_RTHandlePostProcessScale": [1.0] * 4, "_RTHandlePostProcessScaleHistory": [1.0] * 4,
        "_DynamicResolutionFullscreenScale": [1.0] * 4,
        "_ZBufferParams": [-1.0 + f / n, 1.0, (-1.0 + f / n) / f, 1.0 / f],
        "_ProjectionParams": [1.0, n, f, 1.0 / f],
        "unity_OrthoParams": [w / h, 1.0, 0.0, 0.0],
        "_ScreenParams": [w, h, 1.0 + 1.0 / w, 1.0 + 1.0 / h],
        "_GlobalMipBias": 0.0, "_GlobalMipBiasPow2": 1.0,
        # ShaderVariablesGlobal.cs.hlsl:46 (sharpen strength, unused, frame index, TAA on): no TAA, frame
        # 0 (the cascade dither's noise, InterleavedGradientNoise(positionSS, _TaaFrameInfo.z), reads it).
        "_TaaFrameInfo": [0.0, 0.0, 0.0, 0.0],
        # ShaderVariablesLightLoop: one directional light, the one that casts the cascades
        # (_DirectionalShadowIndex: its index; HDRPAdapter.hlsl's MainDirectionalLightIndex takes it).
        "_DirectionalLightCount": 1, "_DirectionalShadowIndex": 0, "_CascadeShadowCount": 1,
        # ShaderVariablesGlobal.cs.hlsl:81-82: (w, h, 1/w, 1/h) of the 1x1 atlas bound below.
        "_CascadeShadowAtlasSize": [res, res, 1.0 / res, 1.0 / res], "_ShadowAtlasSize": [res, res, 1.0 / res, 1.0 / res],
        # ShaderVariables.hlsl:386-392: exposure texel * _ProbeExposureScale, 1 when not rendering a probe.
        "_ProbeExposureScale": 1.0,
        # ShaderVariables.hlsl:419-422 GetIndirectDiffuseMultiplier: the Indirect Lighting Controller's
        # defaults (multiplier 1 on every light layer); light layers off (the HDRP asset's default), so
        # GetMeshRenderingLightLayer (ShaderVariablesFunctions.hlsl:11-14) is DEFAULT_LIGHT_LAYERS.
        "_IndirectDiffuseLightingMultiplier": 1.0, "_IndirectDiffuseLightingLayers": 0xFF, "_EnableLightLayers": 0,
        # UnityPerDraw (ShaderVariables.hlsl:65): the draw's rendering layer mask, asuint'ed;
        # RenderParams' default is the project's default rendering layer mask, layer 0 (1).
        "unity_RenderingLayer": [float_bits(1), 0.0, 0.0, 0.0],
        # The package's own (UnityAdapterCommon.hlsl; GregoryTerrainRenderer sets them), absolute world.
        "_GtObjectToWorld": o2w, "_GtWorldToObject": pp.affine_inverse(o2w),
        # LightDefinition.cs.hlsl:81-117 DirectionalLightData, one light as HDRP's LightLoop
        # (GetDirectionalLightData) packs a sun: forward the direction it travels, color its linear
        # colour times its intensity in lux, dimmers 1 (it lights diffuse and specular), shadowIndex
        # the first HDShadowData of its cascades, no cookie, contact or screen-space shadow (-1).
        "_DirectionalLightDatas": structured_buffer([{
            "positionRWS": [0.0, 0.0, 0.0], "lightLayers": 0xFF, "lightDimmer": 1.0, "volumetricLightDimmer": 1.0,
            "forward": [-x for x in forward] if Setting.flip_forward else forward,
            "cookieMode": 0, "right": right, "up": up, "shadowIndex": 0, "contactShadowIndex": -1,
            "color": [c * Setting.lux for c in light_color], "contactShadowMask": 0,
            "shadowTint": [0.0, 0.0, 0.0], "shadowDimmer": 1.0, "volumetricShadowDimmer": 1.0, "nonLightMappedOnly": 0,
            "minRoughness": 0.0, "screenSpaceShadowIndex": -1, "shadowMaskSelector": [0.0] * 4,
            "diffuseDimmer": 1.0, "specularDimmer": 1.0, "penumbraTint": 0.0, "isRayTracedContactShadow": 0.0,
            "distanceFromCamera": -1.0, "angularDiameter": math.radians(0.53),
            # The adapter loads the struct whole (glslang reads every member): the rest are a sun's
            # without cookie, lens flare or celestial-body surface (surface tint white).
            "cookieScaleOffset": [0.0] * 4, "flareFalloff": 0.0, "flareCosInner": 0.0, "flareCosOuter": 0.0,
            "__unused__": 0.0, "flareTint": [0.0] * 3, "flareSize": 0.0, "surfaceTint": [1.0] * 3,
            "surfaceTextureScaleOffset": [0.0] * 4,
        }]),
        # Shadow/HDShadowManager.cs.hlsl:20- HDShadowData for the one cascade: the light's view (rows, camera-
        # relative) and HDRP's orthographic reversed-depth projection (sx, sy, sz, tz): near 1, far 0.
        "_HDShadowDatas": structured_buffer([{
            "rot0": lview[0][:3], "rot1": lview[1][:3], "rot2": lview[2][:3], "pos": [lview[0][3], lview[1][3], lview[2][3]],
            "proj": proj, "atlasOffset": [0.0, 0.0], "worldTexelSize": texel,
            "normalBias": normal_bias,                             # HDAdditionalLightData's default normal bias
            "shadowMapSize": [res, res, 1.0 / res, 1.0 / res],
            # DIRECTIONAL_FILTER_ALGORITHM (HDShadowAlgorithms.hlsl:21-33) is PCSS only under SHADOW_HIGH;
            # SHADOW_LOW (line 26: PCF tent 5x5) reads neither: PCSS off (kernel 0), no blocker depth range.
            "zBufferParam": [0.0] * 4, "shadowFilterParams0": [0.0] * 4,
            "cacheTranslationDelta": [0.0, 0.0, 0.0], "isInCachedAtlas": 0.0,
            "shadowToWorld": pp.general_inverse(pp.mat_mul([[proj[0], 0, 0, 0], [0, proj[1], 0, 0],
                                                            [0, 0, proj[2], proj[3]], [0, 0, 0, 1.0]], lview)),
        }]),
        # Shadow/HDShadowManager.cs.hlsl:9- HDDirectionalShadowData: the cascade spheres (centre camera-relative,
        # w radius squared: EvalShadow_GetSplitIndex, HDShadowAlgorithms.hlsl:198-), the cascade count in
        # cascadeDirection.w, no border (no blend between cascades).
        "_HDDirectionalShadowData": structured_buffer([{
            "sphereCascades": [center + [radius ** 2]] + [[0.0] * 4] * 3,
            "cascadeDirection": forward + [1.0], "cascadeBorders": [0.0] * 4,
            # Loaded with the struct; no function of this pass uses the fade: none (scale 0, bias 1).
            "fadeScale": 0.0, "fadeBias": 1.0,
        }]),
        # core SphericalHarmonics.hlsl:113 SampleSH9(StructuredBuffer<float4>): SHAr, SHAg, SHAb, SHBr, SHBg,
        # SHBb, SHC (Unity's packing: L0 in w of SHA*). HDRP's sky ambient probe, already divided by pi
        # (Lit adds it to the diffuse without INV_PI): a uniform sky of SKY_SHARE times the sun's lux / pi.
        "_AmbientProbeData": structured_buffer([[0.0, 0.0, 0.0, sky]] * 3 + [[0.0] * 4] * 4),
        # ShaderVariables.hlsl:160, 390: the exposure texture's texel (multiplier, EV100).
        "_ExposureTexture": image("R32G32_SFLOAT", [exposure, Setting.ev100], f"fixed exposure {Setting.ev100:g} EV100"),
        # HDShadowContext.hlsl:26: the cascade atlas, reversed depth's far plane everywhere: nothing occludes.
        "_ShadowmapCascadeAtlas": (atlas_image(Setting.atlas, cascade.resolution) if cascade and Setting.atlas
                                   else image("D32", [0.0], "far plane: no occluder")),
        # ShaderVariables.hlsl:120: HDRP's global comparison sampler, linear clamp; Unity compares
        # GreaterEqual under reversed depth (lavapipe lists no linear filtering of D32: point).
        "s_linear_clamp_compare_sampler": sampler("point:clamp:compare-gequal", "linear clamp compare, reversed depth"),
    }
    return values


def compile_once(compile_pass):
    """pipeline_pass.compile_pass, compiled once per pass, variant and compiler in a run: a later
    picture of the same variant gets copies of the first one's SPIR-V, taken before its rebinding."""
    done = {}

    def compile(sub, pas, out, tmp, keywords=(), compiler="glslang"):
        key = (sub.index, pas.name, tuple(sorted(keywords)), compiler)
        if key not in done:
            spvs = compile_pass(sub, pas, out, tmp, keywords, compiler)
            done[key] = {stage: open(spv, "rb").read() for stage, spv in spvs.items()}
        paths = {}
        for stage, data in done[key].items():
            paths[stage] = os.path.join(out, f"{stage}.spv")
            with open(paths[stage], "wb") as f:
                f.write(data)
        return paths
    return compile


pp.GLOBALS["HDRP"] = hdrp_globals
pp.compile_pass = compile_once(pp.compile_pass)
pp.INCLUDE_PACKAGES["HDRP"] = HDRP_PACKAGES

# ---------------------------------------------------------------------------------------------
# Reads of the structured buffers' members


def buffer_reads(spv, binding, members):
    """Member names of the structured buffer at BINDING that the module reads: an access chain
    (@data, element, member) names one; a chain that stops at the element loads all of them."""
    words = pp.spirv_words(spv)
    var = [v for v, b in pp.variable_bindings(words).items() if b == binding]
    constants = {ops[1]: ops[2] for _, op, ops in pp.instructions(words) if op == pp.OP_CONSTANT and len(ops) >= 3}
    read = set()
    for _, op, ops in pp.instructions(words):
        if op in (pp.OP_ACCESS_CHAIN, pp.OP_IN_BOUNDS_ACCESS_CHAIN) and ops[2] in var:
            if len(ops) > 5:
                read.add(members[constants[ops[5]]])
            else:
                read.update(members)
    return read


def check_buffer_reads(out):
    """Adds the structured buffers' members each stage reads to OUT/manifest.json's reads, and the
    defaulted ones among them to its defaulted_read; prints both."""
    path = os.path.join(out, "manifest.json")
    with open(path) as f:
        manifest = json.load(f)
    for stage in pp.STAGES:
        spv = os.path.join(out, f"{stage}.spv")
        if not os.path.exists(spv):
            continue
        found = []
        for b in manifest["bindings"]:
            if b.get("members"):
                found += [f"{b['name']}[0].{m}" for m in sorted(buffer_reads(spv, b["binding"], b["members"]))]
        manifest["reads"][stage] = sorted(manifest["reads"].get(stage, []) + found)
        if found:
            print(f"reads {stage} buffers {len(found)}: {', '.join(found)}")
    read = set(x for r in manifest["reads"].values() for x in r)
    extra = [d for d in manifest["defaults"] if d.split("=")[0] in read and d not in manifest["defaulted_read"]]
    manifest["defaulted_read"] += extra
    print(f"defaulted_read buffers {len(extra)}: {', '.join(extra)}")
    with open(path, "w") as f:
        json.dump(manifest, f, indent=1)


def with_factor(buffers, factor):
    """A copy of the packed BUFFERS whose TerrainParams (params.f32) has the uniform tessellation factor FACTOR
    (_Tess.w): a pass tessellated unlike the others."""
    names = list(pp.terrain_params(buffers))
    other = buffers + f"-factor{factor}"
    shutil.rmtree(other, ignore_errors=True)
    shutil.copytree(buffers, other)
    path = os.path.join(other, "params.f32")
    p = pp.read_floats(path)
    p[4 * names.index("_Tess") + 3] = float(factor)
    with open(path, "wb") as f:
        f.write(struct.pack(f"<{len(p)}f", *p))
    return other


def nudged(depth, out, ulps, clear=0.0):
    """DEPTH's float32 pixels (a --depth-out file), each written one moved ULPS float32 steps (positive:
    larger, nearer under reversed depth), kept in [0, 1], to OUT: a prepass whose depth is not the forward pass's."""
    with open(depth, "rb") as f:
        data = f.read()
    words = list(struct.unpack(f"<{len(data) // 4}I", data))
    clear_bits = struct.unpack("<I", struct.pack("<f", clear))[0]
    one = struct.unpack("<I", struct.pack("<f", 1.0))[0]
    words = [w if w == clear_bits else min(one, max(1, w + ulps)) for w in words]
    with open(out, "wb") as f:
        f.write(struct.pack(f"<{len(words)}I", *words))
    return out


def broken_stencil(args, how):
    """args with the --stencil block broken as --break-stencil says (None: as ShaderLab writes it)."""
    if not how or "--stencil" not in args:
        return args
    at = args.index("--stencil") + 1
    words = args[at].split()
    pairs = [(c, v) for c, v in zip(words[::2], words[1::2])
             if not (how == "write-mask" and c.lower() == "writemask")]
    pairs = [(c, "Keep" if how == "pass-keep" and c.lower() == "pass" else v) for c, v in pairs]
    return args[:at] + [" ".join(f"{c} {v}" for c, v in pairs)] + args[at + 1:]


# ---------------------------------------------------------------------------------------------

# (picture, pipeline, pass, keywords, world offset, rounded at). hdrp_lit_far: the same view 50 km from the
# world's origin along x and z, where float32 positions step by 4 mm; hdrp_lit_near: at the origin with
# the object's and the camera's positions as float32 rounds them there. Camera-relative rendering that
# subtracts the camera from the translation before adding the rotated position draws the two alike.
FAR = [50000.0, 0.0, 50000.0]
PICTURES = [("lit", "URP", "ForwardLit", [], None, None), ("hdrp_depth", "HDRP", "DepthForwardOnly", [], None, None),
            ("hdrp_lit", "HDRP", "ForwardOnly", ["SHADOW_LOW"], None, None),
            ("hdrp_lit_far", "HDRP", "ForwardOnly", ["SHADOW_LOW"], FAR, None),
            ("hdrp_lit_near", "HDRP", "ForwardOnly", ["SHADOW_LOW"], None, FAR),
            ("hdrp_shadow_map", "HDRP", "ShadowCaster", [], None, None),
            ("hdrp_lit_shadows", "HDRP", "ForwardOnly", ["SHADOW_LOW"], None, None)]
# hdrp_shadow_map: the ShadowCaster pass from the shadowed frame's sun into the cascade atlas (OUT/hdrp_shadow_map.f32,
# no PNG); hdrp_lit_shadows: ForwardOnly under that sun sampling it, over the prepass's depth (its depth in
# OUT/hdrp_lit_shadows_depth.f32, the cascade in OUT/hdrp_shadow.json). Drawn only when named (their own fixture).
ON_REQUEST = {"hdrp_shadow_map", "hdrp_lit_shadows"}


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default=os.path.join(pp.PKG_DIR, ".build", "pipeline-pass-hdrp"))
    ap.add_argument("--only", choices=[p[0] for p in PICTURES], action="append", help="draw only these pictures")
    options.add_number(ap, "--sun-elevation", range="elevation", default=30.0, help="degrees above the horizon (default 30)")
    options.add_number(ap, "--sun-azimuth", range="azimuth", default=-140.0, help="degrees from +z towards +x (default -140)")
    ap.add_argument("--light-color", default="1,0.96,0.9", help="R,G,B: the sun's linear colour (URP: its final colour)")
    ap.add_argument("--leave-default", action="append", default=[], help="NAME: leave a member, buffer or image to its default")
    ap.add_argument("--flip-light-forward", action="store_true", help="HDRP: the light's forward towards the sun (broken)")
    options.add_number(ap, "--shadow-sun-elevation", range="elevation", default=12.0,
                       help="the shadowed frame's sun (hdrp_shadow_map, hdrp_lit_shadows): degrees above the horizon (default 12)")
    options.add_number(ap, "--shadow-sun-azimuth", range="azimuth", default=90.0,
                       help="the shadowed frame's sun: degrees from +z towards +x (default 90, as gt pipeline_pass's)")
    ap.add_argument("--flip-depth-bias", action="store_true", help="the ShadowCaster's depth bias towards the light (broken)")
    ap.add_argument("--transpose-atlas", action="store_true", help="the cascade atlas sampled transposed (broken)")
    options.add_number(ap, "--depth-nudge-ulps", range="ulps", default=0,
                    help="N: the prepass's depth moved N float32 steps before ForwardOnly loads it (broken; -8..8)")
    ap.add_argument("--break-stencil", choices=["write-mask", "pass-keep"],
                    help="both HDRP passes' Stencil blocks without WriteMask, or with Pass Keep (broken)")
    options.add_number(ap, "--depth-pass-factor", range="factor", default=0,
                       help="F: DepthForwardOnly's uniform tessellation factor instead of the scene's (broken; default 0: the scene's)")
    a = ap.parse_args(argv)
    try:
        color = [float(x) for x in a.light_color.split(",")]
        if len(color) != 3 or not all(math.isfinite(x) and 0 <= x <= 1000 for x in color):
            raise ValueError
    except ValueError:
        ap.error(f"argument --light-color: expected R,G,B, each 0..1000, got '{a.light_color}'")
    Setting.flip_forward = a.flip_light_forward
    cam = pp.Camera([0.0, 1.0, -1.0], [0.0] * 3, 50.0, 4, 3, 0.01, 20.0)
    identity = [[1.0 if i == j else 0.0 for j in range(4)] for i in range(4)]
    names = set(hdrp_globals(cam, identity, identity, [0.0, 1.0, 0.0], [1.0] * 3))
    for name in a.leave_default:
        if name not in names:
            ap.error(f"argument --leave-default: HDRP's scene does not set '{name}'")
    scene = types.SimpleNamespace(sun_elevation=a.sun_elevation, sun_azimuth=a.sun_azimuth, light_color=color,
                                  leave_default=a.leave_default, fill_from=[], transpose=[])
    os.makedirs(a.out, exist_ok=True)
    buffers = pp.pack_scene(a.out)
    wanted = set(a.only or [p[0] for p in PICTURES if p[0] not in ON_REQUEST])
    wanted |= {"hdrp_depth"} if wanted & {"hdrp_lit", "hdrp_lit_shadows"} else set()
    wanted |= {"hdrp_shadow_map"} if "hdrp_lit_shadows" in wanted else set()
    prepass = os.path.join(a.out, "hdrp_depth_depth.f32")
    cam, o2w, _ = pp.rig_camera(buffers)
    shadow_sun = pp.sun_direction(a.shadow_sun_elevation, a.shadow_sun_azimuth)
    cascade = HdrpCascade(cam, shadow_sun)
    render_state.GLOBAL_PROPERTIES["_ZClip"] = "off"     # HDRP's _ZClip 0 for a directional light's cascades
    for picture, pipeline, pass_name, keywords, offset, rounded_at in PICTURES:
        if picture not in wanted:
            continue
        if picture in ON_REQUEST:
            draw_shadowed(a, scene, picture, buffers, cascade, prepass, cam, o2w)
            continue
        Setting.world_offset, Setting.rounded_at = offset, rounded_at
        folder = os.path.join(a.out, picture)
        drawn = with_factor(buffers, a.depth_pass_factor) if picture == "hdrp_depth" and a.depth_pass_factor else buffers
        args = pp.prepare(scene, pipeline, pass_name, keywords, drawn, folder)
        if pipeline == "HDRP":
            check_buffer_reads(folder)
            args = broken_stencil(args, a.break_stencil)
        # The normal buffer's depth and view (the test recovers each pixel's position, as pipeline_pass.py's
        # depth_normals); hdrp_lit keeps that depth target, as HDRP's frame does, and writes it back after its pass.
        depth = os.path.join(a.out, picture + "_depth.f32") if picture in ("hdrp_depth", "hdrp_lit") else None
        if picture == "hdrp_lit":       # what it loads, also kept as OUT/hdrp_lit_depth_in.f32 for the tests
            args = args + ["--depth-in", nudged(prepass, os.path.join(a.out, "hdrp_lit_depth_in.f32"), a.depth_nudge_ulps),
                           "--stencil-in", os.path.join(a.out, "hdrp_depth_stencil.u8")]
        if picture in ("hdrp_depth", "hdrp_lit"):     # the frame's stencil, as DepthForwardOnly and ForwardOnly leave it
            args = args + ["--stencil-out", os.path.join(a.out, picture + "_stencil.u8")]
        pp.draw(args, drawn if picture == "hdrp_depth" else buffers, os.path.join(a.out, picture + ".png"),
                os.path.join(folder, "harness.log"), depth_out=depth)
        if picture == "hdrp_depth":
            pp.write_view(scene, buffers, os.path.join(a.out, picture + "_view.json"))


def draw_shadowed(a, scene, picture, buffers, cascade, prepass, cam, o2w):
    """hdrp_shadow_map (the ShadowCaster into the atlas, with HDRP's depth bias) or hdrp_lit_shadows (ForwardOnly
    sampling it over the prepass's depth), under the shadowed frame's sun."""
    folder, n = os.path.join(a.out, picture), cascade.resolution
    texels = os.path.join(a.out, "hdrp_shadow_atlas.f32")
    Setting.world_offset = Setting.rounded_at = None
    Setting.shadow, Setting.atlas = cascade, (texels if picture == "hdrp_lit_shadows" else None)
    log = os.path.join(folder, "harness.log")
    if picture == "hdrp_shadow_map":
        args = pp.prepare(scene, "HDRP", "ShadowCaster", [], buffers, folder, scene=cascade.caster_values(), sun=cascade.sun)
        units, slope = HDRP_DEPTH_BIAS
        sign = -1.0 if a.flip_depth_bias else 1.0
        depth = os.path.join(a.out, picture + ".f32")
        pp.draw(args + ["--depth-bias", f"{sign * units:g},{sign * slope:g}"], buffers, None, log, (n, n), depth)
        pp.shadow_map_texels(depth, texels, n)
        if a.transpose_atlas:
            t = pp.read_floats(texels)
            with open(texels, "wb") as f:
                f.write(struct.pack(f"<{n * n}f", *[t[c * n + r] for r in range(n) for c in range(n)]))
    else:
        args = pp.prepare(scene, "HDRP", "ForwardOnly", ["SHADOW_LOW"], buffers, folder, sun=cascade.sun)
        check_buffer_reads(folder)
        pp.draw(args + ["--depth-in", prepass], buffers, os.path.join(a.out, picture + ".png"), log,
                depth_out=os.path.join(a.out, picture + "_depth.f32"))
        with open(os.path.join(a.out, "hdrp_shadow.json"), "w") as f:
            json.dump({"resolution": n, "texel": cascade.texel, "world_texel": cascade.world_texel, "depth_bias": HDRP_DEPTH_BIAS,
                       "normal_bias": HDRP_NORMAL_BIAS, "radius": cascade.radius, "camera_view_proj": cam.view_proj,
                       "object_to_world": o2w, "sun": cascade.sun}, f, indent=1)
    Setting.shadow = Setting.atlas = None


if __name__ == "__main__":
    main()
