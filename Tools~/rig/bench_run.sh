#!/usr/bin/env bash
# Runs the jobs of a gt bench plan (gt-cli bench-plan) with the harness; needs only bash, python3
# and the harness, so it also runs on the NVIDIA machine (no dotnet there).
#   bench_run.sh PLAN_DIR HARNESS SPV_DIR OUT_DIR [harness args for every job, e.g. --device NVIDIA]
# Writes OUT_DIR/results.txt ("== ID KIND" then the harness's lines, "exit N"), OUT_DIR/readback.tar
# (the factor readbacks) and OUT_DIR/device.txt. Static meshes are made by make_grid_mesh.py
# (Tools~/harness/test, or beside this script) with as many triangles as the job they match.
# static-bake jobs capture the terrain's vertices (GT_READBACK) and pack them with
# bench_static_mesh.py into OUT_DIR/static/REF for the fair static mesh's run (vert_static);
# the captures and packed meshes are deleted at the end (hundreds of MB at 8M triangles).
# floor-match jobs draw the tessellator's floor at the triangle count job REF drew: PLAN_DIR/jobs/levels_floor
# (a uniform tile grid) copied to OUT_DIR/floor/ID with M x M tiles at odd F, 2 (M F)^2 nearest the count
# (TerrainParams' _Tess = (M, F, target, F)); @FLOOR@ in ARGS names that folder plus --patches M^2.
# A job naming an option this harness's --help does not list (e.g. the vertex cache's --compute-once
# on a harness without it) is not run: "skipped: this harness has no OPTION" instead of its output.
# Every job draws with the render state of the shader's forward pass, PLAN_DIR/pass_state_tessellated.args
# for jobs with --tesc, else pass_state_fallback.args (written by bench.sh's make_plan).
set -uo pipefail
plan=$1 harness=$2 spv=$3 out=$4; shift 4
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
mesher="$here/make_grid_mesh.py"; [ -f "$mesher" ] || mesher="$here/../harness/test/make_grid_mesh.py"
mkdir -p "$out/readback" "$out/mesh" "$out/capture" "$out/static" "$out/floor"
res="$out/results.txt"; : > "$res"
"$harness" --list-devices "$@" > "$out/device.txt" 2>&1 || true
usage=$("$harness" --help 2>&1 || true)
missing_option() {  # prints the first --option of "$1" that the harness's usage does not list
  local w
  for w in $1; do
    case "$w" in
      --*) grep -qE -- "(^|[[:space:]/])${w}([[:space:]/]|$)" <<< "$usage" || { printf '%s' "$w"; return; } ;;
    esac
  done
}
for draw in tessellated fallback; do
  [ -f "$plan/pass_state_$draw.args" ] || { echo "bench_run: $plan has no pass_state_$draw.args (make the plan again)" >&2; exit 2; }
done
read -ra state_tessellated < "$plan/pass_state_tessellated.args"
read -ra state_fallback < "$plan/pass_state_fallback.args"
start=$(date +%s)
n=0
while IFS=$'\t' read -r id kind ref args; do
  [ -z "$id" ] && continue
  n=$((n + 1))
  if [ "$kind" = static-match ]; then
    tris=$(awk -v r="== $ref run" '$0 == r {f = 1; next} /^== / {f = 0} f && $1 == "stat" && $2 == "clipping_invocations" {print $3; exit}' "$res")
    [ -z "$tris" ] && { printf '== %s %s\nskipped: no triangle count for %s\n' "$id" "$kind" "$ref" >> "$res"; continue; }
    cells=$(python3 -c "import math; print(max(1, round(math.sqrt($tris / 2))))")
    [ -f "$out/mesh/$cells.u32" ] || python3 "$mesher" "$cells" "$out/mesh/$cells.f32" "$out/mesh/$cells.u32" > /dev/null
    args=${args//@MESH@/"$out/mesh/$cells.f32 $out/mesh/$cells.u32"}
  fi
  if [ "$kind" = floor-match ]; then
    tris=$(awk -v r="== $ref run" '$0 == r {f = 1; next} /^== / {f = 0} f && $1 == "stat" && $2 == "clipping_invocations" {print $3; exit}' "$res")
    [ -z "$tris" ] && { printf '== %s %s\nskipped: no triangle count for %s\n' "$id" "$kind" "$ref" >> "$res"; continue; }
    rm -rf "$out/floor/$id"; cp -r "$plan/jobs/levels_floor" "$out/floor/$id"
    tiles=$(python3 - "$tris" "$out/floor/$id/params.f32" <<'PY'
import struct, sys
t = int(sys.argv[1])
m, f = min(((m, f) for m in range(4, 65) for f in range(1, 64, 2)), key=lambda p: (abs(2 * (p[0] * p[1]) ** 2 - t), abs(p[0] - 32)))
with open(sys.argv[2], "r+b") as p:
    p.seek(12 * 4); p.write(struct.pack("<4f", m, f, 1.0, f))
print(m * m, m, f, 2 * (m * f) ** 2)
PY
)
    read -r patches fm ff ftris <<< "$tiles"
    args=${args//@FLOOR@/"$out/floor/$id --patches $patches"}
    printf '== %s %s\nfloor tiles %s factor %s triangles %s of %s\n' "$id" "$kind" "$fm" "$ff" "$ftris" "$tris" >> "$res"
  else
    printf '== %s %s\n' "$id" "$kind" >> "$res"
  fi
  args=${args//@SPV@/$spv}; args=${args//@JOB@/$plan/jobs}; args=${args//@OUT@/$out}
  miss=$(missing_option "$args")
  if [ -n "$miss" ]; then printf 'skipped: this harness has no %s\n' "$miss" >> "$res"; continue; fi
  state=("${state_fallback[@]}"); [[ " $args " == *" --tesc "* ]] && state=("${state_tessellated[@]}")
  # shellcheck disable=SC2086
  "$harness" "${state[@]}" $args "$@" >> "$res" 2>&1
  rc=$?
  if [ "$kind" = static-bake ] && [ $rc -eq 0 ]; then
    python3 "$here/bench_static_mesh.py" "$out/capture/$ref.f32" "$plan/jobs/$ref" "$out/static/$ref" >> "$res" 2>&1
    rc=$?
    rm -f "$out/capture/$ref.f32"
  fi
  echo "exit $rc" >> "$res"
done < "$plan/plan.tsv"
rm -rf "$out/mesh" "$out/capture" "$out/static" "$out/floor"
[ -d "$out/readback" ] && (cd "$out" && tar cf readback.tar readback && rm -rf readback)
echo "bench_run: $n jobs in $(( $(date +%s) - start )) s -> $out" | tee -a "$res"
