# gt snow-bench [--quick] [--device SUBSTR]: the snow simulation's cost and accuracy against the
# snow-map resolution (the paper's Table 2 sweeps 512/1024/2048). For R = 256, 512, 1024, 2048
# (--quick: 128, 256, 512, for lavapipe) it runs Shaders/SnowSimulation.compute with gt-compute
# on one synthetic terrain, prints the GPU time per exposure pass and per accumulation step (median of
# timestamp queries), and the depth difference after the same simulated time against the highest R
# (the reference box-averaged down to each R), in units of the depth cap.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

quick=0; device=""
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) quick=1 ;;
    --device) device="${2:?--device needs a name substring}"; shift ;;
    *) die "snow-bench: unknown argument '$1' (use --quick, --device SUBSTR)" ;;
  esac
  shift
done
# Every R runs STEPS steps of DT seconds: 10 s of snowfall, the same simulated time at every R.
if [ $quick = 1 ]; then RES=(128 256 512); STEPS=40; DT=0.25; EXPOSURE_REPEAT=3
else RES=(256 512 1024 2048); STEPS=200; DT=0.05; EXPOSURE_REPEAT=10; fi

runner="$BUILD_DIR/computerig/gt-compute"
if [ ! -x "$runner" ]; then
  command -v cmake >/dev/null || die "no gt-compute at $runner and no cmake to build it"
  say "building gt-compute"
  cmake -S "$TOOLS_DIR/computerig" -B "$BUILD_DIR/computerig" -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$BUILD_DIR/computerig" -j "$(nproc)" >/dev/null
fi
# A python with numpy (the distribution's, if the one on PATH has none).
PY=""
for p in python3 /usr/bin/python3; do "$p" -c "import numpy" 2>/dev/null && { PY="$p"; break; }; done
[ -n "$PY" ] || die "snow-bench needs python3 with numpy (run gt setup)"

work="$BUILD_DIR/snow-bench"; rm -rf "$work"; mkdir -p "$work"
for k in SnowExposureKernel SnowAccumulateKernel; do
  if [ -n "${GT_SNOW_SPV_DIR:-}" ]; then
    # A machine without glslang (a carried GPU box): SPIR-V compiled elsewhere from the same source.
    cp "$GT_SNOW_SPV_DIR/$k.spv" "$work/$k.spv" || die "no $k.spv in GT_SNOW_SPV_DIR"
    continue
  fi
  glslangValidator -D -V -S comp -e "$k" -o "$work/$k.spv" "$PKG_DIR/Shaders/SnowSimulation.compute" >/dev/null \
    || die "glslang failed on $k"
  spirv-val "$work/$k.spv"
done
dev=(); [ -n "$device" ] && dev=(--device "$device")

median_of() { sed -n 's/^time dispatch_ms_median //p' "$1"; }
for r in "${RES[@]}"; do
  "$PY" - "$work" "$r" "$DT" <<'PY'
