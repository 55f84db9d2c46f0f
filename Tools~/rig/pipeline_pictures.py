#!/usr/bin/env python3
"""gt pipeline_pictures: the same scene through the standalone rig, URP, HDRP and Built-in, side by side.

The sample grid in RigScene's zoom view under the shadowed frame's sun (12 degrees up, from +x: a ridge shadows a
valley), each panel the pipeline's own passes as gt pipeline_pass / gt pipeline_pass_hdrp draw them:
  standalone  the rig's own adapter (Shaders/Pipelines/StandaloneAdapter.hlsl, base variant, the sun in
              _RigLightDirection; its light colour, 1, is every panel's; it has no shadow)
  URP         ForwardLit _MAIN_LIGHT_SHADOWS over its ShadowCaster's 2048^2 map (pipeline_pass.py lit_shadows)
  HDRP        ForwardOnly SHADOW_LOW over DepthForwardOnly's depth and its ShadowCaster's cascade, after HDRP's
              exposure (pipeline_pass_hdrp.py hdrp_lit_shadows: x 0.81 of URP's where their models agree)
  Built-in    ForwardBase SHADOWS_SCREEN (DXC's SPIR-V) over the screen-space shadow its ShadowCaster's 2048^2 map and
              the camera's depth texture give (pipeline_pass.py builtin_lit_shadows); ForwardBase's base variant
              (builtin_lit) is drawn too, for its agreement with the standalone panel
Writes OUT/pipelines.png (4 x 200 px wide) and prints where the panels agree: per pair, the covered pixels
whose channels differ by at most 2/255 (HDRP divided by its exposure scale first). --docs also writes the
palette PNG to Documentation~/images/pipelines.png (png_palette.py; run with a python3 that has PIL).

  gt pipeline_pictures [--out DIR] [--docs]
"""
import argparse
import json
import math
import os
import struct
import subprocess
import sys

RIG_DIR = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, RIG_DIR)
import pipeline_pass as pp  # noqa: E402
import render_state  # noqa: E402

SUN = ("12", "90")                     # the shadowed frame's sun: pipeline_pass.py's --shadow-sun-* defaults
LIGHT = "1,1,1"                        # the standalone adapter's light colour, so every panel has the same sun
HDRP_SCALE = 100000.0 / math.pi / (1.2 * 2.0 ** 15)   # lux / pi x fixed exposure (pipeline_pass_hdrp.py)
PANEL = (200, 150)                     # half the rig's 400 x 300: the manual's picture stays small
SKY = (140, 178, 230)


def run(cmd, log, env=None):
    r = subprocess.run(cmd, capture_output=True, text=True, env=env)
    with open(log, "w") as f:
        f.write(" ".join(cmd) + "\n" + r.stdout + r.stderr)
    if r.returncode != 0:
        raise SystemExit(f"pipeline-pictures: error: {' '.join(cmd[:2])} failed ({log}):\n{r.stdout[-1500:]}{r.stderr[-1500:]}")


def standalone(out, buffers, sun):
    """The rig's own base variant on pipeline_pass.py's buffers, the camera block's light turned to SUN."""
    shaders = os.path.join(out, "shaders")
    # Its own build folder: gt shaders empties the SPIR-V folder it writes.
    run(["bash", os.path.join(RIG_DIR, "shaders.sh"), "--only", "base", "--spirv-only"], os.path.join(out, "shaders.log"),
        env=dict(os.environ, GT_BUILD_DIR=shaders))
    lit = os.path.join(out, "standalone_buffers")
    subprocess.run(["rm", "-rf", lit], check=True)
    subprocess.run(["cp", "-r", buffers, lit], check=True)
    cam = pp.read_floats(os.path.join(lit, "camera.f32"))
    cam[40:43] = sun                                   # _RigLightDirection (RigCamera: 2 matrices, 2 float4 before it)
    with open(os.path.join(lit, "camera.f32"), "wb") as f:
        f.write(struct.pack(f"<{len(cam)}f", *cam))
    spv = os.path.join(shaders, "spirv", "base")
    state = render_state.harness_options(os.path.join(pp.PKG_DIR, "Shaders", "GregoryTerrain.shader"), "tessellated").split()
    png = os.path.join(out, "standalone.png")
    run([os.path.join(pp.PKG_DIR, ".build", "harness", "gt-harness"), "--vert", f"{spv}/vert.spv", "--tesc", f"{spv}/tesc.spv",
         "--tese", f"{spv}/tese.spv", "--frag", f"{spv}/frag.spv", "--buffers", lit, "--patches", str(pp.TILES ** 2),
         "--width", str(pp.WIDTH), "--height", str(pp.HEIGHT), "--png", png] + state, os.path.join(out, "standalone.log"))
    return png


