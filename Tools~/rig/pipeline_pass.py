#!/usr/bin/env python3
"""gt pipeline_pass: draw a render pipeline's real passes of Shaders/GregoryTerrain.shader in the harness.

Each pass (URP's DepthOnly and ForwardLit, Built-in's ForwardBase; a variant by its keywords) is compiled exactly as
`gt shaderlab` compiles it (glslang, Unity's 2022.3 libraries in ../shared/unity-shaderlib,
shaderlab.py's emulation). Each stage's SPIR-V is reflected (spirv-cross --reflect); every resource
the pass declares gets one binding of set 0 from 16 up, by name, the same in every stage (glslang's
--auto-map-bindings numbers each stage on its own), and every uniform-block member and buffer is
filled BY NAME from the scene (the sample grid, RigScene's zoom view, a sun). A member the scene does
not set gets a named default: the run lists them ("defaults: ..."), the members each stage reads
(SPIR-V access chains: "reads ..."), and the defaulted members some stage reads ("defaulted_read").

Writes OUT/buffers (gt-cli pack), OUT/<picture>.png and OUT/<picture>/: the stages (bindings
rewritten), one file per binding, manifest.json (bindings, filled, defaults, reads, render state,
harness arguments) and harness.log. Pictures: depth (DepthOnly: depth in R, ColorMask R), lit
(ForwardLit, base variant), normals (ForwardLit with GT_DEBUG_NORMALS: world normal * 0.5 + 0.5),
lit_dxc (ForwardLit base from DXC's SPIR-V, legalised at -O0, unreferenced resources dropped),
builtin_lit (Built-in's ForwardBase, tessellated SubShader, base variant: one directional light),
shadow_map (URP's ShadowCaster drawn from the sun: OUT/shadow_map.f32, no PNG) and lit_shadows (ForwardLit
_MAIN_LIGHT_SHADOWS sampling it; OUT/lit_shadows_depth.f32 its camera depth; OUT/shadow.json the
light's matrices), both under --shadow-sun-elevation/--shadow-sun-azimuth; depth_normals (only with --only:
URP's DepthNormalsOnly, _GBUFFER_NORMALS_OCT, its depth in OUT/depth_normals_depth.f32, its view in
OUT/depth_normals_view.json) and depth_normals_snorm (only with --only: the base variant into R8G8B8A8_SNorm, the
PNG's bytes signed; _depth.f32, _view.json likewise), depth_normals_layers and lit_layers (only with --only: the
_WRITE_RENDERING_LAYERS variants, their second target's R8 bytes in OUT/<picture>_target1.bin), under --object-yaw;
lit_fog_* and builtin_fog_* (only with --only: the fog variants, linear/exp/exp2; _depth.f32, _view.json likewise);
builtin_lit_shadows (only with --only; draws builtin_shadow_map and builtin_camera_depth first): Built-in's screen-space
shadow (OUT/builtin_screen_shadow.f32 the collected texture, OUT/builtin_lit_shadows_depth.f32 ForwardBase's depth);
lit_cascades (only with --only): URP's cascaded shadow, --cascades of them (draw_cascades).
Uniform blocks are bound as storage buffers (--uniform-blocks storage: the harness rewrites the
blocks, same offsets): the rig's lavapipe rule (one compile per SPIR-V, whatever the values) on every device.

  gt pipeline_pass [--out DIR] [--only depth|lit|normals|lit_dxc|builtin_lit|shadow_map|lit_shadows|depth_normals|depth_normals_snorm|depth_normals_layers|lit_layers|lit_fog_*|builtin_fog_*|builtin_lit_shadows|lit_cascades]...
      [--sun-elevation DEG] [--sun-azimuth DEG] [--shadow-sun-elevation DEG] [--shadow-sun-azimuth DEG] [--light-color R,G,B]
      [--object-yaw DEG] [--cascades 2|4] [--leave-default NAME]... [--fill-from NAME=OTHER]... [--transpose NAME]...
      [--flip-shadow-bias] [--swap-cascade-matrices]
--leave-default / --fill-from / --transpose / --flip-shadow-bias break the scene on purpose (the tests' broken inputs): a
member left to its default, a member filled with another member's value, a matrix transposed (in each
pipeline whose scene sets the names).
"""
import argparse
import concurrent.futures
import json
import math
import os
import re
import struct
import shutil
import subprocess
import sys

RIG_DIR = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, RIG_DIR)
import options  # noqa: E402
import render_state  # noqa: E402
import shaderlab  # noqa: E402

PKG_DIR = os.path.dirname(os.path.dirname(RIG_DIR))
URP_PACKAGES = ["com.unity.render-pipelines.core", "com.unity.render-pipelines.universal",
                "com.unity.render-pipelines.universal-config"]
FIRST_BINDING = 16          # above the rig's 0..6 and the vertex cache's 7..9
STAGES = ("vert", "tesc", "tese", "frag")

# ---------------------------------------------------------------------------------------------
# Compile and reflect


def find_pass(pipeline, name):
    subs = shaderlab.parse_shader(os.path.join(PKG_DIR, "Shaders", "GregoryTerrain.shader"))
    for s in subs:      # the first SubShader of the pipeline: the tessellated one, as Unity picks it
        if s.pipeline == pipeline:
            for p in s.passes:
                if p.name == name:
                    return s, p
            raise SystemExit(f"pipeline-pass: error: {pipeline}'s first SubShader has no pass '{name}' "
                             f"(it has {', '.join(p.name for p in s.passes)})")
    raise SystemExit(f"pipeline-pass: error: no {pipeline} SubShader in GregoryTerrain.shader")


def compile_pass(sub, pas, out, tmp, keywords=(), compiler="glslang"):
    """{stage: spv path}: the pass's variant with exactly these keywords (none: the base variant),
    compiled as shaderlab does: glslang after its preprocessing and emulation, or DXC with its
    defines (shaderlab's DXC_DEFINES, DXC_EMULATED) legalised at -O0 (shaderlab stops at -fcgl,
    which no driver can run)."""
    lib = os.path.abspath(os.path.join(PKG_DIR, "..", "shared", "unity-shaderlib"))
    rig = shaderlab.Rig(PKG_DIR, lib, tmp, 1, None, None)
    includes = rig.include_root(sub.pipeline.lower(), INCLUDE_PACKAGES[sub.pipeline])
    dxc = os.path.abspath(os.path.join(PKG_DIR, "..", "shared", "dxc", "bin", "dxc"))
    cases = [c for c in shaderlab.shader_cases([sub], "Shaders/GregoryTerrain.shader", tmp, "pp", "all")
             if c.label.startswith(f"{sub.pipeline} sub{sub.index} {pas.name} ") and sorted(c.keywords) == sorted(keywords)]

    def one(case):
        spv = os.path.join(out, f"{case.stage}.spv")
        if compiler == "dxc":
            c = subprocess.run([dxc, "-HV", "2018", "-spirv", "-T", shaderlab.DXC_PROFILES[case.stage], "-E", case.entry,
                                "-O0", "-Fo", spv] + [f"-I{d}" for d in includes]
                               + [f"-D{d}" for d in case.defines() + shaderlab.DXC_DEFINES + shaderlab.DXC_EMULATED]
                               + [case.source], capture_output=True, text=True)
            if c.returncode != 0:
                raise SystemExit(f"pipeline-pass: error: DXC on {case.label} failed:\n{c.stdout}{c.stderr}")
            # -O0 keeps every resource the headers declare (18 textures, 15 samplers in ForwardLit's
            # fragment stage); this drops the ones no function refers to, and changes nothing else.
            d = subprocess.run(["spirv-opt", "--eliminate-dead-variables", spv, "-o", spv], capture_output=True, text=True)
            if d.returncode != 0:
                raise SystemExit(f"pipeline-pass: error: spirv-opt on {spv} failed:\n{d.stdout}{d.stderr}")
            return case.stage, spv
        pre = subprocess.run(["glslangValidator", "-D", "-E", "-S", case.stage, "-e", case.entry]
                             + [f"-I{d}" for d in includes] + [f"-D{d}" for d in case.defines()] + [case.source],
                             capture_output=True, text=True)
        if pre.returncode != 0:
            raise SystemExit(f"pipeline-pass: error: preprocessing {case.label} failed:\n{pre.stdout}{pre.stderr}")
        text, _ = shaderlab.emulate(pre.stdout)
        src = os.path.join(tmp, f"{case.stage}.hlsl")
        with open(src, "w", encoding="utf-8") as f:
            f.write(text)
        c = subprocess.run(["glslangValidator", "-D", "-V", "-S", case.stage, "-e", case.entry,
                            "--auto-map-bindings", "--hlsl-iomap", "-o", spv, src], capture_output=True, text=True)
        if c.returncode != 0:
            raise SystemExit(f"pipeline-pass: error: compiling {case.label} failed:\n{c.stdout}{c.stderr}")
        return case.stage, spv

    # Two at a time: the stages are independent compiles, and the rig's machines have two cores.
    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        return dict(pool.map(one, cases))


def reflect(spv):
    r = subprocess.run(["spirv-cross", spv, "--reflect"], capture_output=True, text=True)
    if r.returncode != 0:
        raise SystemExit(f"pipeline-pass: error: spirv-cross --reflect {spv}: {r.stderr}")
    return json.loads(r.stdout)


def resources(refl):
    """[(kind, name, set, binding, members or None, size)] of one stage. kind: uniform | storage, or
    the reflection's key for images and samplers, whose size is then their type (texture2DArray, ...)."""
    out = []
    for kind, key in (("uniform", "ubos"), ("storage", "ssbos")):
        for u in refl.get(key, []):
            t = refl["types"][u["type"]]
            name = u["name"][len("type."):] if u["name"].startswith("type.") else u["name"]   # DXC's block names
            out.append((kind, name, u["set"], u["binding"], t["members"], u.get("block_size", 0)))
    for key in ("textures", "separate_images", "separate_samplers", "images"):
        for u in refl.get(key, []):
            out.append((key, u["name"], u["set"], u["binding"], None, u.get("type", "")))
    return out


# ---------------------------------------------------------------------------------------------
# SPIR-V: rewrite bindings, find the members each stage reads

OP_NAME, OP_DECORATE, OP_CONSTANT, OP_LOAD, OP_ACCESS_CHAIN, OP_IN_BOUNDS_ACCESS_CHAIN = 5, 71, 43, 61, 65, 66
DEC_BINDING, DEC_SET = 33, 34


def spirv_words(path):
    with open(path, "rb") as f:
        data = f.read()
    return list(struct.unpack(f"<{len(data) // 4}I", data))


def instructions(words):
    i = 5
    while i < len(words):
        n, op = words[i] >> 16, words[i] & 0xFFFF
        yield i, op, words[i + 1:i + n]
        i += n


def variable_bindings(words):
    """{variable id: binding} from OpDecorate Binding."""
    return {ops[0]: ops[2] for _, op, ops in instructions(words) if op == OP_DECORATE and ops[1] == DEC_BINDING}


def rebind(path, mapping):
    """Rewrites each Binding decoration old -> mapping[old] and every DescriptorSet to 0, in place."""
    words = spirv_words(path)
    for i, op, ops in instructions(words):
        if op == OP_DECORATE and ops[1] == DEC_BINDING:
            words[i + 3] = mapping[ops[2]]
        elif op == OP_DECORATE and ops[1] == DEC_SET:
            words[i + 3] = 0
    with open(path, "wb") as f:
        f.write(struct.pack(f"<{len(words)}I", *words))


