#!/usr/bin/env bash
# Quick functional benchmark with the test shaders (not the package's): tiles M at factor F vs a
# static mesh of the same triangle count; plain, range-per-frame and re-send frames.
# Usage: bench.sh HARNESS SPV_DIR WORK_DIR M F [FRAMES] [extra harness args]
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
h=$1 spv=$2 work=$3 m=$4 f=$5 frames=${6:-50}; shift 5; [ $# -gt 0 ] && shift
mkdir -p "$work"
python3 - "$work/in" "$m" "$f" <<'PY'
import os, struct, sys
d, m, f = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]); os.makedirs(d, exist_ok=True)
w = lambda n, v: open(os.path.join(d, n), "wb").write(struct.pack("<%df" % len(v), *v))
w("params.f32", [0, 0, 1, 1] + [0] * 4 + [8, 8, 0, 0] + [m, f, 1, f] + [0] * 20)
rows = [[2, 0, 0, -1], [0, 0, 2, -1], [0, 0, 0, 0.5], [0, 0, 0, 1]]
w("camera.f32", [rows[r][c] for c in range(4) for r in range(4)] + [float(r == c) for c in range(4) for r in range(4)] + [0] * 12)
w("control_points.f32", [0.0] * (80 * 64)); w("regions.f32", [0.0] * (4 * 64)); w("grid_lines.f32", [0.0] * 65)
PY
python3 "$here/make_grid_mesh.py" $((m * f)) "$work/pos.f32" "$work/idx.u32"
tris=$((2 * m * m * f * f))
common=(--buffers "$work/in" --width 1920 --height 1080 --frames "$frames" --warmup 5 --timestamps "$@")
tess=(--vert "$spv/tiles.vert.spv" --tesc "$spv/tiles.tesc.spv" --tese "$spv/tiles.tese.spv" --frag "$spv/tiles.frag.spv"
      --patches $((m * m)) --max-factor "$f")
echo "bench tiles $m factor $f triangles $tris"
run() { echo "== $1"; shift; "$h" "$@" | grep -E "^(device name|draws|time frame_ms_(median|min)|time cpu_frame_ms_median)"; }
run "tess plain" "${tess[@]}" "${common[@]}"
run "tess range_per_frame" "${tess[@]}" "${common[@]}" --update-range-per-frame
run "tess resend_bytes $((tris * 3 * 12))" "${tess[@]}" "${common[@]}" --resend-bytes $((tris * 3 * 12))
run "static mesh" --static-mesh --mesh "$work/pos.f32" "$work/idx.u32" --vert "$spv/mesh.vert.spv" --frag "$spv/mesh.frag.spv" "${common[@]}"