# Synthetic terrain (a diagonal ridge, a steep block and ripples) with exact normals, and SnowParams.
# The packing mirrors SnowSettings.PackParams (Runtime/Core/SnowSettings.cs): keep them in step.
import sys, numpy as np
work, r, dt = sys.argv[1], int(sys.argv[2]), float(sys.argv[3])
c = (np.arange(r) + 0.5) / r
x, y = np.meshgrid(c, c)                      # [j, i]: row j is y, column i is x
d = (x - 0.5) + 0.3 * (y - 0.5)
g = np.exp(-d * d / (2 * 0.05 ** 2))
bump = 0.004 * np.sin(40 * x) * np.cos(37 * y)
block = 0.08 / (1 + np.exp(-(0.03 - np.maximum(abs(x - 0.25), abs(y - 0.7))) / 0.004))
h = 0.12 * g + bump + block
hx = -d / 0.05 ** 2 * 0.12 * g + 0.004 * 40 * np.cos(40 * x) * np.cos(37 * y)
hy = 0.3 * (-d / 0.05 ** 2 * 0.12 * g) - 0.004 * 37 * np.sin(40 * x) * np.sin(37 * y)
s = block * (1 - block / 0.08) / 0.004        # derivative of the logistic block, by its argument
ax, ay = abs(x - 0.25), abs(y - 0.7)
hx = hx + np.where(ax >= ay, -np.sign(x - 0.25) * s, 0)
hy = hy + np.where(ay > ax, -np.sign(y - 0.7) * s, 0)
n = np.stack([-hx, -hy, np.ones_like(h)], -1)
n /= np.linalg.norm(n, axis=-1, keepdims=True)
np.concatenate([n, h[..., None]], -1).astype(np.float32).tofile(f"{work}/field_{r}.bin")
wind, fall = np.array([1.6, 0.7]), 1.0
v = np.array([wind[0], wind[1], -fall]); hs = np.hypot(v[0], v[1]); sp = np.linalg.norm(v)
params = [r, 1 / r, 0.3, 32,  -v[0] / hs, -v[1] / hs, hs / sp, -v[2] / sp,  0, 0, 1, 0.002,
          1.0, 0.5, 0.1, 0,  dt, 0.02, 0.0002, 0]
np.array(params, np.float32).tofile(f"{work}/params_{r}.bin")
PY
  g=$((r / 8)); bytes=$((4 * r * r))
  "$runner" --spv "$work/SnowExposureKernel.spv" --entry SnowExposureKernel "${dev[@]}" --groups "$g,$g" \
    --repeat "$EXPOSURE_REPEAT" --timestamps --uniform "0=$work/params_$r.bin" --buffer "1=$work/field_$r.bin" \
    --zeros "2=$bytes" --out "2=$work/exposure_$r.bin" >"$work/exposure_$r.log" || { cat "$work/exposure_$r.log"; die "exposure run failed at R $r"; }
  "$runner" --spv "$work/SnowAccumulateKernel.spv" --entry SnowAccumulateKernel "${dev[@]}" --groups "$g,$g" \
    --repeat "$STEPS" --timestamps --uniform "0=$work/params_$r.bin" --buffer "1=$work/field_$r.bin" \
    --buffer "2=$work/exposure_$r.bin" --zeros "3=$bytes" --out "3=$work/depth_$r.bin" >"$work/accumulate_$r.log" \
    || { cat "$work/accumulate_$r.log"; die "accumulate run failed at R $r"; }
  echo "$r $(median_of "$work/exposure_$r.log") $(median_of "$work/accumulate_$r.log")" >>"$work/times.txt"
done

say "device: $(sed -n 's/^device //p' "$work/exposure_${RES[0]}.log")"
"$PY" - "$work" "$STEPS" "$DT" <<'PY'
import sys, numpy as np
work, steps, dt = sys.argv[1], int(sys.argv[2]), float(sys.argv[3])
rows = [l.split() for l in open(f"{work}/times.txt")]
res = [int(r[0]) for r in rows]
ref_r = max(res)
ref = np.fromfile(f"{work}/depth_{ref_r}.bin", np.float32).reshape(ref_r, ref_r)
cap = 0.02
print(f"snow-bench: {steps} steps of {dt} s ({steps * dt:g} s simulated); depth differences against R {ref_r}, in units of the cap")
print(f"{'R':>6} {'exposure_ms':>12} {'step_ms':>10} {'mean|dD|/cap':>13} {'max|dD|/cap':>12} {'cover>cap/2':>11}")
for r, (_, e_ms, a_ms) in zip(res, rows):
    dep = np.fromfile(f"{work}/depth_{r}.bin", np.float32).reshape(r, r)
    f = ref_r // r
    down = ref.reshape(r, f, r, f).mean(axis=(1, 3))   # box-average the reference to this R
    diff = np.abs(dep - down) / cap
    print(f"{r:>6} {float(e_ms):>12.3f} {float(a_ms):>10.3f} {diff.mean():>13.5f} {diff.max():>12.4f} {(dep > 0.5 * cap).mean():>11.3f}")
PY
