#!/usr/bin/env bash
# lod-device.sh RUN_DIR [--device SUBSTR] [--frames N] [--rounds R]: GPU frame time of the levels of
# detail against today's single-range draw of about the same triangle count, from a self-contained
# folder (bash, python3 and the prebuilt harness; Tools~/rig/lod-carry.sh assembles it). Per terrain
# of RUN_DIR/runs.txt, R rounds of (levels, single range) alternating, each N frames after 3 warm-up
# frames, timed with Vulkan timestamps, 1920 x 1080. Prints raw lines, then per terrain the medians:
#   device NAME
#   draw TERRAIN_M lod|single round K frame_ms MEDIAN triangles T
#   lod TERRAIN_M lod_ms X single_ms Y ratio X/Y lod_triangles T1 single_triangles T2
# Logs go to $OUT when it is set, else RUN_DIR/out.
#
# RUN_DIR layout: bin/gt-harness; spv/lod/*.spv (lod+noise), spv/single/*.spv (noise);
# runs.txt ("NAME TERRAIN_M PATCHES LAVAPIPE_TRIANGLES F" a line); NAME/lod, NAME/single (lod-scene
# folders); pass_state_tessellated.args (the forward pass's render state as harness options);
# .gl/*.deb (optional) a Vulkan loader to unpack where the machine has none.
set -euo pipefail
run="$(cd "${1:?usage: lod-device.sh RUN_DIR [--device SUBSTR] [--frames N] [--rounds R]}" && pwd)"; shift
device=""; frames=50; rounds=3
# The rig's range check (options.py, carried beside this script).
check_number() { python3 "$(dirname "${BASH_SOURCE[0]}")/options.py" lod-device "$@" || exit 2; }
while [ $# -gt 0 ]; do
  case "$1" in
    --device) device="${2:?--device needs a name substring}"; shift ;;
    --frames) check_number "$1" frames "${2-}"; frames=$2; shift ;;
    --rounds) check_number "$1" rounds "${2-}"; rounds=$2; shift ;;
    *) echo "lod-device: unknown argument '$1'" >&2; exit 2 ;;
  esac
  shift
done
out="${OUT:-$run/out}"; mkdir -p "$out"
if ! ldconfig -p 2>/dev/null | grep -q libvulkan.so.1; then
  for d in "$run/.gl" ".gl"; do
    if ls "$d"/*.deb >/dev/null 2>&1; then for f in "$d"/*.deb; do dpkg -x "$f" /; done; ldconfig; break; fi
  done
fi
H="$run/bin/gt-harness"
read -ra state < "$run/pass_state_tessellated.args" || { echo "lod-device: $run has no pass_state_tessellated.args (assemble it again with gt lod-carry)" >&2; exit 2; }
dev=(); [ -n "$device" ] && dev=(--device "$device")
median() { python3 -c "import sys, statistics; v = [float(x) for x in sys.stdin.read().split()]; print(f'{statistics.median(v):.4f}' if v else 'nan')"; }
draw() {  # draw NAME KIND PATCHES LOG
  local v="$run/spv/$2" dir="$run/$1/$2" tail=()
  [ "$2" = lod ] && tail=(--params-tail "$dir/lod_tail.f32" --storage "7:$((64 * $3))" --storage 8:16)
  "$H" "${dev[@]}" --vert "$v/vert.spv" --tesc "$v/tesc.spv" --tese "$v/tese.spv" --frag "$v/frag.spv" \
    --buffers "$dir" "${tail[@]}" --patches "$3" --width 1920 --height 1080 "${state[@]}" --stats \
    --frames "$frames" --warmup 3 --timestamps >"$4" || { cat "$4"; exit 1; }
}
first=1
while read -r name metres patches _ f; do
  [ -n "$name" ] || continue
  lodt=""; sint=""
  for ((k = 1; k <= rounds; k++)); do
    draw "$name" lod "$patches" "$out/$name-lod-$k.log"
    draw "$name" single $((64 * 64)) "$out/$name-single-$k.log"
    if [ "$first" = 1 ]; then sed -n 's/^device name /device /p' "$out/$name-lod-$k.log"; first=0; fi
    for kind in lod single; do
      log="$out/$name-$kind-$k.log"
      ms=$(sed -n 's/^time frame_ms [0-9]* //p' "$log" | median)
      tri=$(awk '$1 == "stat" && $2 == "clipping_invocations" { print $3 }' "$log")
      echo "draw $metres $kind round $k frame_ms $ms triangles $tri"
      if [ "$kind" = lod ]; then lodt="$lodt $ms"; lodtri=$tri; else sint="$sint $ms"; sintri=$tri; fi
    done
  done
  l=$(echo "$lodt" | median); s=$(echo "$sint" | median)
  echo "lod $metres lod_ms $l single_ms $s ratio $(python3 -c "print(f'{$l / $s:.3f}')") lod_triangles $lodtri single_triangles $sintri"
done < "$run/runs.txt"
