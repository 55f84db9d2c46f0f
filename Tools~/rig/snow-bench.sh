# gt snow-bench [--quick] [--docs] [--device SUBSTR]: snow cost and accuracy against the snow-map resolution
# (the paper's Table 2 sweeps 512/1024/2048), on the real pipeline: for R = 256, 512, 1024, 2048
# (--quick: 128, 256, 512 with 40 steps of 0.25 s, for lavapipe) the terrain field kernel, the
# exposure pass, one accumulation step (medians of GPU timestamps), the terrain drawn with GT_SNOW
# reading the resulting map (frame time, and once without snow), and the depth and image
# differences against the highest R. Assembles $BUILD_DIR/snow-run with `gt snow-carry` and runs
# Tools~/rig/snow-device.sh on it; see that script for the output lines. --docs renders 480 x 360
# frames (the manual ships them: small indexed PNGs, png_palette.py) and writes the highest R's frame
# to Documentation~/images/snow_ridge.png (the bare frame stays in $BUILD_DIR/snow-run/out); its
# timings are then not the manual's (640 x 480).
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
quick=0; docs=0; device=()
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) quick=1 ;;
    --docs) docs=1 ;;
    --device) device=(--device "${2:?--device needs a name substring}"); shift ;;
    *) die "snow-bench: unknown argument '$1' (use --quick, --docs, --device SUBSTR)" ;;
  esac
  shift
done
run="$BUILD_DIR/snow-run"
size=$([ $docs = 1 ] && echo 480x360 || echo 640x480)
if [ $quick = 1 ]; then bash "$RIG_DIR/snow-carry.sh" "$run" --resolutions 128,256,512 --steps 40 --dt 0.25 --size "$size"
else bash "$RIG_DIR/snow-carry.sh" "$run" --size "$size"; fi
EXPOSURE_REPEAT=$([ $quick = 1 ] && echo 2 || echo 5) OUT="$run/out" bash "$run/snow-device.sh" "$run" "${device[@]}" \
  --frames "$([ $quick = 1 ] && echo 3 || echo 10)"
if [ $docs = 1 ]; then
  top=$(sed -n 's/^resolutions //p' "$run/snow/run.txt" | tr ' ' '\n' | sort -n | tail -1)
  # 32 colours: fine-grained snow compresses poorly, and at 32 it looks the same as at 64, 9 KB smaller
  python3 "$RIG_DIR/png_palette.py" "$run/out/snow_$top.png" "$PKG_DIR/Documentation~/images/snow_ridge.png" 16
  say "wrote Documentation~/images/snow_ridge.png (R $top)"
fi
