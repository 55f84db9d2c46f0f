#!/usr/bin/env bash
# snow-device.sh RUN_DIR [--device SUBSTR] [--frames N]: the full snow bench from a self-contained
# folder (no glslang, no dotnet, no numpy: bash, python3 and the two prebuilt runners), so it can be
# carried to a GPU machine. For every R of RUN_DIR/snow/run.txt it runs, on the chosen device:
#   SnowFieldKernel (the terrain at the cell centres) -> SnowExposureKernel -> STEPS x SnowAccumulateKernel
#   -> the terrain drawn with GT_SNOW reading that depth map (and once without snow, the baseline)
# and prints raw lines, then the differences against the highest R:
#   device NAME
#   snow R field_ms X exposure_ms X step_ms X render_ms X           (medians of GPU timestamps)
#   bare render_ms X                                                 (same draw, snow variant off)
#   diff R depth_mean_cap X depth_max_cap X image_mean X image_px X  (against the highest R)
# depth_*_cap: |depth - highest R's depth box-averaged down| / cap; image_mean: mean |RGB| difference
# of the rendered frames in [0, 1]; image_px: fraction of pixels differing by more than 8/255.
# Logs and PNGs go to $OUT when it is set, else RUN_DIR/out; the maps (up to 64 MB at 2048) to
# $OUT/maps only without $OUT (else to a scratch folder), so a device tool's $OUT stays small.
#
# RUN_DIR layout (Tools~/rig/snow-carry.sh assembles it):
#   bin/gt-harness bin/gt-compute
#   spv/SnowFieldKernel.spv spv/SnowExposureKernel.spv spv/SnowAccumulateKernel.spv  (field: with GT_NOISE)
#   spv/snow/{vert,tesc,tese,frag}.spv   (variant noise+height_color+snow)
#   spv/bare/{vert,tesc,tese,frag}.spv   (variant noise+height_color)
#   snow/                                 (gt-cli snow-scene output: scene/, *_R.f32, run.txt)
#   pass_state_tessellated.args           the forward pass's render state as harness options
#   .gl/*.deb (optional)                  a Vulkan loader to unpack where the machine has none
set -euo pipefail
run="$(cd "${1:?usage: snow-device.sh RUN_DIR [--device SUBSTR] [--frames N]}" && pwd)"; shift
device=""; frames=20
# The rig's range check (options.py, carried beside this script).
check_number() { python3 "$(dirname "${BASH_SOURCE[0]}")/options.py" snow-device "$@" || exit 2; }
while [ $# -gt 0 ]; do
  case "$1" in
    --device) device="${2:?--device needs a name substring}"; shift ;;
    --frames) check_number "$1" frames "${2-}"; frames=$2; shift ;;
    *) echo "snow-device: unknown argument '$1'" >&2; exit 2 ;;
  esac
  shift
