# gt demo: the README's first command. Sets up the rig, builds the 5x5 sample grid, compiles the
# noise + height colour shaders, and renders the grid through the package's shaders with the
# harness at the paper's ranges g = h = 1.0, 0.5, 0.2, 0.1, 0.02 (c = d = 0), each range filling
# the same view (the paper's zoom view). Prints vertices and triangles per range (pipeline
# statistics: tessellation evaluation invocations and clipping invocations, the triangles entering the clipper).
#   gt demo [--docs] [--dem | --tiled] [--no-setup] [--device SUBSTR] [--tiles M] [--factor F] [--width W] [--height H]
# Writes .build/demo/demo_g<g>.png; with --docs also Documentation~/images/demo_g1.0.png and, for
# g < 1, Tools~/images/demo_g<g>.png (only the development page shows those: not packed; half size,
# the thumbnails of its row of five). Small indexed PNGs, png_palette.py.
# --dem: instead, the real-data crop of the tests (Tools~/RigTests/Data/dem/N48E009_east.hgt, SRTM3, 241 x 241
# samples, 14.7 km across) fitted with 32 x 32 patches, heights x 3, rendered whole at g = h = 1 without
# noise: .build/demo/demo_dem.png (with --docs also Documentation~/images/demo_dem.png).
# --tiled: instead, the sample grid whole with fine noise (6 octaves from 64 cells across, so the
# finer ones span more than the table's 256 cells), hashed (noise+height_color) and tiled
# (GT_NOISE_TABLE, its table bound at 9): .build/demo/noise_hashed.png and noise_tiled.png (with
# --docs half size in Documentation~/images/, the manual's "Tiled noise" pair).
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
# 400 x 300: the manual ships these pictures, so they stay small (about 30 KB; the half-size ones 10 KB).
docs=0 dem=0 tiled=0 setup=1 device="" tiles=16 factor=15 width=400 height=300
while [ $# -gt 0 ]; do
  case "$1" in
    --docs) docs=1 ;;
    --dem) dem=1 ;;
    --tiled) tiled=1 ;;
    --no-setup) setup=0 ;;
    --device) device="$2"; shift ;;
    --tiles) check_number demo "$1" tiles "${2-}"; tiles="$2"; shift ;;
    --factor) check_number demo "$1" factor "${2-}"; factor="$2"; shift ;;
    --width) check_number demo "$1" pixels "${2-}"; width="$2"; shift ;;
    --height) check_number demo "$1" pixels "${2-}"; height="$2"; shift ;;
    *) usage_error demo "unknown option '$1' (see the header of $0)" ;;
  esac
  shift
done
[ "$setup" = 1 ] && bash "$RIG_DIR/setup.sh"
cli="$BUILD_DIR/gt-cli/gt-cli"
harness="$BUILD_DIR/harness/gt-harness"
[ -x "$cli" ] || die "$cli is missing (run: gt setup)"
[ -x "$harness" ] || die "$harness is missing (run: gt setup)"
out="$BUILD_DIR/demo"
mkdir -p "$out"

if [ "$dem" = 1 ]; then
  "$cli" demo-grid --dem "$PKG_DIR/Tools~/RigTests/Data/dem/N48E009_east.hgt" --columns 32 --rows 32 --exaggerate 3 --out "$out/dem_grid.json" >&2
else
  "$cli" demo-grid --out "$out/grid.json" >&2
fi
variant="noise+height_color"
# Its own build folder: gt shaders empties the spirv folder it writes.
GT_BUILD_DIR="$out/shaders" bash "$RIG_DIR/shaders.sh" --only "$variant" >"$out/shaders.log" 2>&1 \
  || { cat "$out/shaders.log" >&2; die "compiling $variant failed"; }
spv="$out/shaders/spirv/$variant"
dev=(); [ -n "$device" ] && dev=(--device "$device")
# The forward pass's render state (Cull Back: the terrain draws its front faces only, as in Unity).
pass_state_args state tessellated

