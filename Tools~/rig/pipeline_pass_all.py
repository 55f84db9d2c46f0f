#!/usr/bin/env python3
"""gt pipeline_pass_all: every variant of every pass of each pipeline's tessellated SubShader, drawn once.

The variants are the ones gt shaderlab compiles (shaderlab.pass_variants: none, each keyword alone, a set's platform
defines, the effects together, the effects with the other sets' first keywords), each compiled as gt pipeline_pass
compiles it (glslang; DXC's SPIR-V where glslang cannot: Built-in's screen-space SHADOWS_SCREEN path, see
pipeline_pass.py) and drawn by the harness on gt pipeline_pass's scene (the sample grid, RigScene's zoom view, the sun
30 degrees up), every binding filled by name from the pipeline's scene (pipeline_pass.py's URP and Built-in values,
pipeline_pass_hdrp.py's HDRP values and buffers; the editor's selection and picking values; URP's 4 cascades'
constants). Shadow maps and HDRP's atlas are their listed 1x1 defaults; URP's screen-space shadow and SSAO textures
hold 1 on the left half of the screen and a known level on the right (pipeline_pass.screen_halves); buffers the scene
has nothing for (the snow map's, the vertex cache's, the levels' factors) are zero-filled and listed as defaulted, so
those variants draw what zero inputs give.
Checked per variant: no member a stage reads left to its default (the manifest's defaulted_read); every depth the pass
writes finite and within [0, 1] (--depth-out: a NaN or Inf position shows there as it is); in the forward passes'
colour variants (not the debug views) no covered pixel black in all three channels (an 8-bit UNORM target stores a NaN
as 0; an Inf saturates like a bright pixel, so only NaN is seen in colour); the selection and picking passes' pixels
hold the editor's values; URP's single-keyword screen-shadow and SSAO variants equal ForwardLit's base picture in the
left half and what the texture's level gives in the right (screen_texture_failures). Prints a line per variant, then passes and
variants drawn per pipeline and per variant set, bindings filled and defaulted, and every failure; exits 1 if any.
Not part of gt test (Tools~/rig/README.md gives its time); the PipelinePass* fixtures draw a representative subset.

  gt pipeline_pass_all [--out DIR] [--list] [--pipeline URP|HDRP|Builtin]... [--pass NAME]... [--keyword KEYWORD]...
--list prints the variants it would draw (pipeline, SubShader, pass, keywords; tab-separated) and draws nothing.
"""
import argparse
import collections
import json
import os
import struct
import sys
import time
import types
import zlib

RIG_DIR = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, RIG_DIR)
import pipeline_pass as pp  # noqa: E402
import pipeline_pass_hdrp  # noqa: E402,F401  (registers HDRP's scene and its compile-once in pipeline_pass)
import render_state  # noqa: E402
import shaderlab  # noqa: E402

PIPELINES = ("URP", "HDRP", "Builtin")
FORWARD_PASSES = {"ForwardLit", "ForwardBase", "ForwardOnly"}
# Keywords whose inputs the rig's scene does not describe: their variants draw on zero buffers and listed defaults,
# so their defaulted reads are printed, not failed (the snow, levels and vertex-cache fixtures draw them with data).
SCENE_LACKS = {"GT_SNOW": "snow map", "GT_LOD": "level tiles", "GT_VERTEX_CACHE": "vertex cache"}
ZERO_BUFFER_BYTES = 1 << 20     # a buffer the scene lacks: zeros, enough for any index the scene's 256 patches reach


def tessellated_variants(shader):
    """shaderlab's variants of the first SubShader of each pipeline (the tessellated one, which Unity picks)."""
    out, first = [], {}
    for pipeline, sub, name, keywords in shaderlab.pass_variants(shader):
        first.setdefault(pipeline, sub)
        if pipeline in PIPELINES and sub == first[pipeline]:
            out.append((pipeline, sub, name, keywords))
    return out


def compiler_for(pipeline, keywords):
    """DXC for Built-in's screen-space shadow lookup (a DX9 sampler2D, which glslang cannot compile), else glslang."""
    screen = "SHADOWS_SCREEN" in keywords and "UNITY_NO_SCREENSPACE_SHADOWS" not in keywords
    return "dxc" if pipeline == "Builtin" and screen else "glslang"


def zero_buffer(name, kind, size, binding, path, spvs, report):
    """pipeline_pass.MISSING_BUFFER: a buffer the scene has nothing for, zero-filled and listed as a default."""
    with open(path, "wb") as f:
        f.write(bytes(ZERO_BUFFER_BYTES))
    report["defaults"].append(f"{name}=zeros({ZERO_BUFFER_BYTES} bytes)")
    return {"name": name, "binding": binding, "kind": kind, "bytes": ZERO_BUFFER_BYTES, "file": path}