def members_read(words, binding, members):
    """Names of the block's members some access chain of the module reads (all of them when the
    whole block is loaded)."""
    var = [v for v, b in variable_bindings(words).items() if b == binding]
    constants = {ops[1]: ops[2] for _, op, ops in instructions(words) if op == OP_CONSTANT and len(ops) >= 3}
    read = set()
    for _, op, ops in instructions(words):
        if op in (OP_ACCESS_CHAIN, OP_IN_BOUNDS_ACCESS_CHAIN) and ops[2] in var and len(ops) > 3:
            read.add(members[constants[ops[3]]]["name"])
        elif op == OP_LOAD and ops[2] in var:
            read.update(m["name"] for m in members)
    return read


# ---------------------------------------------------------------------------------------------
# The scene: a Unity camera and main light, in Unity's conventions


def mat_mul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(4)) for j in range(4)] for i in range(4)]


def affine_inverse(m):
    """Inverse of an affine 4x4 (last row 0 0 0 1): the 3x3 by cofactors, then the translation."""
    a = [row[:3] for row in m[:3]]
    det = (a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0])
           + a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]))
    inv = [[(a[(j + 1) % 3][(i + 1) % 3] * a[(j + 2) % 3][(i + 2) % 3]
             - a[(j + 1) % 3][(i + 2) % 3] * a[(j + 2) % 3][(i + 1) % 3]) / det for j in range(3)] for i in range(3)]
    t = [-sum(inv[i][k] * m[k][3] for k in range(3)) for i in range(3)]
    return [inv[0] + [t[0]], inv[1] + [t[1]], inv[2] + [t[2]], [0.0, 0.0, 0.0, 1.0]]


def general_inverse(m):
    """Gauss-Jordan with partial pivoting (projection matrices are not affine)."""
    n = [row[:] + [1.0 if i == j else 0.0 for j in range(4)] for i, row in enumerate(m)]
    for c in range(4):
        p = max(range(c, 4), key=lambda r: abs(n[r][c]))
        n[c], n[p] = n[p], n[c]
        pivot = n[c][c]
        n[c] = [x / pivot for x in n[c]]
        for r in range(4):
            if r != c:
                f = n[r][c]
                n[r] = [x - f * y for x, y in zip(n[r], n[c])]
    return [row[4:] for row in n]


def normalize(v):
    s = math.sqrt(sum(x * x for x in v))
    return [x / s for x in v]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def read_floats(path):
    with open(path, "rb") as f:
        data = f.read()
    return list(struct.unpack(f"<{len(data) // 4}f", data))


def columns_to_matrix(f):
    """HLSL's default column_major packing (RigCamera.WriteColumns): column after column."""
    return [[f[col * 4 + row] for col in range(4)] for row in range(4)]


class Camera:
    """RigScene.ZoomViewCamera's view (eye, target, 50 degrees, near 0.01, far 20) as Unity's Camera
    has it: worldToCameraMatrix looking down -z (right-handed camera space), and the GPU projection
    Unity builds for Vulkan (GL.GetGPUProjectionMatrix): reversed depth, near 1, far 0 (UNITY_REVERSED_Z),
    clip y up, not flipped (rendering to the camera's target: _ProjectionParams.x = 1; the harness's
    negative viewport height shows it upright)."""

    def __init__(self, eye, target, fov_y, width, height, near, far):
        self.eye, self.width, self.height, self.near, self.far = eye, width, height, near, far
        self.target, self.fov_y = target, fov_y
        self.view = Camera.look_along(eye, normalize([t - e for t, e in zip(target, eye)]))
        t = 1.0 / math.tan(math.radians(fov_y) / 2.0)
        zz, zw = near / (far - near), near * far / (far - near)
        self.proj = [[t * height / width, 0, 0, 0], [0, t, 0, 0], [0, 0, zz, zw], [0, 0, -1, 0]]
        self.view_proj = mat_mul(self.proj, self.view)

    @staticmethod
    def look_along(eye, f):
        """Unity's worldToCameraMatrix of a camera at eye looking along the unit vector f (camera space
        right-handed, looking down -z)."""
        up = [0.0, 0.0, 1.0] if abs(f[1]) > 0.99 else [0.0, 1.0, 0.0]
        r = normalize(cross(up, f))       # left-handed world: right = up x forward
        u = cross(f, r)
        return [r + [-dot(r, eye)], u + [-dot(u, eye)], [-x for x in f] + [dot(f, eye)], [0.0, 0.0, 0.0, 1.0]]


def rig_camera(buffers):
    """The zoom view of RigScene.ZoomViewCamera (Tools~/dotnet/Gt/RigScene.cs) and camera.f32's
    object-to-world; checks that P V O2W equals camera.f32's object-to-clip, so both draw the same view."""
    cam = read_floats(os.path.join(buffers, "camera.f32"))
    o2c, o2w = columns_to_matrix(cam[0:16]), columns_to_matrix(cam[16:32])
    width, height = int(round(cam[36])), int(round(cam[37]))
    c = Camera([0.0, 0.75, -1.05], [0.0, -0.05, 0.0], 50.0, width, height, 0.01, 20.0)
    mine = mat_mul(c.view_proj, o2w)
    worst = max(abs(mine[i][j] - o2c[i][j]) / max(1.0, abs(o2c[i][j])) for i in range(4) for j in range(4))
    if worst > 1e-5:
        raise SystemExit(f"pipeline-pass: error: {buffers}/camera.f32 is not RigScene's zoom view "
                         f"(object-to-clip differs by {worst:.3g}); pack it with gt-cli pack defaults")
    return c, o2w, o2c


def sun_direction(elevation, azimuth):
    """Towards the sun, world space: elevation above the horizon, azimuth from +z towards +x."""
    e, a = math.radians(elevation), math.radians(azimuth)
    return [math.cos(e) * math.sin(a), math.sin(e), math.cos(e) * math.cos(a)]


def urp_globals(cam, o2w, o2c, sun, light_color):
    """$Global members by name, each with where its value and layout come from. Paths are under
    ../shared/unity-shaderlib/srp-14.0.9/com.unity.render-pipelines.universal/ShaderLibrary/ unless named."""
    w, h, n, f = cam.width, cam.height, cam.near, cam.far
    inv_vp = general_inverse(cam.view_proj)
    return {
        # UnityInput.hlsl:217 unity_MatrixVP, used as UNITY_MATRIX_VP (Input.hlsl:194) by
        # TransformWorldToHClip; URP sets it from the camera's GPU projection times its view.
        "unity_MatrixVP": cam.view_proj,
        "unity_MatrixV": cam.view,                       # UnityInput.hlsl: worldToCameraMatrix
        "unity_MatrixInvV": affine_inverse(cam.view),
        "unity_MatrixInvP": general_inverse(cam.proj),
        "unity_MatrixInvVP": inv_vp,
        "glstate_matrix_projection": cam.proj,           # UNITY_MATRIX_P (Input.hlsl)
        "unity_CameraProjection": cam.proj,
        "unity_CameraInvProjection": general_inverse(cam.proj),
        "unity_WorldToCamera": cam.view,
        "unity_CameraToWorld": affine_inverse(cam.view),
        "_ViewProjMatrix": cam.view_proj, "_NonJitteredViewProjMatrix": cam.view_proj,
        "_PrevViewProjMatrix": cam.view_proj, "_ViewMatrix": cam.view, "_ProjMatrix": cam.proj,
        "_InvViewProjMatrix": inv_vp, "_InvViewMatrix": affine_inverse(cam.view),
        "_InvProjMatrix": general_inverse(cam.proj),
        "_WorldSpaceCameraPos": cam.eye,                 # UnityInput.hlsl:47
        # UnityInput.hlsl:50-54: x = 1 (not flipped), near, far, 1/far.
        "_ProjectionParams": [1.0, n, f, 1.0 / f],
        # UnityInput.hlsl:56-60: width, height, 1 + 1/width, 1 + 1/height.
        "_ScreenParams": [w, h, 1.0 + 1.0 / w, 1.0 + 1.0 / h],
        "_ScaledScreenParams": [w, h, 1.0 + 1.0 / w, 1.0 + 1.0 / h],   # Input.hlsl: render scale 1
        "_ScreenSize": [w, h, 1.0 / w, 1.0 / h],
        # UnityInput.hlsl:62-72, reversed depth: (-1 + far/near, 1, x/far, 1/far).
        "_ZBufferParams": [-1.0 + f / n, 1.0, (-1.0 + f / n) / f, 1.0 / f],
        "unity_OrthoParams": [w / h, 1.0, 0.0, 0.0],     # UnityInput.hlsl:74-78: w = 0, perspective
        # Input.hlsl:101-103; URP's ForwardLights.SetupMainLightConstants: a directional light's
        # position is the direction towards it, w = 0; its colour is light.finalColor (linear colour
        # times intensity).
        "_MainLightPosition": sun + [0.0],
        "_MainLightColor": light_color + [1.0],
        "_MainLightOcclusionProbes": [0.0, 0.0, 0.0, 0.0],
        "_MainLightLayerMask": 0xFFFFFFFF,               # every rendering layer (URP: light's layer mask)
        # UnityInput.hlsl:117 (UnityPerDraw); RealtimeLights.hlsl:108: z is 1 when the light is not
        # culled by the culling mask (GetMainLight's distanceAttenuation). DXC's SPIR-V loads it,
        # glslang's drops the unused load.
        "unity_LightData": [0.0, 0.0, 1.0, 0.0],
        "_GlobalMipBias": [0.0, 1.0],                    # Input.hlsl: (bias, 2^bias)
        # UnityInput.hlsl:85, read by TransformScreenUV (ShaderVariablesFunctions.hlsl:433-437) under
        # UNITY_UV_STARTS_AT_TOP. URP 14's DrawObjectsPass.Execute sets it before the opaque list from
        # cameraData.IsCameraProjectionMatrixFlipped(): not flipped (the camera's target) -> (1, 0, 1, 1).
        "_ScaleBiasRt": [1.0, 0.0, 1.0, 1.0],
        # UnityInput.hlsl (UnityPerDraw): x holds the draw's rendering layer mask as bits (GetMeshRenderingLayer:
        # asuint(unity_RenderingLayer.x)), from RenderParams.renderingLayerMask for Graphics.RenderPrimitives.
        "unity_RenderingLayer": [uint_bits_as_float(RENDERING_LAYER_MASK), 0.0, 0.0, 0.0],
        # Input.hlsl:112-113, RenderingLayerUtils.SetupProperties(maskSize) before the passes that write the
        # rendering-layers target: 2^bits - 1 and its reciprocal (8 bits: the default 8 layers' R8_UNorm target).
        "_RenderingLayerMaxInt": (1 << RENDERING_LAYER_BITS) - 1,
        "_RenderingLayerRcpMaxInt": 1.0 / ((1 << RENDERING_LAYER_BITS) - 1),
        # The package's own (UnityAdapterCommon.hlsl:17-29, GregoryTerrainRenderer sets them):
        # object <-> world of the renderer's Transform, the camera's object-to-clip and screen size
        # that choose tessellation factors.
        "_GtObjectToWorld": o2w,
        "_GtWorldToObject": affine_inverse(o2w),
        "_GtTessObjectToClip": o2c,
        "_GtTessScreenSize": [w, h, 1.0 / w, 1.0 / h],
    }


