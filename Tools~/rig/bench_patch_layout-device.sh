#!/usr/bin/env bash
# bench_patch_layout-device.sh DIR [--rounds R] [--frames N] [--device SUBSTR]: the patch layout A/B
# from a folder Tools~/rig/bench_patch_layout.sh --prepare DIR made (bash, python3 and the prebuilt
# harness; no dotnet). R rounds of (REF, this tree) alternating, each N frames after 5 warm-up
# frames, timed with Vulkan timestamps. Prints:
#   device NAME
#   round K old X ms new Y ms            (each run's median frame time)
#   patch layout (VARIANT): REF X ms, TREE Y ms, new / old R
# Both layouts draw with this tree's forward-pass render state (bench.conf's state): a REF from
# before the tessellated winding was made clockwise draws its terrain back-facing, culled.
# Logs go to $OUT when it is set, else DIR/out.
set -euo pipefail
dir="$(cd "${1:?usage: bench_patch_layout-device.sh DIR [--rounds R] [--frames N] [--device SUBSTR]}" && pwd)"; shift
rounds=5; frames=60; device=""
# The rig's range check (options.py, carried beside this script).
check_number() { python3 "$(dirname "${BASH_SOURCE[0]}")/options.py" bench_patch_layout-device "$@" || exit 2; }
while [ $# -gt 0 ]; do
  case "$1" in
    --rounds) check_number "$1" rounds "${2-}"; rounds=$2; shift ;;
    --frames) check_number "$1" frames "${2-}"; frames=$2; shift ;;
    --device) device="${2:?--device needs a name substring}"; shift ;;
    *) echo "bench_patch_layout-device: unknown argument '$1'" >&2; exit 2 ;;
  esac
  shift
done
# shellcheck source=/dev/null
source "$dir/bench.conf"
out="${OUT:-$dir/out}"; mkdir -p "$out"
if ! ldconfig -p 2>/dev/null | grep -q libvulkan.so.1; then
  for d in "$dir/.gl" ".gl"; do
    if ls "$d"/*.deb >/dev/null 2>&1; then for f in "$d"/*.deb; do dpkg -x "$f" /; done; ldconfig; break; fi
  done
fi
H="$dir/bin/gt-harness"
read -ra state_args <<< "${state:?bench.conf has no state (prepare the folder again)}"
dev=(); [ -n "$device" ] && dev=(--device "$device")
draw() {  # draw LAYOUT ROUND: one harness run, prints its median frame ms
  local s="$dir/spv/$1" log="$out/$1-$2.log"
  "$H" "${dev[@]}" --vert "$s/vert.spv" --tesc "$s/tesc.spv" --tese "$s/tese.spv" --frag "$s/frag.spv" \
    --buffers "$dir/$1" --patches "$patches" --width "$width" --height "$height" "${state_args[@]}" \
    --frames "$frames" --warmup 5 --timestamps >"$log" 2>&1 || { cat "$log" >&2; exit 1; }
  awk '$1 == "time" && $2 == "frame_ms_median" {print $3}' "$log"
}
old_all="" new_all=""
for r in $(seq 1 "$rounds"); do
  o=$(draw old "$r"); n=$(draw new "$r")
  [ -n "$o" ] && [ -n "$n" ] || { echo "round $r: the harness printed no frame time (old '$o', new '$n')" >&2; exit 1; }
  [ "$r" = 1 ] && sed -n 's/^device name /device /p' "$out/new-1.log"
  echo "round $r old $o ms new $n ms"
  old_all="$old_all $o"; new_all="$new_all $n"
done
python3 - "$old_all" "$new_all" "$ref" "$tree" "$variant" "$old_layout" <<'PY'
import statistics, sys
old = [float(x) for x in sys.argv[1].split()]
new = [float(x) for x in sys.argv[2].split()]
mo, mn = statistics.median(old), statistics.median(new)
print(f"patch layout ({sys.argv[5]}; REF layout: {sys.argv[6]}): {sys.argv[3]} {mo:.3f} ms, {sys.argv[4]} {mn:.3f} ms, new / old {mn / mo:.3f}")
PY
