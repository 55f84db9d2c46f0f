# gt fit-bench: the shipped heightmap fit (least squares over G1 Gregory nets) side by side with the
# previous one (least squares over C1 splines) and the pre-issue-27 interpolating fitter
# (Tools~/dotnet/Gt/Legacy), one process per fit so each peak memory is its own.
#   gt fit-bench [--dem FILE.hgt] [--patches "16 64 256"] [--sizes "257 1025 4097 8193"]
#                [--scale-patches "32 128 256"] [--legacy-sizes "1025 4097"] [--skip-dem] [--skip-scale] [--reference]
# --reference: also, per patch count, the best band-limited (DCT) and C1-spline approximations with the
# Gregory net's unknown count (and 9/7, 2, 4 times it) against the bilinear baseline (gt-cli fit-reference).
# "gregory-net" is the shipped fit (max held to the baseline's), "gregory-ls" its least-squares optimum alone.
# Columns: fitter, samples, patches a side, max (m), RMS (m), max and RMS in % of relief, largest
# normal angle across shared edges (deg; DEM only, z over the tile width), wall and CPU seconds, extra peak MiB,
# extra bytes per sample, CG iterations (Gregory net only). Prints the growth exponent of CPU time in
# samples per fitter and patch count at the end.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
dem="$PKG_DIR/../shared/dem/N48E009.hgt" patches="16 64 256" sizes="257 1025 4097 8193"
scale_patches="32 128 256" legacy_sizes="1025 4097" skip_dem=0 skip_scale=0 reference=0
while [ $# -gt 0 ]; do
  case "$1" in
    --dem) dem="$2"; shift ;;
    --patches) check_number fit-bench "$1" patches,... "${2-}"; patches="$2"; shift ;;
    --sizes) check_number fit-bench "$1" samples,... "${2-}"; sizes="$2"; shift ;;
    --scale-patches) check_number fit-bench "$1" patches,... "${2-}"; scale_patches="$2"; shift ;;
    --legacy-sizes) check_number fit-bench "$1" samples,... "${2-}"; legacy_sizes="$2"; shift ;;
    --skip-dem) skip_dem=1 ;;
    --skip-scale) skip_scale=1 ;;
    --reference) reference=1 ;;
    *) usage_error fit-bench "unknown option '$1'" ;;
  esac
  shift
done
say "building gt-cli"
dotnet build "$TOOLS_DIR/dotnet/Gt/Gt.csproj" -c Release -v quiet -nologo -o "$BUILD_DIR/gt-cli" >/dev/null
cli="$BUILD_DIR/gt-cli/gt-cli"
printf 'fitter\tsamples\tpatches\tmax_m\trms_m\tmax_pct\trms_pct\tg1_deg\tseconds\tcpu_seconds\tpeak_mib\tbytes_per_sample\tcg_iterations\tbaseline_max_m\tbaseline_rms_m\tmax_ratio\trms_ratio\treweight_rounds\n'
if [ "$skip_dem" = 0 ]; then
  [ -f "$dem" ] || die "fit-bench: $dem not found (give --dem FILE.hgt)"
  for p in $patches; do
    "$cli" fit-bench --dem "$dem" --patches "$p"
    "$cli" fit-bench --dem "$dem" --patches "$p" --ls
    "$cli" fit-bench --dem "$dem" --patches "$p" --c1
    "$cli" fit-bench --dem "$dem" --patches "$p" --legacy
  done
fi
if [ "$reference" = 1 ]; then
  for p in $patches; do "$cli" fit-reference --dem "$dem" --patches "$p"; done
fi
if [ "$skip_scale" = 0 ]; then
  out="$(mktemp)"
  for p in $scale_patches; do
    for n in $sizes; do
      "$cli" fit-bench --size "$n" --patches "$p" | tee -a "$out"
      "$cli" fit-bench --size "$n" --patches "$p" --c1 | tee -a "$out"
    done
  done
  for n in $legacy_sizes; do "$cli" fit-bench --size "$n" --patches 256 --legacy; done
  # Growth exponent: slope of log(CPU seconds) over log(samples) between the two largest sizes, per fitter and patch count.
  python3 - "$out" <<'PY'
import math, sys
rows = [l.split('\t') for l in open(sys.argv[1]) if l.strip()]
by = {}
for r in rows:
    n = int(r[1].split('x')[0]); by.setdefault((r[0], int(r[2])), []).append((n * n, float(r[9]), float(r[10])))
for (f, p), v in sorted(by.items()):
    v.sort()
    if len(v) >= 2 and v[-2][1] > 0:
        (s0, t0, _), (s1, t1, _) = v[-2], v[-1]
        print(f"growth, {f} at {p} patches: CPU time ~ samples^{math.log(t1 / t0) / math.log(s1 / s0):.2f} ({s0} -> {s1} samples)")
PY
  rm -f "$out"
fi