# The draw's rendering layers: layers 0, 2, 5 and 7, and bit 8, which an 8-bit target drops
# (EncodeMeshRenderingLayer masks with _RenderingLayerMaxInt). Unity's default mask is 1 (layer 0).
RENDERING_LAYER_MASK = 0x1A5
RENDERING_LAYER_BITS = 8     # RenderingLayerUtils.MaskSize.Bits8: R8_UNorm (GetFormat), up to 8 layers defined


def uint_bits_as_float(u):
    """The float whose bits are u (Unity stores unity_RenderingLayer's mask so; small masks are denormals)."""
    return struct.unpack("<f", struct.pack("<I", u))[0]


# URP's main-light shadow, one cascade, as URP 14 sets it. C# under
# com.unity.render-pipelines.universal/Runtime/ (read through the code search; not in ../shared):
# ShadowUtils.cs ExtractDirectionalLightMatrix, GetShadowTransform, GetShadowBias,
# SetupShadowCasterConstantBuffer, RenderShadowSlice; Passes/MainLightShadowCasterPass.cs
# RenderMainLightCascadeShadowmap, SetupMainLightShadowReceiverConstants.
SHADOW_RESOLUTION = 2048     # the URP asset's default main-light shadow resolution
SHADOW_DISTANCE = 3.0        # max shadow distance (world units): the zoom view's terrain is within 1.8 of the eye
SHADOW_DEPTH_BIAS = 1.0      # the URP asset's default Depth Bias and Normal Bias, in shadow-map texels
SHADOW_NORMAL_BIAS = 1.0
SHADOW_NEAR_PLANE = 0.2      # Light.shadowNearPlane's default: how far the light's near plane is pulled back
CASCADE_BORDER = 0.2         # the URP asset's default cascade border (the last cascade's fade), a fraction


def culling_sphere(cam, near, far):
    """(centre, radius) of the smallest sphere centred on the view axis that holds the camera frustum's slice from
    view distance near to far (near 0: the eye): equidistant from the slice's near and far corners, or centred on the
    far plane when that sphere already holds the near corners."""
    per_distance = math.tan(math.radians(cam.fov_y) / 2.0) * math.sqrt(1.0 + (cam.width / cam.height) ** 2)
    half_near, half_far = near * per_distance, far * per_distance      # the slice's half diagonals
    along = min((far ** 2 + half_far ** 2 - near ** 2 - half_near ** 2) / (2.0 * (far - near)), far)
    # From the eye (near 0) the distance is along itself; else to a far corner.
    radius = along if near == 0.0 else math.sqrt((far - along) ** 2 + half_far ** 2)
    forward = normalize([x - e for x, e in zip(cam.target, cam.eye)])
    return [e + along * f for e, f in zip(cam.eye, forward)], radius


class MainLightShadow:
    """The shadow slice Unity's CullingResults.ComputeDirectionalShadowMatricesAndCullingPrimitives
    returns for one cascade (native code, not public: its documented behaviour) and what URP makes of it.
    The culling sphere encloses the camera's frustum from near to the shadow distance: the rig takes the
    smallest sphere centred on the view axis through the slice's far corners. view: the light's
    world-to-camera (right-handed, looking down -z along the light's forward, -sun); proj: an
    OpenGL-style orthographic projection of the sphere (z_gl -1 at near; Unity leaves it unreversed,
    GetShadowTransform says so), its depth from the sphere's far side to SHADOW_NEAR_PLANE beyond its near side."""

    def __init__(self, cam, sun, resolution=SHADOW_RESOLUTION, distance=SHADOW_DISTANCE, slice_near=0.0, slice_far=None):
        self.resolution, self.distance = resolution, distance
        self.center, self.radius = culling_sphere(cam, slice_near, distance if slice_far is None else slice_far)
        r = self.radius
        light_forward = [-x for x in sun]
        eye = [c - (r + SHADOW_NEAR_PLANE) * f for c, f in zip(self.center, light_forward)]
        self.view = Camera.look_along(eye, light_forward)
        near, far = 0.0, 2.0 * r + SHADOW_NEAR_PLANE
        self.proj = [[1.0 / r, 0, 0, 0], [0, 1.0 / r, 0, 0], [0, 0, -2.0 / (far - near), -(far + near) / (far - near)],
                     [0, 0, 0, 1.0]]
        # What the ShadowCaster pass draws with: Unity's GPU projection of proj on Vulkan (reversed depth:
        # z = (w - z_gl) / 2, near 1, far 0). Unity renders into the shadow texture with clip y flipped
        # and culling inverted; the rig draws y unflipped (same faces kept) and flips the map's rows
        # instead (shadow_map_texels), so texture row 0 is v = 0 as GetShadowTransform's 0.5 y + 0.5 expects.
        gpu = [row[:] for row in self.proj]
        gpu[2] = [0.5 * w - 0.5 * z for z, w in zip(self.proj[2], self.proj[3])]
        self.gpu_proj = gpu
        self.view_proj = mat_mul(gpu, self.view)
        # GetShadowTransform: z row negated under reversed depth, then x, y, z mapped from [-1, 1] to [0, 1].
        reversed_proj = [row[:] for row in self.proj]
        reversed_proj[2] = [-x for x in self.proj[2]]
        scale_bias = [[0.5, 0, 0, 0.5], [0, 0.5, 0, 0.5], [0, 0, 0.5, 0.5], [0, 0, 0, 1.0]]
        self.world_to_shadow = mat_mul(scale_bias, mat_mul(reversed_proj, self.view))
        # GetShadowBias, directional: frustum size 2 / proj.m00, one texel = size / resolution; both
        # biases negative (casters pushed away from the light and into their surface). Hard shadows:
        # no soft-shadow kernel factor.
        self.texel = 2.0 / self.proj[0][0] / resolution
        self.bias = [-SHADOW_DEPTH_BIAS * self.texel, -SHADOW_NORMAL_BIAS * self.texel, 0.0, 0.0]
        self.sun, self.eye = sun, eye

    def fade(self):
        """ShadowUtils.GetScaleAndBiasForLinearDistanceFade(maxShadowDistance^2, border): a linear fade
        of the squared camera distance over the last (1 - (1 - border)^2) of it."""
        d2 = self.distance ** 2
        near = (1.0 - CASCADE_BORDER) ** 2 * d2
        return 1.0 / (d2 - near), -near / (d2 - near)

    def caster_values(self):
        """ShadowUtils.SetupShadowCasterConstantBuffer and RenderShadowSlice's SetViewProjectionMatrices(view, proj)."""
        return {"_ShadowBias": self.bias,
                "_LightDirection": self.sun,                 # -localToWorld column 2: towards the light
                "_LightPosition": self.eye + [1.0],          # localToWorld column 3 (read by punctual lights only)
                "unity_MatrixVP": self.view_proj, "unity_MatrixV": self.view, "glstate_matrix_projection": self.gpu_proj,
                "unity_MatrixInvV": affine_inverse(self.view), "unity_MatrixInvP": general_inverse(self.gpu_proj),
                "unity_MatrixInvVP": general_inverse(self.view_proj)}

    def receiver_values(self):
        """MainLightShadowCasterPass.SetupMainLightShadowReceiverConstants with one cascade."""
        n = self.resolution
        no_op = [[0.0] * 4 for _ in range(4)]
        no_op[2][2] = 1.0                                    # the unused cascades' no-op (reversed depth: z = 1)
        fade_scale, fade_bias = self.fade()
        return {"_MainLightWorldToShadow": [self.world_to_shadow] + [no_op] * 4,
                # (shadowStrength 1: the Light's default, soft shadows 0: hard, fade scale, fade bias)
                "_MainLightShadowParams": [1.0, 0.0, fade_scale, fade_bias],
                # set when the asset supports soft shadows (its default): half-texel offsets and the size
                "_MainLightShadowOffset0": [-0.5 / n, -0.5 / n, 0.5 / n, -0.5 / n],
                "_MainLightShadowOffset1": [-0.5 / n, 0.5 / n, 0.5 / n, 0.5 / n],
                "_MainLightShadowmapSize": [1.0 / n, 1.0 / n, float(n), float(n)]}


# URP 14's main-light cascades (_MAIN_LIGHT_SHADOWS_CASCADE), as its C# sets them up (read through the code search):
# UniversalRenderPipelineAsset's defaults m_Cascade2Split 0.25 and m_Cascade4Split (0.067, 0.2, 0.467), fractions of
# the shadow distance where each cascade ends (the asset's default count is 1: choosing 2 or 4 takes these);
# UniversalRenderPipeline.InitializeShadowData: the atlas is resolution^2, or resolution x resolution / 2 for 2 cascades;
# MainLightShadowCasterPass.Setup: each cascade's tile ShadowUtils.GetMaxTileResolutionInAtlas(width, height, count);
# ShadowUtils.ExtractDirectionalLightMatrix: cascade i's tile at ((i % 2) x tile, (i / 2) x tile), its
# GetShadowTransform times ApplySliceTransform's scale and offset into the atlas; RenderMainLightCascadeShadowmap:
# each cascade's ShadowCaster with GetShadowBias of its own projection and tile (RenderShadowSlice: viewport = the
# tile); SetupMainLightShadowReceiverConstants: _MainLightWorldToShadow[i] per cascade, the no-op at [count] (the
# others identity, as Clear() leaves them), _CascadeShadowSplitSpheres0..3 the culling spheres (centre, radius; zero
# past count), _CascadeShadowSplitSphereRadii their squared radii, offsets and size of the whole atlas.
CASCADE_SPLITS = {2: [0.25], 4: [0.067, 0.2, 0.467]}