# The factor is odd: shipped shaders partition fractional_odd, which rounds an even factor up.
# Noise: 8 octaves, so that the narrow ranges show detail the wide ones cannot (the octave count
# follows the range width); a gentle light from the side-front.
if [ "$tiled" = 1 ]; then
  dir="$out/buffers_tiled"
  # Many vertices, so the octave rule keeps the fine octaves that wrap the table.
  "$cli" pack --grid "$out/grid.json" --range "0,0,1,1" --tiles 32 --factor 31 \
    --noise 0.003,64,2,1.6 --octaves 6 --width "$width" --height "$height" --out "$dir" --noise-table >/dev/null
  GT_BUILD_DIR="$out/shaders_tiled" bash "$RIG_DIR/shaders.sh" --only noise+height_color+noise_table >"$out/shaders_tiled.log" 2>&1 \
    || { cat "$out/shaders_tiled.log" >&2; die "compiling noise+height_color+noise_table failed"; }
  for kind in hashed tiled; do
    s="$spv"; table=()
    [ "$kind" = tiled ] && { s="$out/shaders_tiled/spirv/noise+height_color+noise_table"; table=(--storage-data "9:$dir/noise_cells.f32"); }
    log="$out/harness_$kind.log"
    "$harness" --vert "$s/vert.spv" --tesc "$s/tesc.spv" --tese "$s/tese.spv" --frag "$s/frag.spv" \
      --buffers "$dir" --patches $((32 * 32)) --width "$width" --height "$height" "${table[@]}" \
      --png "$out/noise_$kind.png" --stats "${state[@]}" "${dev[@]}" >"$log" 2>&1 || { cat "$log" >&2; die "harness failed ($kind noise)"; }
    say "$kind noise: $(awk '$1=="stat" && $2=="clipping_invocations" {print $3}' "$log") triangles; image $out/noise_$kind.png"
    if [ "$docs" = 1 ]; then
      mkdir -p "$PKG_DIR/Documentation~/images"
      python3 "$RIG_DIR/png_palette.py" "$out/noise_$kind.png" "$PKG_DIR/Documentation~/images/noise_$kind.png" 32 --half
    fi
  done
  exit 0
fi
if [ "$dem" = 1 ]; then
  dir="$out/buffers_dem"
  "$cli" pack --grid "$out/dem_grid.json" --range "0,0,1,1" --tiles "$tiles" --factor "$factor" \
    --noise 0,16,2,2 --octaves 1 --width "$width" --height "$height" --out "$dir" >/dev/null
  log="$out/harness_dem.log"
  "$harness" --vert "$spv/vert.spv" --tesc "$spv/tesc.spv" --tese "$spv/tese.spv" --frag "$spv/frag.spv" \
    --buffers "$dir" --patches $((tiles * tiles)) --width "$width" --height "$height" \
    --png "$out/demo_dem.png" --stats "${state[@]}" "${dev[@]}" >"$log" 2>&1 || { cat "$log" >&2; die "harness failed on the DEM grid"; }
  say "DEM crop: $(awk '$1=="stat" && $2=="clipping_invocations" {print $3}' "$log") triangles; image $out/demo_dem.png"
  if [ "$docs" = 1 ]; then
    mkdir -p "$PKG_DIR/Documentation~/images"
    # 32 colours: the noisy ground looks the same as at 64, 5 KB smaller
    python3 "$RIG_DIR/png_palette.py" "$out/demo_dem.png" "$PKG_DIR/Documentation~/images/demo_dem.png" 16
  fi
  exit 0
fi
printf '%-6s %-24s %12s %12s %14s\n' "g=h" "range" "vertices" "triangles" "nonsky pixels"
for g in 1.0 0.5 0.2 0.1 0.02; do
  dir="$out/buffers_g$g"
  "$cli" pack --grid "$out/grid.json" --range "0,0,$g,$g" --tiles "$tiles" --factor "$factor" \
    --noise 0.004,16,2,2 --octaves 8 --width "$width" --height "$height" --out "$dir" >/dev/null
  log="$out/harness_g$g.log"
  "$harness" --vert "$spv/vert.spv" --tesc "$spv/tesc.spv" --tese "$spv/tese.spv" --frag "$spv/frag.spv" \
    --buffers "$dir" --patches $((tiles * tiles)) --width "$width" --height "$height" \
    --png "$out/demo_g$g.png" --stats "${state[@]}" "${dev[@]}" >"$log" 2>&1 || { cat "$log" >&2; die "harness failed at g = $g"; }
  verts=$(awk '$1=="stat" && $2=="tessellation_evaluation_shader_invocations" {print $3}' "$log")
  tris=$(awk '$1=="stat" && $2=="clipping_invocations" {print $3}' "$log")
  nonsky=$(awk '$1=="image" && $2=="nonsky_pixels" {print $3 " of " $5}' "$log")
  printf '%-6s %-24s %12s %12s %14s\n' "$g" "0,0,$g,$g" "$verts" "$tris" "$nonsky"
  if [ "$docs" = 1 ]; then
    # g < 1 only appears in the development page's row of five, where half size is what shows: 200 x 150.
    half=() images="$PKG_DIR/Documentation~/images"; [ "$g" = 1.0 ] || { half=(--half); images="$PKG_DIR/Tools~/images"; }
    mkdir -p "$images"
    python3 "$RIG_DIR/png_palette.py" "$out/demo_g$g.png" "$images/demo_g$g.png" 24 "${half[@]}"
  fi
done
say "images: $out/demo_g*.png$([ "$docs" = 1 ] && echo " and Documentation~/images/demo_g1.0.png, Tools~/images/demo_g0.*.png")"
say "device: $(awk '$1=="device" && $2=="name" {$1=$2=""; print substr($0,3)}' "$out/harness_g1.0.log")"