def png_rgba(path):
    """The harness's PNG (8-bit RGBA, not interlaced) as (width, height, bytes), unfiltered."""
    with open(path, "rb") as f:
        data = f.read()
    pos, idat, width, height = 8, b"", 0, 0
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, color = struct.unpack(">IIBB", body[:10])
            if (depth, color) != (8, 6):
                raise SystemExit(f"pipeline-pass-all: error: {path} is not 8-bit RGBA")
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw, stride, out = zlib.decompress(idat), 4 * width, bytearray()
    prev = bytearray(stride)
    for y in range(height):
        kind, row = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = row[i - 4] if i >= 4 else 0
            b, c = prev[i], prev[i - 4] if i >= 4 else 0
            if kind == 1:
                row[i] = (row[i] + a) & 255
            elif kind == 2:
                row[i] = (row[i] + b) & 255
            elif kind == 3:
                row[i] = (row[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                row[i] = (row[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        out += row
        prev = row
    return width, height, bytes(out)


def check(picture_png, depth_file, pass_name, keywords, manifest):
    """(covered pixels, failures) of one drawn variant."""
    depth = pp.read_floats(depth_file)
    covered = [i for i, d in enumerate(depth) if d != 0.0]
    failures = []
    bad = sum(1 for d in depth if not (0.0 <= d <= 1.0))
    if bad:
        failures.append(f"{bad} depths NaN, Inf or outside [0, 1]")
    if manifest["defaulted_read"]:
        failures.append("defaulted reads: " + ", ".join(manifest["defaulted_read"]))
    colour = pass_name in FORWARD_PASSES and not any(k.startswith("GT_DEBUG") for k in keywords)
    if colour:
        _, _, rgba = png_rgba(picture_png)
        black = sum(1 for i in covered if rgba[4 * i] == 0 and rgba[4 * i + 1] == 0 and rgba[4 * i + 2] == 0)
        if black:
            failures.append(f"{black} covered pixels black in every channel (NaN)")
    return len(covered), failures


def editor_pass_failures(pass_name, rgba, covered):
    """SceneSelectionPass writes (_ObjectId, _PassValue, 1, 1), ScenePickingPass _SelectionID: every covered pixel holds
    those bytes (picking: decoding back to the picking index), or the failures."""
    if pass_name == "SceneSelectionPass":
        want = [min(255, pp.EDITOR_OBJECT_ID * 255), min(255, pp.EDITOR_PASS_VALUE * 255), 255, 255]
        wrong = [i for i in covered if list(rgba[4 * i:4 * i + 4]) != want]
        return [f"{len(wrong)} covered pixels not (_ObjectId, _PassValue, 1, 1) = {want}"] if wrong else []
    wrong = [i for i in covered if pp.decode_selection_id(rgba[4 * i:4 * i + 4]) != pp.PICKING_INDEX]
    return [f"{len(wrong)} covered pixels do not decode to the picking index {pp.PICKING_INDEX}"] if wrong else []


def screen_texture_failures(keywords, rgba, base, shadowed, width, covered):
    """The single-keyword screen-space variants against ForwardLit's base picture (BASE) and, for SSAO, the
    _MAIN_LIGHT_SHADOWS_SCREEN picture (SHADOWED), whose right half keeps only the ambient term albedo x ambient.
    Left of width / 2 the textures hold 1: the picture is the base one within 1/255. Right of it: screen shadows,
    no channel above the base's; SSAO at SSAO_LEVEL with direct strength s: albedo x (ambient x ao + light x N.L x
    lerp(1, ao, s)) = k B - (k - ao) S where k = lerp(1, ao, s), B the base and S the shadowed picture, within 2/255."""
    k = 1.0 + (pp.SSAO_LEVEL - 1.0) * pp.SSAO_DIRECT_STRENGTH
    left = off = 0
    for i in covered:
        for c in range(3):
            v, b = rgba[4 * i + c], base[4 * i + c]
            if i % width < width // 2:
                left += abs(v - b) > 1
            elif "_SCREEN_SPACE_OCCLUSION" in keywords:
                off += abs(v - (k * b - (k - pp.SSAO_LEVEL) * shadowed[4 * i + c])) > 2
            else:
                off += v > b + 1
    what = "SSAO's" if "_SCREEN_SPACE_OCCLUSION" in keywords else "the screen shadow's"
    return ([f"{left} channels in the unoccluded half differ from the base picture by more than 1/255"] if left else []) + \
        ([f"{off} channels in {what} half off its expected value"] if off else [])


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default=os.path.join(pp.PKG_DIR, ".build", "pipeline-pass-all"))
    ap.add_argument("--list", action="store_true", help="print the variants (tab-separated) and draw nothing")
    ap.add_argument("--pipeline", action="append", choices=PIPELINES, help="only these pipelines (default: all three)")
    ap.add_argument("--pass", dest="passes", action="append", default=[], help="NAME: only passes of this name")
    ap.add_argument("--keyword", action="append", default=[], help="KEYWORD: only variants that have it")
    a = ap.parse_args(argv)
    shader = os.path.join(pp.PKG_DIR, "Shaders", "GregoryTerrain.shader")
    todo = [v for v in tessellated_variants(shader)
            if (not a.pipeline or v[0] in a.pipeline) and (not a.passes or v[2] in a.passes)
            and all(k in v[3] for k in a.keyword)]
    if a.list:
        for pipeline, sub, name, keywords in todo:
            print(f"{pipeline}\t{sub}\t{name}\t{' '.join(keywords) or '-'}")
        return 0
    pp.MISSING_BUFFER = zero_buffer
    # HDRP's ShadowCaster reads ZClip [_ZClip]: HDRP sets 0 for a directional light's cascades (pipeline_pass_hdrp.py).
    render_state.GLOBAL_PROPERTIES["_ZClip"] = "off"
    scene = types.SimpleNamespace(sun_elevation=30.0, sun_azimuth=-140.0, light_color=[1.0, 0.96, 0.9], object_yaw=0.0,
                                  leave_default=[], fill_from=[], transpose=[])
    os.makedirs(a.out, exist_ok=True)
    buffers = pp.pack_scene(a.out)
    cam, _, _ = pp.rig_camera(buffers)
    sun = pp.sun_direction(scene.sun_elevation, scene.sun_azimuth)
    light = pp.MainLightShadow(cam, sun)
    # What each pass's frame sets besides the pipeline's camera and light: the shadow casters drawn as the frames of
    # gt pipeline_pass / gt pipeline_pass_hdrp draw them (URP's and HDRP's from the light, Built-in's as the camera's
    # depth texture), the receivers' shadow constants (their maps stay the 1x1 defaults: nothing occludes).
    pass_scene = {("URP", "ShadowCaster"): light.caster_values(), ("Builtin", "ShadowCaster"): pp.builtin_camera_depth_values(),
                  ("HDRP", "ShadowCaster"): pipeline_pass_hdrp.HdrpCascade(cam, sun).caster_values()}
    pipeline_scene = {"URP": light.receiver_values(), "Builtin": pp.builtin_collect_values(light), "HDRP": {}}
    for pipeline in ("URP", "HDRP"):    # the editor's own passes: what it sets for them (pipeline_pass.editor_pass_values)
        for editor_pass in ("SceneSelectionPass", "ScenePickingPass"):
            pass_scene[(pipeline, editor_pass)] = pp.editor_pass_values(editor_pass)
    # _MAIN_LIGHT_SHADOWS_CASCADE: URP's 4 cascades (their spheres and atlas matrices; the map stays the 1x1 default,
    # gt pipeline_pass --only lit_cascades draws it); the screen-space textures: pipeline_pass.screen_halves.
    cascades = pp.MainLightCascades(cam, sun, 4)
    screen = {"_ScreenSpaceShadowmapTexture": pp.screen_halves(os.path.join(a.out, "screen_shadow.f32"), cam.width, cam.height,
                                                               pp.SCREEN_SHADOW_RIGHT),
              "_ScreenSpaceOcclusionTexture": pp.screen_halves(os.path.join(a.out, "ssao.f32"), cam.width, cam.height, pp.SSAO_LEVEL)}
    pictures = {}   # (pipeline, pass, keywords) -> RGBA of a drawn variant, for the screen-space variants' references
    clock = time.time()
    rows, per_pipeline, per_set = [], collections.Counter(), collections.Counter()
    filled = collections.Counter()
    defaulted = collections.Counter()
    failed = []
    def draw_variant(folder, pipeline, name, keywords):
        """Draws one variant into folder: (picture, depth file, manifest, compiler)."""
        compiler = compiler_for(pipeline, keywords)
        values = dict(pipeline_scene[pipeline], **pass_scene.get((pipeline, name), {}))
        if set(keywords) & set(shaderlab.FOG_KEYWORDS):     # the fog pictures' RenderSettings fog
            values.update(pp.fog_values("lit_fog_linear"))
        if pipeline == "URP" and "_MAIN_LIGHT_SHADOWS_CASCADE" in keywords:
            values.update(cascades.receiver_values())
        if pipeline == "URP" and "_SCREEN_SPACE_OCCLUSION" in keywords:
            values.update(pp.ssao_values())
        args = pp.prepare(scene, pipeline, name, keywords, buffers, folder, compiler, scene=values, sun=sun,
                          images=screen if pipeline == "URP" else None)
        frag = args[args.index("--frag") + 1]
        outputs = pp.reflect(frag).get("outputs", [])
        target1 = f"R8_UNORM:{os.path.join(folder, 'target1.bin')}" if any(o.get("location") == 1 for o in outputs) else None
        png, depth = os.path.join(folder, "picture.png"), os.path.join(folder, "depth.f32")
        pp.draw(args, buffers, png, os.path.join(folder, "harness.log"), depth_out=depth, target1=target1)
        with open(os.path.join(folder, "manifest.json")) as f:
            manifest = json.load(f)
        pictures[(pipeline, name, tuple(keywords))] = png_rgba(png)[2]
        return png, depth, manifest, compiler

    def reference(keywords):
        """URP ForwardLit's picture with exactly these keywords, drawn now if the run has not drawn it."""
        key = ("URP", "ForwardLit", tuple(keywords))
        if key not in pictures:
            draw_variant(os.path.join(a.out, "reference-" + ("+".join(keywords) or "base")), "URP", "ForwardLit", keywords)
        return pictures[key]

    for i, (pipeline, sub, name, keywords) in enumerate(todo):
        label = f"{pipeline} {name} {'+'.join(keywords) or 'base'}"
        png, depth, manifest, compiler = draw_variant(os.path.join(a.out, f"{i:03d}"), pipeline, name, keywords)
        covered, failures = check(png, depth, name, keywords, manifest)
        cover = [j for j, d in enumerate(pp.read_floats(depth)) if d != 0.0]
        if name in ("SceneSelectionPass", "ScenePickingPass"):
            failures += editor_pass_failures(name, pictures[(pipeline, name, tuple(keywords))], cover)
        if pipeline == "URP" and keywords in (["_MAIN_LIGHT_SHADOWS_SCREEN"], ["_SCREEN_SPACE_OCCLUSION"]):
            failures += screen_texture_failures(keywords, pictures[(pipeline, name, tuple(keywords))], reference([]),
                                                reference(["_MAIN_LIGHT_SHADOWS_SCREEN"]), png_rgba(png)[0], cover)
        lacking = [SCENE_LACKS[k] for k in keywords if k in SCENE_LACKS]
        if lacking:     # zero inputs the scene cannot describe: their reads are listed, not failed
            failures = [f for f in failures if not f.startswith("defaulted reads")]
        print(f"variant {label} compiler {compiler}: covered {covered}, filled {len(manifest['filled'])}, "
              f"defaulted {len(manifest['defaults'])}, defaulted_read {len(manifest['defaulted_read'])}"
              + (f" (the scene has no {', no '.join(lacking)}" + "".join(f": {r}" for r in [', '.join(manifest['defaulted_read'])] if r)
                 + ")" if lacking else "")
              + ("; FAILED: " + "; ".join(failures) if failures else ""), flush=True)
        rows.append({"pipeline": pipeline, "pass": name, "keywords": keywords, "compiler": compiler, "covered": covered,
                     "filled": len(manifest["filled"]), "defaulted": len(manifest["defaults"]), "failures": failures})
        per_pipeline[(pipeline, name)] += 1
        per_set[(pipeline, "base" if not keywords else "effects" if set(keywords) & set(shaderlab.EFFECTS) and len(keywords) > 1
                 else "one keyword")] += 1
        filled[pipeline] += len(manifest["filled"])
        defaulted[pipeline] += len(manifest["defaults"])
        if failures:
            failed.append(label)
    for pipeline in PIPELINES:
        passes = {n: c for (p, n), c in per_pipeline.items() if p == pipeline}
        if passes:
            print(f"pipeline {pipeline}: {len(passes)} passes, {sum(passes.values())} variants drawn "
                  f"({', '.join(f'{n} {c}' for n, c in passes.items())}); bindings' members filled {filled[pipeline]}, "
                  f"defaulted {defaulted[pipeline]} (over all its variants)")
    for (pipeline, kind), count in sorted(per_set.items()):
        print(f"variant set {pipeline} {kind}: {count}")
    print(f"drawn {len(rows)} variants in {time.time() - clock:.0f} s; failed {len(failed)}" + (": " + "; ".join(failed) if failed else ""))
    with open(os.path.join(a.out, "variants.json"), "w") as f:
        json.dump(rows, f, indent=1)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