def agreement(a, b, scale_a=1.0):
    """Covered pixels (both not sky) and how many of them agree within 2/255 per channel, a divided by scale_a."""
    covered = same = 0
    for pa, pb in zip(a.getdata(), b.getdata()):
        if all(abs(x - s) <= 1 for x, s in zip(pa, SKY)) or all(abs(x - s) <= 1 for x, s in zip(pb, SKY)):
            continue
        covered += 1
        same += all(abs(x / scale_a - y) <= 2.0 for x, y in zip(pa, pb))
    return covered, same


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default=os.path.join(pp.PKG_DIR, ".build", "pipeline-pictures"))
    ap.add_argument("--docs", action="store_true", help="also write Documentation~/images/pipelines.png (palette)")
    a = ap.parse_args(argv)
    from PIL import Image   # the rig's python3 for pictures (png_palette.py needs it too)
    os.makedirs(a.out, exist_ok=True)
    urp, hdrp = os.path.join(a.out, "urp"), os.path.join(a.out, "hdrp")
    scene = ["--light-color", LIGHT]
    run([sys.executable, os.path.join(RIG_DIR, "pipeline_pass.py"), "--out", urp, "--only", "lit_shadows", "--only", "builtin_lit", "--only", "builtin_lit_shadows",
         "--sun-elevation", SUN[0], "--sun-azimuth", SUN[1], "--shadow-sun-elevation", SUN[0], "--shadow-sun-azimuth", SUN[1]] + scene,
        os.path.join(a.out, "urp.log"))
    run([sys.executable, os.path.join(RIG_DIR, "pipeline_pass_hdrp.py"), "--out", hdrp, "--only", "hdrp_lit_shadows",
         "--shadow-sun-elevation", SUN[0], "--shadow-sun-azimuth", SUN[1]] + scene, os.path.join(a.out, "hdrp.log"))
    sun = pp.sun_direction(float(SUN[0]), float(SUN[1]))
    files = [standalone(a.out, os.path.join(urp, "buffers"), sun), os.path.join(urp, "lit_shadows.png"),
             os.path.join(hdrp, "hdrp_lit_shadows.png"), os.path.join(urp, "builtin_lit_shadows.png"), os.path.join(urp, "builtin_lit.png")]
    pictures = [Image.open(f).convert("RGB") for f in files]
    figures = {"HDRP / scale vs URP (both shadowed)": agreement(pictures[2], pictures[1], HDRP_SCALE),
               "Built-in (base variant) vs standalone (both unshadowed)": agreement(pictures[4], pictures[0]),
               "Built-in vs URP (both shadowed)": agreement(pictures[3], pictures[1])}
    for what, (covered, same) in figures.items():
        print(f"agree {what}: {same} of {covered} covered pixels within 2/255 ({100.0 * same / max(covered, 1):.2f}%)")
    sheet = Image.new("RGB", (PANEL[0] * 4, PANEL[1]))
    for i, p in enumerate(pictures[:4]):
        sheet.paste(p.resize(PANEL, Image.LANCZOS), (PANEL[0] * i, 0))
    png = os.path.join(a.out, "pipelines.png")
    sheet.save(png)
    with open(os.path.join(a.out, "agreement.json"), "w") as f:
        json.dump({k: {"covered": c, "within_2_255": s} for k, (c, s) in figures.items()}, f, indent=1)
    print(f"picture {png}")
    if a.docs:
        doc = os.path.join(pp.PKG_DIR, "Documentation~", "images", "pipelines.png")
        run([sys.executable, os.path.join(RIG_DIR, "png_palette.py"), png, doc, "32"], os.path.join(a.out, "palette.log"))
        print(f"docs {doc} {os.path.getsize(doc)} bytes")


if __name__ == "__main__":
    main()