def max_tile_resolution(width, height, count):
    """ShadowUtils.GetMaxTileResolutionInAtlas: halve the tile until count of them fit."""
    tile = min(width, height)
    while (width // tile) * (height // tile) < count:
        tile //= 2
    return tile


class MainLightCascades:
    """count (2 or 4) cascades of the main light: slices[i] is cascade i's MainLightShadow (its culling sphere around
    the camera's frustum from the previous split to its own, its tile's resolution and bias); world_to_shadow[i] its
    GetShadowTransform moved into its atlas tile."""

    def __init__(self, cam, sun, count, resolution=SHADOW_RESOLUTION, distance=SHADOW_DISTANCE):
        if count not in CASCADE_SPLITS:
            raise SystemExit(f"pipeline-pass: error: cascade count {count}: URP's asset offers 2 or 4 (1 is MainLightShadow)")
        self.count, self.distance, self.sun = count, distance, sun
        self.width, self.height = resolution, resolution // 2 if count == 2 else resolution
        self.tile = max_tile_resolution(self.width, self.height, count)
        ends = [f * distance for f in CASCADE_SPLITS[count]] + [distance]
        starts = [0.0] + ends[:-1]
        self.slices = [MainLightShadow(cam, sun, self.tile, distance, a, b) for a, b in zip(starts, ends)]
        self.offsets = [((i % 2) * self.tile, (i // 2) * self.tile) for i in range(count)]
        self.world_to_shadow = [mat_mul(self.slice_transform(i), sl.world_to_shadow) for i, sl in enumerate(self.slices)]

    def slice_transform(self, i):
        """ShadowUtils.ApplySliceTransform: [0, 1] of the tile to its place in the atlas."""
        (x, y), t = self.offsets[i], self.tile
        return [[t / self.width, 0, 0, x / self.width], [0, t / self.height, 0, y / self.height], [0, 0, 1.0, 0],
                [0, 0, 0, 1.0]]

    def receiver_values(self, swap=None):
        """SetupMainLightShadowReceiverConstants with count cascades; swap=(i, j) exchanges two cascades' matrices (a
        broken input)."""
        identity = [[1.0 if r == c else 0.0 for c in range(4)] for r in range(4)]
        no_op = [[0.0] * 4 for _ in range(4)]
        no_op[2][2] = 1.0
        matrices = self.world_to_shadow + [no_op] + [identity] * (4 - self.count)
        if swap:
            matrices[swap[0]], matrices[swap[1]] = matrices[swap[1]], matrices[swap[0]]
        spheres = [sl.center + [sl.radius] for sl in self.slices] + [[0.0] * 4] * (4 - self.count)
        w, h = self.width, self.height
        fade_scale, fade_bias = self.slices[-1].fade()
        values = {"_MainLightWorldToShadow": matrices, "_MainLightShadowParams": [1.0, 0.0, fade_scale, fade_bias],
                  "_CascadeShadowSplitSphereRadii": [sp[3] ** 2 for sp in spheres],
                  "_MainLightShadowOffset0": [-0.5 / w, -0.5 / h, 0.5 / w, -0.5 / h],
                  "_MainLightShadowOffset1": [-0.5 / w, 0.5 / h, 0.5 / w, 0.5 / h],
                  "_MainLightShadowmapSize": [1.0 / w, 1.0 / h, float(w), float(h)]}
        values.update({f"_CascadeShadowSplitSpheres{i}": spheres[i] for i in range(4)})
        return values

    def cascade_index(self, world):
        """Shadows.hlsl's ComputeCascadeIndex: the first cascade whose sphere holds the point (squared distance below
        the squared radius), count when none does."""
        for i, sl in enumerate(self.slices):
            if sum((a - b) ** 2 for a, b in zip(world, sl.center)) < sl.radius ** 2:
                return i
        return self.count

    def atlas(self, tile_files, path):
        """The atlas's texels (row 0 at v = 0) from each cascade's tile (shadow_map_texels' rows), cleared to 0 (URP
        clears the map; reversed depth's far plane) where no tile lies."""
        t, w = self.tile, self.width
        texels = [0.0] * (w * self.height)
        for (x, y), f in zip(self.offsets, tile_files):
            tile = read_floats(f)
            for row in range(t):
                texels[(y + row) * w + x:(y + row) * w + x + t] = tile[row * t:(row + 1) * t]
        with open(path, "wb") as f:
            f.write(struct.pack(f"<{len(texels)}f", *texels))


# The Scene view's selection outline (SceneSelectionPass) and picking (LightMode Picking): the editor sets their
# values natively when it draws those passes; Unity 2022.3's C# reference holds neither. Picking: _SelectionID is the
# picking index as 4 bytes / 255, low byte in x, as picking.cpp's PickingEncodeIndex writes it (mirrored in C# by
# HandleUtility.EncodeSelectionId / DecodeSelectionId, Editor/Mono/Handles/HandleUtility.cs in Unity 6's reference;
# the passes read it through URP's UniversalDOTSInstancing.hlsl:68 / HDRP's ShaderVariables.hlsl:666 as
# unity_SelectionID). Selection: the shader writes (_ObjectId, _PassValue, 1, 1) (URP's SelectionPickingPass.hlsl:32,
# HDRP's ShaderPassDepthOnly.hlsl:112): the rig's renderer is object 1 of the outline's first pass (0). Both chosen
# so each byte of the target is distinct from the clear and from a default of zero.
EDITOR_OBJECT_ID, EDITOR_PASS_VALUE = 1, 0
PICKING_INDEX = 0x00A5C3


def encode_selection_id(index):
    """HandleUtility.EncodeSelectionId: the picking index's bytes, low first, each / 255."""
    return [((index >> shift) & 0xFF) / 255.0 for shift in (0, 8, 16, 24)]


def decode_selection_id(rgba):
    """HandleUtility.DecodeSelectionId of a pixel's four 8-bit channels."""
    return rgba[0] | rgba[1] << 8 | rgba[2] << 16 | rgba[3] << 24


def editor_pass_values(pass_name):
    """What the editor sets for its SceneSelectionPass / ScenePickingPass draw, else {}."""
    if pass_name == "SceneSelectionPass":
        return {"_ObjectId": EDITOR_OBJECT_ID, "_PassValue": EDITOR_PASS_VALUE}
    if pass_name == "ScenePickingPass":
        return {"_SelectionID": encode_selection_id(PICKING_INDEX)}
    return {}


# URP's screen-space textures that a frame draws before ForwardLit, given a content the checks can see: the left half
# of the screen unoccluded, the right half at a known level (the rig has no depth texture pass for them to read).
# _ScreenSpaceShadowmapTexture (ScreenSpaceShadows' R8_UNorm target, 1 = lit; Shadows.hlsl:181-195 samples it with
# sampler_PointClamp at the pixel's normalized screen uv): right half 0, every pixel there in the main light's shadow.
# _ScreenSpaceOcclusionTexture (the SSAO feature's result, 1 = unoccluded; AmbientOcclusion.hlsl:17-35): right half
# SSAO_LEVEL; _AmbientOcclusionParam is what URP 14's ScreenSpaceAmbientOcclusionPass sets with the texture,
# (0, 0, 0, DirectLightingStrength), its setting's default 0.25: direct light x lerp(1, ao, 0.25), ambient x ao.
SCREEN_SHADOW_RIGHT = 0.0
SSAO_LEVEL = 0.5
SSAO_DIRECT_STRENGTH = 0.25


def ssao_values():
    return {"_AmbientOcclusionParam": [0.0, 0.0, 0.0, SSAO_DIRECT_STRENGTH]}


def screen_halves(path, width, height, right):
    """A width x height R32 texture (rows top first, as the harness's targets): 1 left of width / 2, right beyond."""
    row = [1.0] * (width // 2) + [right] * (width - width // 2)
    with open(path, "wb") as f:
        f.write(struct.pack(f"<{width * height}f", *(row * height)))
    return "R32_SFLOAT", path, width, height


# Built-in's main directional light shadow as Built-in draws it in Forward on desktop (screen-space shadows): the
# scene's ShadowCaster pass from the light into the shadow map, the same pass from the camera into
# _CameraDepthTexture, a collect step that writes the screen-space shadow texture, and ForwardBase's SHADOWS_SCREEN
# variant sampling it at the pixel (AutoLight.cginc:40-49: UNITY_DECLARE_SCREENSPACE_SHADOWMAP(_ShadowMapTexture),
# unitySampleShadow's UNITY_SAMPLE_SCREEN_SHADOW). The light's view, projection and world-to-shadow are
# MainLightShadow's (one cascade: the culling sphere's orthographic view, unity_WorldToShadow[0] with z reversed).
BUILTIN_SHADOW_DEPTH_BIAS = 1.0     # texels; Unity scales Light.shadowBias natively (not public): one texel, as URP's
BUILTIN_SHADOW_NORMAL_BIAS = 0.4    # texels: Light.shadowNormalBias's default (the scripting reference: in shadow-map texels)


def builtin_caster_values(shadow, flip_bias=False):
    """The ShadowCaster pass from the light (UnityShaderVariables.cginc:156 unity_LightShadowBias, read by
    UnityApplyLinearShadowBias, UnityCG.cginc:936-959): x the depth bias in clip z (reversed depth: negative moves
    the caster away from the light; the orthographic clip z spans the light's depth range once), y 1 for a
    directional light (casters nearer than the near plane clamped onto it), z the normal bias in world units
    ("scaled by world space texel size", UnityCG.cginc:917-918; UnityClipSpaceShadowCasterPos, 904-928, which the
    adapter's GT_ObjectToShadowClip follows). flip_bias: the depth bias's sign flipped (a broken input)."""
    depth_range = -2.0 / shadow.proj[2][2]
    x = -BUILTIN_SHADOW_DEPTH_BIAS * shadow.texel / depth_range
    return {"unity_MatrixVP": shadow.view_proj, "unity_MatrixV": shadow.view, "glstate_matrix_projection": shadow.gpu_proj,
            "unity_MatrixInvV": affine_inverse(shadow.view),
            "unity_LightShadowBias": [-x if flip_bias else x, 1.0, BUILTIN_SHADOW_NORMAL_BIAS * shadow.texel, 0.0],
            "_WorldSpaceLightPos0": shadow.sun + [0.0]}


def builtin_camera_depth_values():
    """The ShadowCaster pass from the camera into _CameraDepthTexture: the camera's matrices (builtin_globals), no
    light, so no shadow bias (x 0 adds nothing, y 0 leaves z unclamped: UnityCG.cginc:946, 957) and no light
    position (a caster that normalizes it regardless draws NaN: UnityCG.cginc:908 tests z first)."""
    return {"unity_LightShadowBias": [0.0, 0.0, 0.0, 0.0], "_WorldSpaceLightPos0": [0.0, 0.0, 0.0, 0.0]}


def builtin_collect_values(shadow):
    """What the collect step reads (UnityShaderVariables.cginc:159-160): unity_WorldToShadow[0] (one cascade: the
    others the no-op URP sets, z = 1) and _LightShadowData.x, 1 - the light's shadow strength (1: the Light's
    default), the shadowed value lerp(x, 1, lit) reaches."""
    no_op = [[0.0] * 4 for _ in range(4)]
    no_op[2][2] = 1.0
    return {"unity_WorldToShadow": [shadow.world_to_shadow] + [no_op] * 3, "_LightShadowData": [0.0, 0.0, 0.0, 0.0]}


def collect_screen_shadows(camera_depth, map_texels, cam, shadow, values, out_path):
    """Unity's screen-space shadow collect (Internal-ScreenSpaceShadows, one cascade, hard shadows; not in the
    CGIncludes: written from what they sample and the manual's description): per screen pixel, the world position
    of _CameraDepthTexture's depth through the inverse of the camera's view-projection, its shadow coordinate
    unity_WorldToShadow[0] x world, the map's texel there compared as UNITY_SAMPLE_SHADOW's comparison sampler
    compares under reversed depth (lit when the receiver's z is at or above the map's; point, as the rig's other
    maps), then lerp(_LightShadowData.x, 1, lit). Pixels with no depth (the far plane) and pixels past the shadow
    distance are lit. Writes W x H float32, top row first (the screen's rows as the harness draws them); returns
    (pixels with depth, pixels shadowed)."""
    w, h, n = cam.width, cam.height, shadow.resolution
    depth, texels = read_floats(camera_depth), read_floats(map_texels)
    if len(depth) != w * h or len(texels) != n * n:
        raise SystemExit(f"pipeline-pass: error: {camera_depth} or {map_texels} has the wrong size for {w}x{h} and {n}^2")
    clip_to_world, to_shadow = general_inverse(cam.view_proj), values["unity_WorldToShadow"][0]
    strength_floor = values["_LightShadowData"][0]
    out, drawn, shadowed = [1.0] * (w * h), 0, 0
    for p, d in enumerate(depth):
        if not d > 0.0:
            continue
        ndc = [(p % w + 0.5) / w * 2.0 - 1.0, 1.0 - (p // w + 0.5) / h * 2.0, d, 1.0]
        world = [sum(clip_to_world[r][c] * ndc[c] for c in range(4)) for r in range(4)]
        world = [x / world[3] for x in world]
        drawn += 1
        if math.dist(world[:3], cam.eye) > shadow.distance:
            continue
        s = [sum(to_shadow[r][c] * world[c] for c in range(4)) for r in range(3)]
        tx, ty = min(max(int(s[0] * n), 0), n - 1), min(max(int(s[1] * n), 0), n - 1)
        if s[2] < texels[ty * n + tx]:
            out[p] = strength_floor
            shadowed += 1
    with open(out_path, "wb") as f:
        f.write(struct.pack(f"<{w * h}f", *out))
    return drawn, shadowed


def builtin_globals(cam, o2w, o2c, sun, light_color):
    """Built-in's members by name for ForwardBase with one directional light, each with where its
    layout comes from. Paths are under ../shared/unity-shaderlib/builtin-2022.3.62f1/CGIncludes/."""
    w, h, n, f = cam.width, cam.height, cam.near, cam.far
    identity = [[1.0 if i == j else 0.0 for j in range(4)] for i in range(4)]
    # Flat ambient of the package's constant (GT_AMBIENT, TerrainShading.hlsl) as an SH probe: only
    # the L0 terms (w of unity_SHAr/g/b, UnityCG.cginc ShadeSHPerPixel's SHEvalLinearL0L1) are non-zero.
    return {
        # UnityShaderVariables.cginc:218-221 (UnityPerFrame): the camera's GPU projection, view and
        # their product; UNITY_MATRIX_VP (line 32) is what UnityWorldToClipPos (UnityCG.cginc) uses.
        "glstate_matrix_projection": cam.proj,
        "unity_MatrixV": cam.view,
        "unity_MatrixInvV": affine_inverse(cam.view),
        "unity_MatrixVP": cam.view_proj,
        # UnityShaderVariables.cginc:167-168 (UnityPerDraw): Graphics.RenderPrimitives draws without a
        # renderer's Transform (BuiltinAdapter.hlsl), so Unity's per-draw matrices are the identity.
        "unity_ObjectToWorld": identity,
        "unity_WorldToObject": identity,
        # UnityShaderVariables.cginc:48 (UnityPerCamera).
        "_WorldSpaceCameraPos": cam.eye,
        # UnityShaderVariables.cginc:51-55: x = 1 (not flipped), near, far, 1/far.
        "_ProjectionParams": [1.0, n, f, 1.0 / f],
        # UnityShaderVariables.cginc:57-61: width, height, 1 + 1/width, 1 + 1/height.
        "_ScreenParams": [w, h, 1.0 + 1.0 / w, 1.0 + 1.0 / h],
        # UnityShaderVariables.cginc:63-73, reversed depth (UNITY_REVERSED_Z on Vulkan): (-1 + far/near, 1, x/far, 1/far).
        "_ZBufferParams": [-1.0 + f / n, 1.0, (-1.0 + f / n) / f, 1.0 / f],
        "unity_OrthoParams": [w / h, 1.0, 0.0, 0.0],     # UnityShaderVariables.cginc:75-79: w = 0, perspective
        # UnityShaderVariables.cginc:108-110 (UnityLighting): in ForwardBase the main directional
        # light's direction towards it, w = 0 (a point or spot light would have its position, w = 1).
        "_WorldSpaceLightPos0": sun + [0.0],
        # UnityLightingCommon.cginc:6: the light's colour times its intensity (linear).
        "_LightColor0": light_color + [1.0],
        # UnityShaderVariables.cginc:133-139: the ambient probe's SH, Unity's packing (L0 in w of SHA*).
        "unity_SHAr": [0.0, 0.0, 0.0, GT_AMBIENT_LEVEL], "unity_SHAg": [0.0, 0.0, 0.0, GT_AMBIENT_LEVEL],
        "unity_SHAb": [0.0, 0.0, 0.0, GT_AMBIENT_LEVEL],
        "unity_SHBr": [0.0] * 4, "unity_SHBg": [0.0] * 4, "unity_SHBb": [0.0] * 4, "unity_SHC": [0.0] * 4,
        # The package's own (UnityAdapterCommon.hlsl, as for URP).
        "_GtObjectToWorld": o2w,
        "_GtWorldToObject": affine_inverse(o2w),
        "_GtTessObjectToClip": o2c,
        "_GtTessScreenSize": [w, h, 1.0 / w, 1.0 / h],
    }


# The fog Unity sets from RenderSettings (Lighting window: mode, start and end, density, colour) for every pass
# that declares it; URP's C# sets neither. UnityInput.hlsl:209-210 (Built-in: UnityShaderVariables.cginc:231-237,
# whose comment gives the packing): unity_FogParams = (density / sqrt(ln 2), density / ln 2, -1 / (end - start),
# end / (end - start)); unity_FogColor the linear colour. Built-in reads x (EXP2), y (EXP), z and w (LINEAR) at clip z
# remapped by _ProjectionParams (UnityCG.cginc:1020-1050), ForwardBase lerping to unity_FogColor (1101-1105). The distances and density are chosen so the fog varies
# across the zoom view's terrain (0.5 to 1.8 units from the eye).
FOG_START, FOG_END, FOG_DENSITY, FOG_COLOR = 0.4, 2.4, 0.9, [0.5, 0.6, 0.7, 1.0]


def fog_values(picture):
    """unity_FogParams and unity_FogColor for a fog picture (each mode sets all four components), else {}."""
    if picture not in FOG_PICTURES:
        return {}
    return {"unity_FogParams": [FOG_DENSITY / math.sqrt(math.log(2.0)), FOG_DENSITY / math.log(2.0),
                                -1.0 / (FOG_END - FOG_START), FOG_END / (FOG_END - FOG_START)],
            "unity_FogColor": FOG_COLOR}


GT_AMBIENT_LEVEL = 0.2      # TerrainShading.hlsl's GT_AMBIENT
GLOBALS = {"URP": urp_globals, "Builtin": builtin_globals}
INCLUDE_PACKAGES = {"URP": URP_PACKAGES, "Builtin": []}


# Members the scene does not set, by name: what they hold instead. Everything else defaults to zero,
# and every default is listed in the run's output.
NAMED_DEFAULTS = {
    "unity_StereoScaleOffset": [1.0, 1.0, 0.0, 0.0],
    "_ScaleBias": [1.0, 0.0, 1.0, 0.0],
    "_ScaleBiasRt": [1.0, 0.0, 1.0, 0.0],
    "_ScreenCoordScaleBias": [1.0, 1.0, 0.0, 0.0],
}


# ---------------------------------------------------------------------------------------------
# Bytes


SCALARS = {"float": "f", "vec2": "2f", "vec3": "3f", "vec4": "4f", "uint": "I", "int": "i", "uvec4": "4I", "ivec4": "4i"}


def element_bytes(member, value):
    """One element's bytes (HLSL float4x4: column after column, as its default column_major packing reads)."""
    t = member["type"]
    if t == "mat4":
        return struct.pack("<16f", *[value[r][c] for c in range(4) for r in range(4)])
    if t not in SCALARS:
        raise SystemExit(f"pipeline-pass: error: member {member['name']} has type {t}, which the scene cannot write")
    values = value if isinstance(value, list) else [value]
    # A float4 Unity sets with SetGlobalVector fills a float2/float3 the shader declares with its first components.
    return struct.pack("<" + SCALARS[t], *values[:struct.calcsize("<" + SCALARS[t]) // 4])


def member_bytes(member, value):
    """The member's bytes as its block lays them out; an array's elements array_stride apart."""
    if not member.get("array"):
        return element_bytes(member, value)
    out = b""
    for v in value:
        one = element_bytes(member, v)
        out += one + bytes(member["array_stride"] - len(one))
    return out


def zero_value(member):
    t, count = member["type"], (member.get("array") or [1])[0]
    one = {"mat4": [[0.0] * 4 for _ in range(4)], "float": 0.0, "uint": 0, "int": 0, "vec2": [0.0] * 2,
           "vec3": [0.0] * 3, "vec4": [0.0] * 4, "uvec4": [0] * 4, "ivec4": [0] * 4}.get(t)
    if one is None:
        raise SystemExit(f"pipeline-pass: error: member {member['name']} has type {t}, which the scene cannot write")
    return [one] * count if member.get("array") else one


def show(value):
    if isinstance(value, list) and value and isinstance(value[0], list):
        return "0" if all(x == 0 for r in value for x in r) else "matrix"
    if isinstance(value, list):
        return "(" + ",".join(f"{x:g}" for x in value) + ")"
    return f"{value:g}"


def transposed(value):
    """A matrix transposed, or each matrix of an array (--transpose: a broken input)."""
    if value and isinstance(value[0], list) and value[0] and isinstance(value[0][0], list):
        return [transposed(m) for m in value]
    return [[value[c][r] for c in range(4)] for r in range(4)]


def fill_block(name, members, size, values, report):
    data = bytearray(size)
    for m in members:
        if m["name"] in values:
            value = values[m["name"]]
            report["filled"].append(f"{name}.{m['name']}")
        else:
            value = NAMED_DEFAULTS.get(m["name"], zero_value(m))
            report["defaults"].append(f"{m['name']}={show(value)}")
        b = member_bytes(m, value)
        data[m["offset"]:m["offset"] + len(b)] = b
    return bytes(data)


def terrain_params(buffers):
    """TerrainParams by name (Shaders/Terrain/TerrainParams.cs.hlsl, the generated contract: one
    float4 per member in field order): the rig's params.f32 in that order. URP's UnityPerMaterial
    holds them; Built-in's CBUFFER_START declares no block, so there they are $Global members."""
    with open(os.path.join(PKG_DIR, "Shaders", "Terrain", "TerrainParams.cs.hlsl"), encoding="utf-8") as f:
        names = re.findall(r"^float4 (\w+);", f.read(), re.M)
    p = read_floats(os.path.join(buffers, "params.f32"))
    if len(p) < 4 * len(names):
        raise SystemExit(f"pipeline-pass: error: {buffers}/params.f32 has {len(p)} floats, TerrainParams needs {4 * len(names)}")
    return {name: p[4 * i:4 * i + 4] for i, name in enumerate(names)}


# A buffer the scene has nothing for stops the run, unless a caller (gt pipeline_pass_all) sets this hook, called as
# the scene's own buffer functions are (name, kind, size, binding, path, spvs, report) to write a listed default.
MISSING_BUFFER = None
# The grid's structured buffers (TerrainInputs.hlsl; internals.md "GPU layout"), as the rig packs them.
GRID_BUFFERS = {"_ControlPoints": "control_points.f32", "_Regions": "regions.f32", "_GridLines": "grid_lines.f32"}


# The scene sets no texture yet: each separate image a pass declares gets a 1x1 named default, listed
# with the defaults. Shadow maps hold reversed depth's far plane (0: nothing occludes, all lit);
# HDRP's exposure texture the multiplier 1 (x) as its RG32 texel (y: 1 as well).
SHADOW_MAP = re.compile(r"[Ss]hadow[Mm]ap|ShadowmapCascadeAtlas|ShadowAtlas")
IMAGE_DEFAULTS = {"_ExposureTexture": ("R32G32_SFLOAT", [1.0, 1.0])}


def image_default(name):
    """(FORMAT, texel floats) of the 1x1 image that stands for the texture NAME."""
    if name in IMAGE_DEFAULTS:
        return IMAGE_DEFAULTS[name]
    if SHADOW_MAP.search(name):
        return "D32", [0.0]
    return "R32G32B32A32_SFLOAT", [0.0, 0.0, 0.0, 0.0]


def sampler_default(name):
    """--sampler's value for NAME, read from Unity's naming (sampler_LinearClampCompare,
    s_point_repeat_sampler, ...): compare -> compare-gequal, Unity's shadow test under reversed depth,
    through point filtering (lavapipe lists no linear filtering of D32); else linear unless named point."""
    low = name.lower()
    wrap = "repeat" if "repeat" in low else "clamp"
    if "compare" in low:
        return f"point:{wrap}:compare-gequal"
    return ("point" if "point" in low else "linear") + ":" + wrap


def default_image_or_sampler(name, kind, type_name, binding, path, report, images):
    if kind == "separate_images" and name in images:      # an image the frame drew (the shadow map)
        fmt, file, w, h = images[name]
        report["filled"].append(name)
        return {"name": name, "binding": binding, "kind": kind, "format": fmt, "file": file, "bytes": 4 * w * h,
                "arrayed": "Array" in type_name, "size": [w, h]}
    if kind == "separate_samplers":
        value = sampler_default(name)
        report["defaults"].append(f"{name}={value}")
        return {"name": name, "binding": binding, "kind": kind, "sampler": value, "bytes": 0}
    fmt, texel = image_default(name)
    with open(path, "wb") as f:
        f.write(struct.pack(f"<{len(texel)}f", *texel))
    report["defaults"].append(f"{name}={fmt}({','.join(show(x) for x in texel)})")
    return {"name": name, "binding": binding, "kind": kind, "format": fmt, "file": path, "bytes": 4 * len(texel),
            "arrayed": "Array" in type_name, "size": [1, 1]}


def layout_key(layout):
    """What two stages must agree on: kind, size and each member's name, offset, type and array (a
    struct member's type is a per-module id, so only its name counts)."""
    kind, members, size = layout
    if members is None:
        return kind, size
    return kind, size, tuple((m["name"], m.get("offset"), "struct" if m["type"].startswith("_") else m["type"],
                              str(m.get("array"))) for m in members)


def prepare(a, pipeline, pass_name, keywords, buffers, out, compiler="glslang", scene=None, images=None, sun=None):
    """Compiles the pass's variant, fills its bindings from the scene (scene: values that replace or
    add to the pipeline's, e.g. the light's view in a shadow pass; images: textures the frame drew,
    name -> (FORMAT, file, W, H); sun: towards the main light, default --sun-elevation/--sun-azimuth's),
    writes out/manifest.json and returns the harness arguments (stages, bindings, the pass's render state)."""
    images = images or {}
    sun = sun or sun_direction(a.sun_elevation, a.sun_azimuth)
    os.makedirs(out, exist_ok=True)
    tmp = os.path.join(out, "work")
    subprocess.run(["rm", "-rf", tmp], check=True)
    os.makedirs(tmp)
    sub, pas = find_pass(pipeline, pass_name)
    spvs = compile_pass(sub, pas, out, tmp, keywords, compiler)
    # The include roots link back to the repository: left in .build, a walk of the package would loop.
    for name in os.listdir(tmp):
        if name.startswith("root-"):
            shutil.rmtree(os.path.join(tmp, name))
    if not spvs:
        raise SystemExit(f"pipeline-pass: error: {pass_name} has no variant with exactly the keywords {keywords}")
    cam, o2w, o2c = yawed(a, *rig_camera(buffers))
    values = GLOBALS[pipeline](cam, o2w, o2c, sun, a.light_color)
    values.update(scene or {})
    broken_inputs(a, values)
    values.update(terrain_params(buffers))

    # One binding per resource name across the stages; a name whose layout differs between stages fails.
    layouts, per_stage = {}, {}
    for stage in STAGES:
        if stage not in spvs:
            continue
        per_stage[stage] = resources(reflect(spvs[stage]))
        for kind, name, _, _, members, size in per_stage[stage]:
            if kind not in ("uniform", "storage", "separate_images", "separate_samplers"):
                raise SystemExit(f"pipeline-pass: error: {stage} declares {kind} '{name}'; only separate "
                                 "images and samplers are bound (as HLSL compiles Texture2D and SamplerState)")
            if name in layouts and layout_key(layouts[name]) != layout_key((kind, members, size)):
                raise SystemExit(f"pipeline-pass: error: '{name}' has another layout in the {stage} stage")
            layouts[name] = (kind, members, size)
    binding_of = {name: FIRST_BINDING + i for i, name in enumerate(sorted(layouts))}
    reads = {}
    for stage, res in per_stage.items():
        words = spirv_words(spvs[stage])
        reads[stage] = sorted(f"{name}.{m}" for kind, name, _, b, members, _ in res if kind == "uniform"
                              for m in members_read(words, b, members))
        rebind(spvs[stage], {b: binding_of[name] for _, name, _, b, _, _ in res})
        v = subprocess.run(["spirv-val", spvs[stage]], capture_output=True, text=True)
        if v.returncode != 0:
            raise SystemExit(f"pipeline-pass: error: {spvs[stage]} after rebinding: {v.stdout}{v.stderr}")

    report = {"filled": [], "defaults": []}
    bindings = []
    for name in sorted(layouts):
        kind, members, size = layouts[name]
        path = os.path.join(out, f"binding_{binding_of[name]}_{re.sub(r'[^A-Za-z0-9_]', '', name)}.bin")
        if kind != "uniform" and callable(values.get(name)):
            # A buffer, image or sampler the pipeline's scene fills itself (pipeline_pass_hdrp.py): the
            # function writes path and returns the binding as below, adding to report's lists.
            bindings.append(values[name](name, kind, size, binding_of[name], path, spvs, report))
            continue
        if kind in ("separate_images", "separate_samplers"):
            bindings.append(default_image_or_sampler(name, kind, size, binding_of[name], path, report, images))
            continue
        if kind == "uniform":
            data = fill_block(name, members, size, values, report)
        elif name in GRID_BUFFERS:
            with open(os.path.join(buffers, GRID_BUFFERS[name]), "rb") as f:
                data = f.read()
            report["filled"].append(name)
        elif MISSING_BUFFER is not None:
            bindings.append(MISSING_BUFFER(name, kind, size, binding_of[name], path, spvs, report))
            continue
        else:
            raise SystemExit(f"pipeline-pass: error: the scene has nothing for the buffer '{name}'")
        with open(path, "wb") as f:
            f.write(data)
        bindings.append({"name": name, "binding": binding_of[name], "kind": kind, "bytes": len(data), "file": path})

    where = f"SubShader {sub.index} ({sub.pipeline}) Pass \"{pas.name}\""
    st = render_state.pass_state(sub, pas, where)
    state = [x for name in render_state.COMMANDS for x in (render_state.COMMANDS[name][0], st[name])]
    state += render_state.stencil_options(sub, pas, where)
    args = []
    for stage in STAGES:
        if stage in spvs:
            args += [f"--{stage}", spvs[stage]]
    for b in bindings:
        if b["kind"] == "separate_images":
            args += ["--image", f"{b['binding']}:{b['file']}:{b['format']}:{b['size'][0]}:{b['size'][1]}"
                     + (":1" if b["arrayed"] else "")]
        elif b["kind"] == "separate_samplers":
            args += ["--sampler", f"{b['binding']}:{b['sampler']}"]
        else:
            args += ["--storage-data", f"{b['binding']}:{b['file']}"]
    args += ["--uniform-blocks", "storage"] + state
    read_all = sorted(set(x for r in reads.values() for x in r))
    defaulted_read = [d for d in report["defaults"] if any(r.endswith("." + d.split("=")[0]) for r in read_all)]
    variant = "+".join(keywords) or "base"
    manifest = {"pipeline": pipeline, "pass": pas.name, "variant": variant, "compiler": compiler, "bindings": bindings,
                "filled": report["filled"], "defaults": report["defaults"], "reads": reads,
                "defaulted_read": defaulted_read, "state": state, "sun": sun,
                "light_color": a.light_color, "harness_args": args}
    with open(os.path.join(out, "manifest.json"), "w") as f:
        json.dump(manifest, f, indent=1)
    print(f"pass {pipeline} {pas.name} variant {variant} compiler {compiler} stages {','.join(s for s in STAGES if s in spvs)}")
    for b in bindings:
        print(f"binding {b['binding']} {b['kind']} {b['name']} bytes {b['bytes']}")
    print(f"filled {len(report['filled'])}: {', '.join(report['filled'])}")
    print(f"defaults {len(report['defaults'])}: {', '.join(report['defaults'])}")
    for stage, r in reads.items():
        print(f"reads {stage} {len(r)}: {', '.join(r)}")
    print(f"defaulted_read {len(defaulted_read)}: {', '.join(defaulted_read)}")
    print(f"state {' '.join(state)}")
    return args


def broken_inputs(a, values):
    """--leave-default, --fill-from, --transpose applied to the names VALUES sets (main() checks that some scene
    sets each name)."""
    for name in a.leave_default:
        values.pop(name, None)
    for pair in a.fill_from:
        dst, _, src = pair.partition("=")
        if dst in values and src in values:
            values[dst] = values[src]
    for name in a.transpose:
        if name in values:
            values[name] = transposed(values[name])
    return values


def yawed(a, cam, o2w, o2c):
    """The renderer's Transform turned --object-yaw degrees about the world's y axis (the terrain is centred
    on it): object-to-world, and the object-to-clip that chooses tessellation, as the renderer would set them."""
    yaw = math.radians(getattr(a, "object_yaw", 0.0))
    if yaw == 0.0:
        return cam, o2w, o2c
    c, s = math.cos(yaw), math.sin(yaw)
    o2w = mat_mul([[c, 0.0, s, 0.0], [0.0, 1.0, 0.0, 0.0], [-s, 0.0, c, 0.0], [0.0, 0.0, 0.0, 1.0]], o2w)
    return cam, o2w, mat_mul(cam.view_proj, o2w)


def write_view(a, buffers, path):
    """The camera's view-projection and the renderer's object-to-world a picture was drawn with."""
    cam, o2w, _ = yawed(a, *rig_camera(buffers))
    with open(path, "w") as f:
        json.dump({"camera_view_proj": cam.view_proj, "camera_view": cam.view, "near": cam.near, "far": cam.far, "object_to_world": o2w,
                   "object_yaw": getattr(a, "object_yaw", 0.0), "fog": fog_values(os.path.basename(path)[:-len("_view.json")])},
                  f, indent=1)


def pack_scene(out):
    """The sample grid (gt-cli demo-grid) packed as the rig's buffers, RigScene's zoom view at 400 x 300."""
    cli = os.path.join(PKG_DIR, ".build", "gt-cli", "gt-cli")
    if not os.path.exists(cli):
        raise SystemExit(f"pipeline-pass: error: {cli} is missing (run: gt setup)")
    buffers = os.path.join(out, "buffers")
    grid = os.path.join(out, "grid.json")
    for cmd in ([cli, "demo-grid", "--out", grid],
                [cli, "pack", "--grid", grid, "--range", "0,0,1,1", "--tiles", str(TILES), "--factor", "15",
                 "--noise", "0,16,2,2", "--octaves", "1", "--width", str(WIDTH), "--height", str(HEIGHT), "--out", buffers]):
        r = subprocess.run(cmd, capture_output=True, text=True)
        if r.returncode != 0:
            raise SystemExit(f"pipeline-pass: error: {' '.join(cmd)} failed:\n{r.stdout}{r.stderr}")
    return buffers


TILES, WIDTH, HEIGHT = 16, 400, 300
# (picture, pass, keywords): URP's depth prepass output (coverage: depth in R, ColorMask R), the lit
# colour, and the same pass's normals debug view (world normals * 0.5 + 0.5) to grade the lighting.
# lit_dxc: the lit picture from DXC's SPIR-V of the same pass.
# builtin_lit: Built-in's ForwardBase (tessellated SubShader, base variant) on the same scene.
PICTURES = [("depth", "URP", "DepthOnly", [], "glslang"), ("lit", "URP", "ForwardLit", [], "glslang"),
            ("normals", "URP", "ForwardLit", ["GT_DEBUG_NORMALS"], "glslang"), ("lit_dxc", "URP", "ForwardLit", [], "dxc"),
            ("builtin_lit", "Builtin", "ForwardBase", [], "glslang"),
            ("shadow_map", "URP", "ShadowCaster", [], "glslang"),
            ("lit_shadows", "URP", "ForwardLit", ["_MAIN_LIGHT_SHADOWS"], "glslang"),
            ("depth_normals", "URP", "DepthNormalsOnly", ["_GBUFFER_NORMALS_OCT"], "glslang"),
            ("depth_normals_snorm", "URP", "DepthNormalsOnly", [], "glslang"),
            ("depth_normals_layers", "URP", "DepthNormalsOnly", ["_WRITE_RENDERING_LAYERS"], "glslang"),
            ("lit_layers", "URP", "ForwardLit", ["_WRITE_RENDERING_LAYERS"], "glslang"),
            ("lit_fog_linear", "URP", "ForwardLit", ["FOG_LINEAR"], "glslang"),
            ("lit_fog_exp", "URP", "ForwardLit", ["FOG_EXP"], "glslang"),
            ("lit_fog_exp2", "URP", "ForwardLit", ["FOG_EXP2"], "glslang"),
            ("builtin_fog_linear", "Builtin", "ForwardBase", ["FOG_LINEAR"], "glslang"),
            ("builtin_fog_exp", "Builtin", "ForwardBase", ["FOG_EXP"], "glslang"),
            ("builtin_fog_exp2", "Builtin", "ForwardBase", ["FOG_EXP2"], "glslang"),
            ("builtin_shadow_map", "Builtin", "ShadowCaster", [], "glslang"),
            ("builtin_camera_depth", "Builtin", "ShadowCaster", [], "glslang"),
            ("builtin_lit_shadows", "Builtin", "ForwardBase", ["SHADOWS_SCREEN"], "dxc"),
            ("lit_cascades", "URP", "ForwardLit", ["_MAIN_LIGHT_SHADOWS_CASCADE"], "glslang")]
# depth_normals: URP's DepthNormalsOnly with _GBUFFER_NORMALS_OCT, the variant whose output fits the harness's
# RGBA8 UNORM target as it fits URP's (UniversalRendererData's Accurate G-buffer Normals: R8G8B8A8_UNorm, the
# octahedral normal's two 12-bit coordinates in RGB 8:8:8). URP's default (Forward, that option off) draws the
# base variant into R8G8B8A8_SNorm (DepthNormalOnlyPass.GetGraphicsFormat): signed, which the harness cannot
# hold. Its camera depth goes to depth_normals_depth.f32 and the view to depth_normals_view.json (the test
# recovers each pixel's world position). Drawn only when named (--only depth_normals): its own fixture.
# depth_normals_snorm: the base variant, which a default asset draws, into the target URP 14 gives it
# (UniversalRenderer, not deferred: normalDescriptor.graphicsFormat = DepthNormalOnlyPass.GetGraphicsFormat(),
# R8G8B8A8_SNorm where the device renders it, as every Vulkan device does): the normal's [-1, 1] as signed
# bytes, which DeclareNormalsTexture's LoadSceneNormals returns as they are (no decode, no normalize).
# depth_normals_layers, lit_layers: the _WRITE_RENDERING_LAYERS variants, drawn as URP 14 draws them with decal
# layers on (DepthNormalOnlyPass.Setup(depth, normal, decalLayer) / DrawObjectsWithRenderingLayersPass: the
# keyword on and a second colour target, RenderingLayerUtils.GetFormat(Bits8) = R8_UNorm, cleared to 0); the
# second target's bytes go to OUT/<picture>_target1.bin.
# lit_fog_*, builtin_fog_*: ForwardLit's and ForwardBase's multi_compile_fog variants under the scene's fog
# (fog_values), depth and view written (the test recomputes each pixel's fog from its depth).
FOG_PICTURES = {"lit_fog_linear", "lit_fog_exp", "lit_fog_exp2", "builtin_fog_linear", "builtin_fog_exp", "builtin_fog_exp2"}
# builtin_shadow_map, builtin_camera_depth, builtin_lit_shadows (only with --only builtin_lit_shadows, which draws
# the other two first): Built-in's screen-space directional shadow (builtin_caster_values .. collect_screen_shadows).
# ForwardBase's SHADOWS_SCREEN variant from DXC's SPIR-V: glslang's HLSL front end declares a DX9 sampler2D as a bare
# OpTypeSampler with no image, so AutoLight's tex2Dproj (and any tex2D) on it is an image operation on a sampler,
# which spirv-val rejects; DXC under Unity's use_dxc defines takes HLSLSupport.cginc's emulated sampler2D (a
# Texture2D and a SamplerState), as Unity's own DXC compile does.
BUILTIN_SHADOW_PICTURES = {"builtin_shadow_map", "builtin_camera_depth", "builtin_lit_shadows"}
# lit_cascades (only with --only): URP's cascaded main-light shadow under the shadowed frame's sun (draw_cascades):
# the ShadowCaster once per cascade into its tile (OUT/cascade_map_<i>.f32), the atlas (OUT/cascade_atlas.f32, rows in
# texture order), ForwardLit's _MAIN_LIGHT_SHADOWS_CASCADE variant sampling it (OUT/lit_cascades.png, _depth.f32), and
# the same variant twice more over atlases whose tiles are all occluding or all clear (OUT/lit_cascades_bit<b>.png:
# tile i occludes when bit b of i is set), so each sunlit pixel's shadow in the two pictures spells the cascade the
# GPU chose there; OUT/cascades.json the cascades' spheres, matrices and the camera.
ON_REQUEST = ({"depth_normals", "depth_normals_snorm", "depth_normals_layers", "lit_layers", "lit_cascades"} | FOG_PICTURES
              | BUILTIN_SHADOW_PICTURES)
DEPTH_PICTURES = {"depth_normals", "depth_normals_snorm", "depth_normals_layers"} | FOG_PICTURES
COLOR_FORMATS = {"depth_normals_snorm": "R8G8B8A8_SNORM", "depth_normals_layers": "R8G8B8A8_SNORM"}
TARGET1 = {"depth_normals_layers": "R8_UNORM", "lit_layers": "R8_UNORM"}
# shadow_map: URP's ShadowCaster (base variant: a directional light) drawn from the main light into a
# SHADOW_RESOLUTION^2 depth map (--depth-out; no colour, ColorMask 0); lit_shadows: ForwardLit's
# _MAIN_LIGHT_SHADOWS variant sampling it, its LightShadows block filled as URP does, and its camera
# depth written too (lit_shadows_depth.f32: the tests recover each pixel's world position from it).
SHADOW_PICTURES = {"shadow_map": "lit_shadows"}


def draw(args, buffers, png, log, size=(WIDTH, HEIGHT), depth_out=None, color_format=None, target1=None):
    harness = os.path.join(PKG_DIR, ".build", "harness", "gt-harness")
    cmd = [harness] + args + ["--buffers", buffers, "--patches", str(TILES * TILES), "--width", str(size[0]),
                              "--height", str(size[1])]
    cmd += ["--color-format", color_format] if color_format else []
    cmd += ["--target1", target1] if target1 else []
    cmd += ["--png", png] if png else []
    cmd += ["--depth-out", depth_out] if depth_out else []
    r = subprocess.run(cmd, capture_output=True, text=True)
    with open(log, "w") as f:
        f.write(" ".join(cmd) + "\n" + r.stdout + r.stderr)
    if r.returncode != 0:
        raise SystemExit(f"pipeline-pass: error: the harness failed ({log}):\n{r.stdout[-2000:]}{r.stderr}")
    print(f"picture {png or depth_out} " + " ".join(l for l in r.stdout.splitlines()
                                                    if l.startswith(("image ", "state ", "depth_out ", "target1 ", "stencil_"))))


def shadow_map_texels(depth_out, texels, n):
    """The harness's depth (top row first: clip y = +1, the light's up) as the shadow texture's rows
    (row 0 at v = 0, where GetShadowTransform puts the light's y = -1): the rows reversed."""
    with open(depth_out, "rb") as f:
        data = f.read()
    row = 4 * n
    if len(data) != row * n:
        raise SystemExit(f"pipeline-pass: error: {depth_out} has {len(data)} bytes, expected {row * n}")
    with open(texels, "wb") as f:
        f.write(b"".join(data[(n - 1 - j) * row:(n - j) * row] for j in range(n)))


def draw_cascades(a, buffers, cam, sun):
    """lit_cascades: the casters per cascade, the atlas, the forward pass over it and the two cascade-index pictures."""
    cascades = MainLightCascades(cam, sun, int(a.cascades))
    tiles = []
    for i, sl in enumerate(cascades.slices):
        folder = os.path.join(a.out, f"cascade_map_{i}")
        args = prepare(a, "URP", "ShadowCaster", [], buffers, folder, scene=sl.caster_values(), sun=sun)
        depth = os.path.join(a.out, f"cascade_map_{i}.f32")
        draw(args, buffers, None, os.path.join(folder, "harness.log"), (cascades.tile, cascades.tile), depth)
        tiles.append(os.path.join(a.out, f"cascade_map_{i}_texels.f32"))
        shadow_map_texels(depth, tiles[-1], cascades.tile)
    atlas = os.path.join(a.out, "cascade_atlas.f32")
    cascades.atlas(tiles, atlas)
    # The two cascades the rig's terrain spans (4 cascades: 1 and 2; 2: both), exchanged on request (a broken input).
    swap = ((0, 1) if cascades.count == 2 else (1, 2)) if a.swap_cascade_matrices else None
    folder = os.path.join(a.out, "lit_cascades")
    args = prepare(a, "URP", "ForwardLit", ["_MAIN_LIGHT_SHADOWS_CASCADE"], buffers, folder, scene=cascades.receiver_values(swap),
                   images={"_MainLightShadowmapTexture": ("D32", atlas, cascades.width, cascades.height)}, sun=sun)
    draw(args, buffers, os.path.join(a.out, "lit_cascades.png"), os.path.join(folder, "harness.log"),
         depth_out=os.path.join(a.out, "lit_cascades_depth.f32"))
    n = cascades.width * cascades.height
    for bit in (0, 1):
        # Tile i at reversed depth's near plane (1: every receiver behind it, shadowed) when bit b of i is set, else
        # at the far plane (0: lit); the same pass and bindings, only the atlas's file differs.
        marks = [[1.0 if i >> bit & 1 else 0.0] * (cascades.tile ** 2) for i in range(cascades.count)]
        files = []
        for i, m in enumerate(marks):
            files.append(os.path.join(a.out, f"cascade_mark_{i}_{bit}.f32"))
            with open(files[-1], "wb") as f:
                f.write(struct.pack(f"<{len(m)}f", *m))
        marked = os.path.join(a.out, f"cascade_atlas_bit{bit}.f32")
        cascades.atlas(files, marked)
        if os.path.getsize(marked) != 4 * n:
            raise SystemExit(f"pipeline-pass: error: {marked} is not the {cascades.width}x{cascades.height} atlas")
        draw([x.replace(atlas, marked) if atlas in x else x for x in args], buffers, os.path.join(a.out, f"lit_cascades_bit{bit}.png"),
             os.path.join(folder, f"harness_bit{bit}.log"))
    with open(os.path.join(a.out, "cascades.json"), "w") as f:
        json.dump({"count": cascades.count, "tile": cascades.tile, "width": cascades.width, "height": cascades.height,
                   "distance": cascades.distance, "centers": [sl.center for sl in cascades.slices],
                   "radii": [sl.radius for sl in cascades.slices], "texels": [sl.texel for sl in cascades.slices],
                   "world_to_shadow": cascades.world_to_shadow, "swapped": list(swap or []), "camera_view_proj": cam.view_proj,
                   "object_to_world": rig_camera(buffers)[1], "sun": sun}, f, indent=1)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default=os.path.join(PKG_DIR, ".build", "pipeline-pass"))
    ap.add_argument("--only", choices=[p[0] for p in PICTURES], action="append",
                    help="draw only these pictures (default: all)")
    options.add_number(ap, "--sun-elevation", range="elevation", default=30.0,
                       help="degrees above the horizon (default 30)")
    options.add_number(ap, "--sun-azimuth", range="azimuth", default=-140.0,
                       help="degrees from +z towards +x (default -140: from the camera's front left)")
    options.add_number(ap, "--shadow-sun-elevation", range="elevation", default=12.0,
                       help="the shadowed frame's sun (shadow_map, lit_shadows): degrees above the horizon (default 12: "
                            "the sample grid's hills cast a large shadow only under a low sun)")
    options.add_number(ap, "--shadow-sun-azimuth", range="azimuth", default=90.0,
                       help="the shadowed frame's sun: degrees from +z towards +x (default 90: from the right, across "
                            "the ridges; 12%% of the sunlit terrain in their shadow)")
    ap.add_argument("--light-color", default="1,0.96,0.9", help="R,G,B: the main light's final colour (linear)")
    options.add_number(ap, "--object-yaw", range="azimuth", default=0.0,
                       help="degrees the renderer's Transform turns about the world's y axis (default 0; depth_normals' "
                            "fixture turns it so normals left in object space differ from world normals)")
    ap.add_argument("--leave-default", action="append", default=[], help="NAME: leave a member to its default")
    ap.add_argument("--fill-from", action="append", default=[], help="NAME=OTHER: fill NAME with OTHER's value")
    ap.add_argument("--transpose", action="append", default=[], help="NAME: fill the matrix NAME (each, for an array) transposed")
    ap.add_argument("--cascades", choices=["2", "4"], default="4",
                    help="lit_cascades: URP's main-light cascade count (default 4; the asset offers 2 or 4)")
    ap.add_argument("--swap-cascade-matrices", action="store_true",
                    help="lit_cascades: the matrices of the two cascades the terrain spans exchanged (4: [1] and [2]; 2: [0] and [1]; a broken input)")
    ap.add_argument("--flip-shadow-bias", action="store_true",
                    help="Built-in's shadow casters biased towards the light instead of away (a broken input: acne)")
    a = ap.parse_args(argv)
    try:
        a.light_color = [float(x) for x in a.light_color.split(",")]
        if len(a.light_color) != 3 or not all(math.isfinite(x) and 0 <= x <= 1000 for x in a.light_color):
            raise ValueError
    except ValueError:
        ap.error(f"argument --light-color: expected R,G,B, each 0..1000, got '{a.light_color}'")
    probe = Camera([0.0, 1.0, -1.0], [0.0] * 3, 50.0, 4, 3, 0.01, 20.0)
    identity = [[1.0 if i == j else 0.0 for j in range(4)] for i in range(4)]
    scene_names = [set(g(probe, identity, identity, [0.0, 1.0, 0.0], [1.0] * 3)) for g in GLOBALS.values()]
    shadow = MainLightShadow(probe, normalize([0.3, 0.5, 0.2]))
    scene_names.append(set(shadow.caster_values()) | set(shadow.receiver_values()))
    scene_names.append(set(builtin_caster_values(shadow)) | set(builtin_collect_values(shadow)))
    scene_names.append(set(fog_values("lit_fog_linear")))
    for name in a.leave_default:
        if not any(name in names for names in scene_names):
            ap.error(f"argument --leave-default: no pipeline's scene sets '{name}'")
    for pair in a.fill_from:
        dst, _, src = pair.partition("=")
        if not any(dst in names and src in names for names in scene_names):
            ap.error(f"argument --fill-from: '{pair}': no pipeline's scene sets both names")
    for name in a.transpose:
        if not any(isinstance(v, list) and v and isinstance(v[0], list)
                   for names in [{**g(probe, identity, identity, [0.0, 1.0, 0.0], [1.0] * 3), **shadow.receiver_values(),
                                  **shadow.caster_values(), **builtin_caster_values(shadow),
                                  **builtin_collect_values(shadow)} for g in GLOBALS.values()] for k, v in names.items() if k == name):
            ap.error(f"argument --transpose: no pipeline's scene sets a matrix '{name}'")
    os.makedirs(a.out, exist_ok=True)
    buffers = pack_scene(a.out)
    cam, _, _ = rig_camera(buffers)
    shadow = MainLightShadow(cam, sun_direction(a.shadow_sun_elevation, a.shadow_sun_azimuth))
    texels = os.path.join(a.out, "shadow_map_texels.f32")
    wanted = set(a.only or [p[0] for p in PICTURES if p[0] not in ON_REQUEST])
    wanted |= {m for m, receiver in SHADOW_PICTURES.items() if receiver in wanted}   # a receiver needs its map
    wanted |= BUILTIN_SHADOW_PICTURES if "builtin_lit_shadows" in wanted else set()
    builtin_texels = os.path.join(a.out, "builtin_shadow_map_texels.f32")
    screen_shadow = os.path.join(a.out, "builtin_screen_shadow.f32")
    for picture, pipeline, pass_name, keywords, compiler in PICTURES:
        if picture not in wanted:
            continue
        folder = os.path.join(a.out, picture)
        log = os.path.join(folder, "harness.log")
        target1 = f"{TARGET1[picture]}:{os.path.join(a.out, picture + '_target1.bin')}" if picture in TARGET1 else None
        if picture == "builtin_shadow_map":
            args = prepare(a, pipeline, pass_name, keywords, buffers, folder, compiler,
                           scene=builtin_caster_values(shadow, a.flip_shadow_bias), sun=shadow.sun)
            depth = os.path.join(a.out, picture + ".f32")
            draw(args, buffers, None, log, (shadow.resolution, shadow.resolution), depth)
            shadow_map_texels(depth, builtin_texels, shadow.resolution)
        elif picture == "builtin_camera_depth":
            args = prepare(a, pipeline, pass_name, keywords, buffers, folder, compiler, scene=builtin_camera_depth_values(),
                           sun=shadow.sun)
            draw(args, buffers, None, log, depth_out=os.path.join(a.out, picture + ".f32"))
            drawn, shadowed = collect_screen_shadows(os.path.join(a.out, picture + ".f32"), builtin_texels, cam, shadow,
                                                     broken_inputs(a, builtin_collect_values(shadow)), screen_shadow)
            print(f"collect {screen_shadow} {cam.width}x{cam.height}: {drawn} pixels with depth, {shadowed} shadowed")
        elif picture == "builtin_lit_shadows":
            args = prepare(a, pipeline, pass_name, keywords, buffers, folder, compiler, sun=shadow.sun,
                           images={"_ShadowMapTexture.t": ("R32_SFLOAT", screen_shadow, cam.width, cam.height)})
            draw(args, buffers, os.path.join(a.out, picture + ".png"), log, depth_out=os.path.join(a.out, picture + "_depth.f32"))
        elif picture == "lit_cascades":
            draw_cascades(a, buffers, cam, shadow.sun)
        elif picture in SHADOW_PICTURES:
            args = prepare(a, pipeline, pass_name, keywords, buffers, folder, compiler, scene=shadow.caster_values(),
                           sun=shadow.sun)
            depth = os.path.join(a.out, picture + ".f32")
            draw(args, buffers, None, log, (shadow.resolution, shadow.resolution), depth)
            shadow_map_texels(depth, texels, shadow.resolution)
        elif picture in SHADOW_PICTURES.values():
            args = prepare(a, pipeline, pass_name, keywords, buffers, folder, compiler, scene=shadow.receiver_values(),
                           images={"_MainLightShadowmapTexture": ("D32", texels, shadow.resolution, shadow.resolution)},
                           sun=shadow.sun)
            draw(args, buffers, os.path.join(a.out, picture + ".png"), log,
                 depth_out=os.path.join(a.out, picture + "_depth.f32"))
        elif picture in DEPTH_PICTURES:
            args = prepare(a, pipeline, pass_name, keywords, buffers, folder, compiler, scene=fog_values(picture))
            draw(args, buffers, os.path.join(a.out, picture + ".png"), log, depth_out=os.path.join(a.out, picture + "_depth.f32"),
                 color_format=COLOR_FORMATS.get(picture), target1=target1)
            write_view(a, buffers, os.path.join(a.out, picture + "_view.json"))
        else:
            args = prepare(a, pipeline, pass_name, keywords, buffers, folder, compiler)
            draw(args, buffers, os.path.join(a.out, picture + ".png"), log, target1=target1)
    with open(os.path.join(a.out, "shadow.json"), "w") as f:
        json.dump({"resolution": shadow.resolution, "distance": shadow.distance, "texel": shadow.texel,
                   "bias": shadow.bias, "radius": shadow.radius, "center": shadow.center,
                   "world_to_shadow": shadow.world_to_shadow, "camera_view_proj": cam.view_proj,
                   "object_to_world": rig_camera(buffers)[1], "sun": shadow.sun}, f, indent=1)


if __name__ == "__main__":
    main()
