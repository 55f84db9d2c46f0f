# gt snow-carry DEST [--resolutions R1,R2,...] [--steps N] [--dt S] [--size WxH]: assembles the self-contained
# folder that Tools~/rig/snow-device.sh runs (on lavapipe here, or carried to a GPU machine): the
# prebuilt gt-harness and gt-compute, the SPIR-V of the snow kernels and of the terrain with and
# without GT_SNOW, and the ridge scene of `gt-cli snow-scene` (default R 256,512,1024,2048, 200
# steps of 0.05 s, frames of 640 x 480), and the render state of the shader's forward pass
# (pass_state_*.args). A Vulkan loader .deb found in $PKG_DIR/.gl is copied to DEST/.gl.
# Then: bash DEST/snow-device.sh DEST [--device NVIDIA]
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
dest="${1:?usage: gt snow-carry DEST [--resolutions R,...] [--steps N] [--dt S]}"; shift
resolutions="256,512,1024,2048"; steps=200; dt=0.05; size=640x480
while [ $# -gt 0 ]; do
  case "$1" in
    --resolutions) check_number snow-carry "$1" resolution,... "${2-}"; resolutions=$2; shift ;;
    --steps) check_number snow-carry "$1" frames "${2-}"; steps=$2; shift ;;
    --dt) check_number snow-carry "$1" seconds "${2-}"; dt=$2; shift ;;
    --size) check_number snow-carry "$1" size "${2-}"; size=$2; shift ;;
    *) usage_error snow-carry "unknown argument '$1'" ;;
  esac
  shift
done
for f in "$BUILD_DIR/harness/gt-harness" "$BUILD_DIR/computerig/gt-compute" "$BUILD_DIR/gt-cli/gt-cli"; do
  [ -x "$f" ] || die "$f is missing (run: gt setup)"
done
rm -rf "$dest"; mkdir -p "$dest/bin" "$dest/spv"
cp "$BUILD_DIR/harness/gt-harness" "$BUILD_DIR/computerig/gt-compute" "$dest/bin/"
cp "$RIG_DIR/snow-device.sh" "$RIG_DIR/options.py" "$dest/"
write_pass_states "$dest"   # the forward pass's render state, for snow-device.sh
# The terrain variants, compiled by gt shaders into a private build folder.
tmp="$BUILD_DIR/snow-carry-spirv"; rm -rf "$tmp"
GT_BUILD_DIR="$tmp" bash "$TOOLS_DIR/gt" shaders --only noise+height_color+snow --only noise+height_color >/dev/null \
  || die "gt shaders failed (run it alone to see why)"
for v in snow:noise+height_color+snow bare:noise+height_color; do
  mkdir -p "$dest/spv/${v%%:*}"
  for s in vert tesc tese frag; do cp "$tmp/spirv/${v#*:}/$s.spv" "$dest/spv/${v%%:*}/"; done
done
# The kernels: the field with the terrain stages' register shifts and noise, the simulation without.
glslangValidator -D -V -S comp -e SnowFieldKernel --hlsl-iomap --stb 2 --suavb 5 -DGT_NOISE \
  -o "$dest/spv/SnowFieldKernel.spv" "$PKG_DIR/Shaders/Snow/SnowField.compute" >/dev/null || die "glslang failed on SnowFieldKernel"
for k in SnowExposureKernel SnowAccumulateKernel; do
  glslangValidator -D -V -S comp -e "$k" -o "$dest/spv/$k.spv" "$PKG_DIR/Shaders/Snow/SnowSimulation.compute" >/dev/null \
    || die "glslang failed on $k"
done
for f in "$dest"/spv/*.spv "$dest"/spv/*/*.spv; do spirv-val "$f"; done
"$BUILD_DIR/gt-cli/gt-cli" snow-scene --out "$dest/snow" --resolutions "$resolutions" --steps "$steps" --dt "$dt" \
  --width "${size%x*}" --height "${size#*x}" >&2
if ls "$PKG_DIR"/.gl/*.deb >/dev/null 2>&1; then mkdir -p "$dest/.gl"; cp "$PKG_DIR"/.gl/*.deb "$dest/.gl/"; fi
say "assembled $(du -sh "$dest" | cut -f1) in $dest; run: bash $dest/snow-device.sh $dest [--device NVIDIA]"
