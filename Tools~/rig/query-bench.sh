# gt query-bench: CPU height, normal and ray queries per second on 1 and N threads, and the terrain
# collider patch's sampling time and deviation from the full-detail surface (a benchmark: it prints).
#   gt query-bench [--grid FILE] [--size METRES] [--threads N] [--seconds S] [--octaves N]
#                  [--noise a,f,alpha,beta | --no-noise] [--collider-samples N] [--collider-spacing METRES]
# Without --grid it uses the demo's 5x5 sample grid (built on first use).
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
cli="$BUILD_DIR/gt-cli/gt-cli"
[ -x "$cli" ] || bash "$RIG_DIR/setup.sh"
args=() grid=""
while [ $# -gt 0 ]; do
  case "$1" in
    --grid) grid="$2"; shift ;;
    *) args+=("$1") ;;
  esac
  shift
done
if [ -z "$grid" ]; then
  grid="$BUILD_DIR/demo/grid.json"
  [ -f "$grid" ] || "$cli" demo-grid --out "$grid" >&2
fi
exec "$cli" query-bench --grid "$grid" "${args[@]}"
