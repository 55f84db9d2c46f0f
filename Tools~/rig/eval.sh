# gt eval: position and normal of the terrain at global points, from Core's float path (what the
# shaders compute, Runtime/Core/Terrain/TerrainVertex.cs), Core's double reference, and with --gpu the GPU
# itself (one harness draw per point: a 1 x 1 tile at factor 1 whose corner is exactly the point,
# read back through GT_READBACK), side by side with the differences.
#   gt eval [--grid FILE] (--points "x,y;x,y;..." | --points-file FILE) [--gpu [--device SUBSTR]]
#           [--no-noise] [--noise a,f,alpha,beta] [--octaves N] [--span W]
# Without --grid it uses the demo's 5x5 sample grid (built on first use).
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
cli="$BUILD_DIR/gt-cli/gt-cli"
[ -x "$cli" ] || bash "$RIG_DIR/setup.sh"
args=() grid="" gpu=0
while [ $# -gt 0 ]; do
  case "$1" in
    --grid) grid="$2"; shift ;;
    --gpu) gpu=1; args+=(--gpu) ;;
    *) args+=("$1") ;;
  esac
  shift
done
if [ -z "$grid" ]; then
  grid="$BUILD_DIR/demo/grid.json"
  [ -f "$grid" ] || "$cli" demo-grid --out "$grid" >&2
fi
if [ "$gpu" = 1 ]; then
  # The two readback variants, in their own build folder (gt shaders empties the one it writes).
  spirv="$BUILD_DIR/eval/spirv"
  # With their range-origin variants (GT_RANGE_ORIGIN): a narrow span draws relative to an origin.
  if [ ! -f "$spirv/readback/tese.spv" ] || [ ! -f "$spirv/readback+noise+range_origin/tese.spv" ] \
     || [ -n "$(find "$PKG_DIR/Shaders" -name '*.hlsl' -newer "$spirv/readback+noise+range_origin/tese.spv")" ]; then
    GT_BUILD_DIR="$BUILD_DIR/eval" bash "$RIG_DIR/shaders.sh" --only readback --only readback+noise \
      --only readback+range_origin --only readback+noise+range_origin \
      >"$BUILD_DIR/eval-shaders.log" 2>&1 || { cat "$BUILD_DIR/eval-shaders.log" >&2; die "compiling the readback shaders failed"; }
  fi
  write_pass_states "$BUILD_DIR/eval"
  args+=(--harness "$BUILD_DIR/harness/gt-harness" --spirv "$spirv" --pass-state "$BUILD_DIR/eval/pass_state_tessellated.args")
fi
exec "$cli" eval --grid "$grid" "${args[@]}"
