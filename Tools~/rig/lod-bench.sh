# gt lod-bench [--device SUBSTR] [--frames N] [--png FILE] [gt-cli lod-scene options...]: the levels of
# detail (GT_LOD, internals.md "Levels of detail") at ground level. Defaults: a 100 km terrain (the
# demo grid), the camera 2 m above the surface looking ahead, M = 16 tiles a level, adaptive factors
# at a 1 px target, the continuous octave rule at 2 px segments, 1920 x 1080. Compiles the lod+noise
# variant, writes the scene with `gt-cli lod-scene` into $BUILD_DIR/lod-run, draws it with the harness
# and prints, one per line: "lod levels L", "lod patches N" (L x M^2 tiles in one draw), "lod triangles
# T" (clipping invocations: triangles the tessellator made that reached the clipper), "lod
# triangles_drawn T" (clipping primitives: those left after clipping), "lod tess_evaluations E", and
# with --frames the harness's "time ..." lines (GPU frame times; lavapipe's are functional only).
# --error: draws the view once more with GT_FACTOR_READBACK and prints gt-cli's "lod_error ..." line
# (LodError.cs: largest and RMS screen error against the double full-detail surface).
# --per-level: with --error, one "lod level k triangles T max_px X rms_px Y ..." line per level instead
# (LodError.MeasureLevels: each level's triangles and screen error, the other levels left out).
# --no-origin: the levels without a range origin (the plain absolute path, for comparison).
# --no-plain: every vertex on the precise path (the levels' plain path off, for comparison).
# Measures only: no bound is asserted here (LodGpuTests asserts the seams, the camera step, the error).
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
device=(); frames=1; png=(); scene=(); error=0; levels_error=()
while [ $# -gt 0 ]; do
  case "$1" in
    --device) device=(--device "${2:?--device needs a name substring}"); shift ;;
    --frames) check_number lod-bench "$1" frames "${2-}"; frames=$2; shift ;;
    --png) png=(--png "${2:?--png needs a file}"); shift ;;
    --error) error=1; shift; continue ;;
    --per-level) levels_error=(--per-level); shift; continue ;;
    --no-origin) scene+=(--no-origin); shift; continue ;;
    --no-plain) scene+=(--no-plain); shift; continue ;;
    --*) scene+=("$1" "${2:?$1 needs a value}"); shift ;;
    *) usage_error lod-bench "unknown argument '$1'" ;;
  esac
  shift
done
harness="$BUILD_DIR/harness/gt-harness"
cli="$BUILD_DIR/gt-cli/gt-cli"
[ -x "$harness" ] && [ -x "$cli" ] || die "harness or gt-cli not built (run: gt setup)"
run="$BUILD_DIR/lod-run"
rm -rf "$run"; mkdir -p "$run"
# The scene first: gt-cli checks the scene options before the shaders compile.
"$cli" lod-scene --out "$run" "${scene[@]}" > "$run/scene.txt"
variants=(--only lod+noise); [ "$error" = 1 ] && variants+=(--only factor_readback+lod+noise)
bash "$RIG_DIR/shaders.sh" "${variants[@]}" >/dev/null || die "the ${variants[*]} variants do not compile (gt shaders ${variants[*]})"
spv="$BUILD_DIR/spirv/lod+noise"
levels=$(awk '$1 == "levels" { print $2 }' "$run/scene.txt")
patches=$(awk '$1 == "patches" { print $2 }' "$run/scene.txt")
width=1920; height=1080
for ((i = 0; i < ${#scene[@]}; i++)); do
  [ "${scene[i]}" = --width ] && width="${scene[i+1]}"
  [ "${scene[i]}" = --height ] && height="${scene[i+1]}"
done
timing=(); [ "$frames" -gt 1 ] && timing=(--frames "$frames" --warmup 2 --timestamps)
pass_state_args state tessellated   # the forward pass's Cull/ZTest/...; RigCamera draws reversed depth, the harness's default
"$harness" --vert "$spv/vert.spv" --tesc "$spv/tesc.spv" --tese "$spv/tese.spv" --frag "$spv/frag.spv" \
  --buffers "$run" --params-tail "$run/lod_tail.f32" --patches "$patches" --storage "7:$((64 * patches))" --storage 8:16 --width "$width" --height "$height" "${state[@]}" \
  --stats "${timing[@]}" "${png[@]}" "${device[@]}" > "$run/harness.txt"
stat() { awk -v k="$1" '$1 == "stat" && $2 == k { print $3 }' "$run/harness.txt"; }
echo "lod levels $levels"
echo "lod patches $patches"
echo "lod level0_m $(awk '$1 == "level0_m" { print $2 }' "$run/scene.txt")"
echo "lod triangles $(stat clipping_invocations)"
echo "lod triangles_drawn $(stat clipping_primitives)"
echo "lod tess_evaluations $(stat tessellation_evaluation_shader_invocations)"
grep '^time ' "$run/harness.txt" || true
if [ "$error" = 1 ]; then
  fr="$BUILD_DIR/spirv/factor_readback+lod+noise"
  "$harness" --vert "$fr/vert.spv" --tesc "$fr/tesc.spv" --tese "$fr/tese.spv" --frag "$fr/frag.spv" \
    --buffers "$run" --params-tail "$run/lod_tail.f32" --patches "$patches" --storage "7:$((64 * patches))" --storage 8:16 --width "$width" --height "$height" "${state[@]}" \
    --readback "$run/factors.f32" --readback-floats $((8 * patches)) "${device[@]}" > "$run/harness-factors.txt" \
    || die "factor readback draw failed ($run/harness-factors.txt)"
  [ -n "${GT_LOD_SKIP_ERROR:-}" ] || "$cli" lod-scene --out "$run/error-scene" "${scene[@]}" --factors "$run/factors.f32" "${levels_error[@]}" \
    | grep -E '^lod_(error|level) ' | sed -e 's/^lod_error /lod error /' -e 's/^lod_level /lod level /'
fi
