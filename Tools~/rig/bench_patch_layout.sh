#!/usr/bin/env bash
# Patch-record layout benchmark (prints figures; not a test): the draw's GPU time with the patch
# layout and shaders of REF against this tree's, side by side in one run, interleaved rounds, the
# same scene at a uniform factor (both layouts draw the same triangles).
#   bash Tools~/rig/bench_patch_layout.sh [--ref REF] [--variant base] [--tiles 16] [--factor 16]
#        [--width 1920 --height 1080] [--rounds 5] [--frames 60] [--device NAME] [--prepare DIR]
# REF: a commit (default: the merge base with main). Its layout is read from its shaders:
#   - before the relative points (no PatchReference in its PatchGrid.hlsl): absolute points, w = 1,
#     the hi grid lines only; the buffers are converted to that;
#   - from the relative points on (2d50e65, 20 float4 read by index arithmetic; or the typed
#     GregoryPatchRecord of this tree): the same bytes, so only the shaders differ.
# Needs gt setup (the CLI packs the scene here). --prepare DIR writes a self-contained folder instead
# of running: bin/gt-harness, spv/old, spv/new, buffers old/ and new/, bench.conf and the device
# script, which needs only bash, python3 and a Vulkan loader (.gl/*.deb when the machine has none):
#   bash DIR/bench_patch_layout-device.sh DIR [--rounds R] [--frames N] [--device NAME]
# Without --prepare the same folder is made under .build and the device script runs here.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
ref="" variant=base rounds=5 frames=60 factor=16 tiles=16 width=1920 height=1080 device=() prepare=""
while [ $# -gt 0 ]; do
  case "$1" in
    --ref) ref=$2; shift ;;
    --variant) variant=$2; shift ;;
    --rounds) check_number bench_patch_layout "$1" rounds "${2-}"; rounds=$2; shift ;;
    --frames) check_number bench_patch_layout "$1" frames "${2-}"; frames=$2; shift ;;
    --factor) check_number bench_patch_layout "$1" factor "${2-}"; factor=$2; shift ;;
    --tiles) check_number bench_patch_layout "$1" tiles "${2-}"; tiles=$2; shift ;;
    --width) check_number bench_patch_layout "$1" pixels "${2-}"; width=$2; shift ;;
    --height) check_number bench_patch_layout "$1" pixels "${2-}"; height=$2; shift ;;
    --device) device=(--device "$2"); shift ;;
    --prepare) prepare=$2; shift ;;
    *) usage_error bench_patch_layout "unknown option $1" ;;
  esac
  shift
done
cli=(dotnet "$BUILD_DIR/gt-cli/gt-cli.dll")
harness="$BUILD_DIR/harness/gt-harness"
[ -f "$BUILD_DIR/gt-cli/gt-cli.dll" ] && [ -x "$harness" ] || die "gt-cli or the harness is not built (run: gt setup)"
[ -n "$ref" ] || ref=$(git -C "$PKG_DIR" merge-base HEAD main) || die "no --ref and no merge base with main"
ref=$(git -C "$PKG_DIR" rev-parse --verify "$ref^{commit}") || die "--ref $ref is no commit"
work="${prepare:-$BUILD_DIR/bench-patch-layout}"
scratch="$BUILD_DIR/bench-patch-layout-scratch"
rm -rf "$work" "$scratch"; mkdir -p "$work/bin" "$work/spv" "$work/new" "$work/old" "$scratch/old-pkg"
work="$(cd "$work" && pwd)"

# This tree's shaders and buffers.
bash "$RIG_DIR/shaders.sh" --spirv-only --only "$variant" >/dev/null || die "gt shaders --only $variant failed"
mkdir -p "$work/spv/new" "$work/spv/old"
cp "$BUILD_DIR/spirv/$variant/"*.spv "$work/spv/new/"
"${cli[@]}" demo-grid --out "$scratch/grid.json" >/dev/null
"${cli[@]}" pack --grid "$scratch/grid.json" --out "$work/new" --tiles "$tiles" --factor "$factor" \
  --width "$width" --height "$height" >/dev/null

# REF's shaders (its own compile script) and its layout of the same grid.
git -C "$PKG_DIR" archive "$ref" Shaders 'Tools~/rig' | tar -x -C "$scratch/old-pkg"
python3 "$scratch/old-pkg/Tools~/rig/shaders.py" "$scratch/old-spv-all" --only "$variant" >/dev/null || die "compiling ${ref:0:12}'s $variant failed"
cp "$scratch/old-spv-all/$variant/"*.spv "$work/spv/old/"
if grep -q PatchReference "$scratch/old-pkg/Shaders/Grid/PatchGrid.hlsl" 2>/dev/null; then
  old_layout="relative points (the same bytes)"
  cp "$work/new/"*.f32 "$work/old/"
else
  old_layout="absolute points, hi lines only"
  cp "$work/new/params.f32" "$work/new/camera.f32" "$work/new/regions.f32" "$work/old/"
  python3 - "$work/new" "$work/old" <<'PY'
import struct, sys
src, dst = sys.argv[1], sys.argv[2]
cp = open(f"{src}/control_points.f32", "rb").read()
f = list(struct.unpack(f"<{len(cp) // 4}f", cp))
for p in range(len(f) // 80):
    ref = [f[80 * p + 4 * k + 3] for k in range(3)]
    for k in range(20):
        o = 80 * p + 4 * k
        f[o:o + 4] = [f[o] + ref[0], f[o + 1] + ref[1], f[o + 2] + ref[2], 1.0]
open(f"{dst}/control_points.f32", "wb").write(struct.pack(f"<{len(f)}f", *f))
lines = open(f"{src}/grid_lines.f32", "rb").read()
open(f"{dst}/grid_lines.f32", "wb").write(lines[: len(lines) // 2])
PY
fi
rm -rf "$scratch"
cp "$harness" "$work/bin/gt-harness"
cp "$RIG_DIR/bench_patch_layout-device.sh" "$RIG_DIR/options.py" "$work/"
cat >"$work/bench.conf" <<CONF
ref=${ref:0:12}
tree=$(git -C "$PKG_DIR" rev-parse --short=12 HEAD)$(git -C "$PKG_DIR" diff --quiet HEAD -- Shaders Runtime || echo +dirty)
variant=$variant
old_layout="$old_layout"
patches=$((tiles * tiles))
width=$width
height=$height
state="$(pass_state tessellated)"
CONF
if [ -n "$prepare" ]; then
  say "prepared $work ($(du -sh "$work" | cut -f1)): REF ${ref:0:12} ($old_layout) vs this tree; on the device: bash $work/bench_patch_layout-device.sh $work"
  exit 0
fi
dev=(); [ ${#device[@]} -gt 0 ] && dev=(--device "${device[1]}")
bash "$work/bench_patch_layout-device.sh" "$work" --rounds "$rounds" --frames "$frames" "${dev[@]}"
