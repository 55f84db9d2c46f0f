# gt snow-bench [--quick] [--device SUBSTR]: snow cost and accuracy against the snow-map resolution
# (the paper's Table 2 sweeps 512/1024/2048), on the real pipeline: for R = 256, 512, 1024, 2048
# (--quick: 128, 256, 512 with 40 steps of 0.25 s, for lavapipe) the terrain field kernel, the
# exposure pass, one accumulation step (medians of GPU timestamps), the terrain drawn with GT_SNOW
# reading the resulting map (frame time, and once without snow), and the depth and image
# differences against the highest R. Assembles $BUILD_DIR/snow-run with `gt snow-carry` and runs
# Tools~/rig/snow-device.sh on it; see that script for the output lines.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
quick=0; device=()
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) quick=1 ;;
    --device) device=(--device "${2:?--device needs a name substring}"); shift ;;
    *) die "snow-bench: unknown argument '$1' (use --quick, --device SUBSTR)" ;;
  esac
  shift
done
run="$BUILD_DIR/snow-run"
if [ $quick = 1 ]; then bash "$RIG_DIR/snow-carry.sh" "$run" --resolutions 128,256,512 --steps 40 --dt 0.25
else bash "$RIG_DIR/snow-carry.sh" "$run"; fi
EXPOSURE_REPEAT=$([ $quick = 1 ] && echo 2 || echo 5) OUT="$run/out" bash "$run/snow-device.sh" "$run" "${device[@]}" \
  --frames "$([ $quick = 1 ] && echo 3 || echo 10)"
