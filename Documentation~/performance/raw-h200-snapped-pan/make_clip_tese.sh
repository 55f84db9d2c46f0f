#!/usr/bin/env bash
# How the experiment's tessellation evaluation stages were made (glslang's HLSL front end has no
# SV_ClipDistance in that stage: "clip/cull not currently implemented for this stage"). Run in a
# copy of the package with experiment-shaders.patch applied, where the experiment's varying
# expClipDistance is an ordinary TEXCOORD7 output; spirv-cross turns the SPIR-V into GLSL, the
# output is made gl_ClipDistance[4] by hand, and glslang compiles the GLSL back.
#   clip       the range's four sides as clip distances (GT_EXP_CLIP)
#   snapclip   the same, clipped spans snapped outward to 1/16 of a cell (GT_EXP_CLIP GT_EXP_SNAP=16.0);
#              its cache_factors and cache_vertices are compiled from the HLSL with the same defines
#   clipconst  the bench's own tese with gl_ClipDistance[0..3] = 1.0 (nothing clipped)
#   aluonly    clip's arithmetic folded into gl_Position.x * 1e-30 instead of clip distances
set -euo pipefail
base=${1:?usage: make_clip_tese.sh BENCH_SPIRV_DIR OUT_DIR}
out=${2:?}
hlsl() {  # hlsl OUT.spv DEFINES...
  local o=$1; shift
  glslangValidator -D -V -S tese -e domain_shader --hlsl-iomap --shift-cbuffer-binding 0 --shift-texture-binding 2 \
    --shift-UAV-binding 5 -DGT_NOISE -DGT_HEIGHT_COLOR -DGT_VERTEX_CACHE "$@" -o "$o" Shaders/Rig/TerrainRig.hlsl >/dev/null
}
mkdir -p "$out"/{clip,snapclip,clipconst,aluonly}
hlsl "$out/clip/hlsl.spv" -DGT_EXP_CLIP
hlsl "$out/snapclip/hlsl.spv" -DGT_EXP_CLIP -DGT_EXP_SNAP=16.0
for v in clip snapclip; do spirv-cross "$out/$v/hlsl.spv" --vulkan-semantics --output "$out/$v/tese.glsl"; done
cp "$out/clip/tese.glsl" "$out/aluonly/tese.glsl"
spirv-cross "$base/noise+height_color+vertex_cache/tese.spv" --vulkan-semantics --output "$out/clipconst/tese.glsl"
python3 - "$out" <<'PY'
import re, sys
out = sys.argv[1]
for v in ("clip", "snapclip"):
    p = f"{out}/{v}/tese.glsl"; s = open(p).read()
    s = s.replace("layout(location = 1) out vec4 _entryPointOutput_expClipDistance;\n", "out float gl_ClipDistance[4];\n")
    m = re.search(r"    _entryPointOutput_expClipDistance = (vec4\(.*\));\n", s)
    s = s.replace(m.group(0), f"    vec4 expClip = {m.group(1)};\n    gl_ClipDistance[0] = expClip.x; gl_ClipDistance[1] = expClip.y; gl_ClipDistance[2] = expClip.z; gl_ClipDistance[3] = expClip.w;\n")
    open(p, "w").write(s)
p = f"{out}/clipconst/tese.glsl"; s = open(p).read()
i = s.index("void main()"); s = s[:i] + "out float gl_ClipDistance[4];\n\n" + s[i:]
j = s.rindex("}"); s = s[:j] + "    gl_ClipDistance[0] = 1.0; gl_ClipDistance[1] = 1.0; gl_ClipDistance[2] = 1.0; gl_ClipDistance[3] = 1.0;\n" + s[j:]
open(p, "w").write(s)
p = f"{out}/aluonly/tese.glsl"; s = open(p).read()
s = s.replace("layout(location = 1) out vec4 _entryPointOutput_expClipDistance;\n", "")
m = re.search(r"    _entryPointOutput_expClipDistance = (vec4\(.*\));\n", s)
s = s.replace(m.group(0), f"    vec4 expClip = {m.group(1)};\n    gl_Position.x += 1e-30 * (expClip.x + expClip.y + expClip.z + expClip.w);\n")
open(p, "w").write(s)
PY
for v in clip snapclip clipconst aluonly; do
  glslangValidator -V -S tese -o "$out/$v/tese.spv" "$out/$v/tese.glsl" >/dev/null && spirv-val "$out/$v/tese.spv"
done