done
out="${OUT:-$run/out}"; mkdir -p "$out"
if [ -n "${OUT:-}" ]; then maps="$(mktemp -d)"; trap 'rm -rf "$maps"' EXIT; else maps="$out/maps"; mkdir -p "$maps"; fi
# A machine without a Vulkan loader: unpack the carried one (as the harness README says).
# Looked for in RUN_DIR/.gl, then in .gl of the current folder (a repository root with .gl carried).
if ! ldconfig -p 2>/dev/null | grep -q libvulkan.so.1; then
  for d in "$run/.gl" ".gl"; do
    if ls "$d"/*.deb >/dev/null 2>&1; then for f in "$d"/*.deb; do dpkg -x "$f" /; done; ldconfig; break; fi
  done
fi
H="$run/bin/gt-harness"; C="$run/bin/gt-compute"; S="$run/snow"; spv="$run/spv"
read -ra state < "$run/pass_state_tessellated.args" || { echo "snow-device: $run has no pass_state_tessellated.args (assemble it again with gt snow-carry)" >&2; exit 2; }
dev=(); [ -n "$device" ] && dev=(--device "$device")
val() { sed -n "s/^$1 //p" "$S/run.txt"; }
read -r -a RES <<< "$(val resolutions)"
steps=$(val steps); patches=$(val patches); read -r W Hh <<< "$(val size)"
exposure_repeat=${EXPOSURE_REPEAT:-5}
med() { sed -n "s/^time $1 //p" "$2"; }

draw() {  # draw VARIANT LOG PNG [snow args...]
  local v="$spv/$1" log="$2" png="$3"; shift 3
  "$H" "${dev[@]}" --vert "$v/vert.spv" --tesc "$v/tesc.spv" --tese "$v/tese.spv" --frag "$v/frag.spv" \
    --buffers "$S/scene" --patches "$patches" --width "$W" --height "$Hh" --png "$png" \
    --frames "$frames" --warmup 3 --timestamps "${state[@]}" "$@" >"$log" || { cat "$log"; exit 1; }
}

draw bare "$out/render_bare.log" "$out/bare.png"
sed -n 's/^device name /device /p' "$out/render_bare.log"
for r in "${RES[@]}"; do
  g=$((r / 8))
  "$C" --spv "$spv/SnowFieldKernel.spv" --entry SnowFieldKernel "${dev[@]}" --groups "$g,$g" --repeat 3 --timestamps \
    --uniform "0=$S/field_params_$r.f32" --buffer "2=$S/scene/control_points.f32" --buffer "3=$S/scene/regions.f32" \
    --buffer "4=$S/scene/grid_lines.f32" --zeros "5=$((16 * r * r))" --out "5=$maps/field_$r.f32" >"$out/field_$r.log" \
    || { cat "$out/field_$r.log"; exit 1; }
  "$C" --spv "$spv/SnowExposureKernel.spv" --entry SnowExposureKernel "${dev[@]}" --groups "$g,$g" --repeat "$exposure_repeat" \
    --timestamps --uniform "0=$S/snow_params_$r.f32" --buffer "1=$maps/field_$r.f32" --zeros "2=$((4 * r * r))" \
    --out "2=$maps/exposure_$r.f32" >"$out/exposure_$r.log" || { cat "$out/exposure_$r.log"; exit 1; }
  "$C" --spv "$spv/SnowAccumulateKernel.spv" --entry SnowAccumulateKernel "${dev[@]}" --groups "$g,$g" --repeat "$steps" \
    --timestamps --uniform "0=$S/snow_params_$r.f32" --buffer "1=$maps/field_$r.f32" --buffer "2=$maps/exposure_$r.f32" \
    --zeros "3=$((4 * r * r))" --out "3=$maps/depth_$r.f32" >"$out/step_$r.log" || { cat "$out/step_$r.log"; exit 1; }
  draw snow "$out/render_$r.log" "$out/snow_$r.png" --snow-depth "$maps/depth_$r.f32" --snow-params "$S/snow_size_$r.f32"
  echo "snow R $r field_ms $(med dispatch_ms_median "$out/field_$r.log") exposure_ms $(med dispatch_ms_median "$out/exposure_$r.log")" \
       "step_ms $(med dispatch_ms_median "$out/step_$r.log") render_ms $(med frame_ms_median "$out/render_$r.log")"
done
echo "bare render_ms $(med frame_ms_median "$out/render_bare.log")"
grep -q "^note lavapipe" "$out/render_bare.log" && echo "note lavapipe timings are functional figures, not performance"

python3 - "$out" "$maps" "$(val cap)" "${RES[@]}" <<'PY'
# Differences against the highest R, standard library only (the GPU machine may have no numpy).
import array, struct, sys, zlib
out, maps, cap, res = sys.argv[1], sys.argv[2], float(sys.argv[3]), [int(r) for r in sys.argv[4:]]
def floats(path):
    a = array.array("f"); a.frombytes(open(path, "rb").read()); return a
def rgb(path):   # the harness's PNG: 8-bit RGBA, filter 0 on every row
    d = open(path, "rb").read(); i, idat = 8, b""
    while i < len(d):
        n, kind = struct.unpack(">I4s", d[i:i + 8]); body = d[i + 8:i + 8 + n]
        if kind == b"IHDR": w, h = struct.unpack(">II", body[:8])
        if kind == b"IDAT": idat += body
        i += 12 + n
    raw = zlib.decompress(idat); stride = 4 * w + 1
    return [raw[y * stride + 1 + 4 * x + c] for y in range(h) for x in range(w) for c in range(3)]
top = max(res); ref = floats(f"{maps}/depth_{top}.f32"); ref_img = rgb(f"{out}/snow_{top}.png")
for r in res:
    d = floats(f"{maps}/depth_{r}.f32"); f = top // r
    tot = mx = 0.0
    for j in range(r):
        for i in range(r):
            s = 0.0
            for b in range(f):
                row = (j * f + b) * top + i * f
                s += sum(ref[row:row + f])
            e = abs(d[j * r + i] - s / (f * f)) / cap
            tot += e; mx = max(mx, e)
    img = rgb(f"{out}/snow_{r}.png")
    diffs = [abs(a - b) for a, b in zip(img, ref_img)]
    px = sum(1 for k in range(0, len(diffs), 3) if max(diffs[k:k + 3]) > 8) / (len(diffs) // 3)
    print(f"diff R {r} depth_mean_cap {tot / (r * r):.5f} depth_max_cap {mx:.4f} image_mean {sum(diffs) / len(diffs) / 255:.5f} image_px {px:.4f}")
PY
