#!/usr/bin/env bash
# Patch-record layout benchmark (prints figures; not a test): the draw's GPU time with the patch
# layout of REF (absolute control points, one float per grid line, its shaders) against this tree's
# (relative control points, hi/lo lines: internals.md, "GPU layout"), side by side in one run,
# interleaved rounds, the same scene at a uniform factor (both layouts draw the same triangles).
#   bash Tools~/rig/bench_patch_layout.sh [--ref REF] [--variant base] [--rounds 5] [--frames 60]
#                                         [--factor 16] [--tiles 16] [--width 1920 --height 1080]
#                                         [--device NAME]
# REF: a commit before the patch records (default: the merge base with main). Needs gt setup.
# Prints each round's median frame time per layout, then the medians and new / old.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
ref="" variant=base rounds=5 frames=60 factor=16 tiles=16 width=1920 height=1080 device=()
while [ $# -gt 0 ]; do
  case "$1" in
    --ref) ref=$2; shift ;;
    --variant) variant=$2; shift ;;
    --rounds) rounds=$2; shift ;;
    --frames) frames=$2; shift ;;
    --factor) factor=$2; shift ;;
    --tiles) tiles=$2; shift ;;
    --width) width=$2; shift ;;
    --height) height=$2; shift ;;
    --device) device=(--device "$2"); shift ;;
    *) die "bench_patch_layout: unknown option $1" ;;
  esac
  shift
done
cli=(dotnet "$BUILD_DIR/gt-cli/gt-cli.dll")
harness="$BUILD_DIR/harness/gt-harness"
[ -f "$BUILD_DIR/gt-cli/gt-cli.dll" ] && [ -x "$harness" ] || die "gt-cli or the harness is not built (run: gt setup)"
[ -n "$ref" ] || ref=$(git -C "$PKG_DIR" merge-base HEAD main) || die "no --ref and no merge base with main"
work="$BUILD_DIR/bench-patch-layout"
rm -rf "$work"; mkdir -p "$work/old-pkg" "$work/new" "$work/old"

# This tree's shaders and buffers.
bash "$RIG_DIR/shaders.sh" --only "$variant" >/dev/null || die "gt shaders --only $variant failed"
cp -r "$BUILD_DIR/spirv/$variant" "$work/new-spv"
"${cli[@]}" demo-grid --out "$work/grid.json" >/dev/null
"${cli[@]}" pack --grid "$work/grid.json" --out "$work/new" --tiles "$tiles" --factor "$factor" \
  --width "$width" --height "$height" >/dev/null

# REF's shaders (its own compile script) and its layout of the same grid: absolute points (the
# reference point added back, w = 1), the hi lines only.
git -C "$PKG_DIR" archive "$ref" Shaders 'Tools~/rig' | tar -x -C "$work/old-pkg"
python3 "$work/old-pkg/Tools~/rig/shaders.py" "$work/old-spv-all" --only "$variant" >/dev/null || die "compiling $ref's $variant failed"
cp -r "$work/old-spv-all/$variant" "$work/old-spv"
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

run() {  # run LAYOUT: one harness run, prints its median frame ms
  local l=$1 spv="$work/$1-spv"
  "$harness" "${device[@]}" --vert "$spv/vert.spv" --tesc "$spv/tesc.spv" --tese "$spv/tese.spv" --frag "$spv/frag.spv" \
    --buffers "$work/$l" --patches $((tiles * tiles)) --width "$width" --height "$height" \
    --frames "$frames" --warmup 5 --timestamps 2>&1 | awk '$1 == "time" && $2 == "frame_ms_median" {print $3}'
}
old_all=() new_all=()
for r in $(seq 1 "$rounds"); do
  o=$(run old); n=$(run new)
  [ -n "$o" ] && [ -n "$n" ] || die "round $r: the harness printed no frame time (old '$o', new '$n')"
  echo "round $r: old $o ms, new $n ms"
  old_all+=("$o"); new_all+=("$n")
done
python3 - "${old_all[*]}" "${new_all[*]}" "$ref" "$variant" <<'PY'
import statistics, sys
old = [float(x) for x in sys.argv[1].split()]
new = [float(x) for x in sys.argv[2].split()]
mo, mn = statistics.median(old), statistics.median(new)
print(f"patch layout ({sys.argv[4]}): {sys.argv[3][:12]} {mo:.3f} ms, this tree {mn:.3f} ms, new / old {mn / mo:.3f}")
PY
