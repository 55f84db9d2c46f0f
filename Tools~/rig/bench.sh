# gt bench: the accuracy-vs-time benchmark (prints figures; not a test).
#   gt bench [--quick] [--device NAME]     plan, run on this machine's Vulkan device, print the tables
#   gt bench [--quick] --prepare DIR       plan + harness + SPIR-V + scripts into DIR, to run elsewhere:
#                                          bash DIR/bench_run.sh DIR DIR/gt-harness DIR/spirv OUT [--device NAME]
#   gt bench [--quick] --report RAW [--plan DIR]  tables of a run's raw output (results.txt, readback.tar)
#   gt bench --docs RAW [--plan DIR]        RAW/bench_table.md (the full tables, kept with the run), and the
#                                          summary tables and the plot of Documentation~/performance.md
#                                          (the headline run: Tools~/bench/runs/h200)
# --quick: small sizes for lavapipe (CI, about 2 minutes). Without --device the first device is used
# (lavapipe here: set VK_DRIVER_FILES to choose).
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
quick=() device=() prepare="" report="" docs="" plan=""
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) quick=(--quick) ;;
    --device) device=(--device "$2"); shift ;;
    --prepare) prepare=$2; shift ;;
    --report) report=$2; shift ;;
    --plan) plan=$2; shift ;;
    --docs) docs=$2; shift ;;
    *) die "bench: unknown option $1" ;;
  esac
  shift
done
cli=(dotnet "$BUILD_DIR/gt-cli/gt-cli.dll")
[ -f "$BUILD_DIR/gt-cli/gt-cli.dll" ] || die "gt-cli is not built (run: gt setup)"
bench="$BUILD_DIR/bench"
grid="$bench/grid.json"
mkdir -p "$bench"
[ -f "$grid" ] || "${cli[@]}" demo-grid --out "$grid" >&2

make_plan() {  # make_plan DIR
  local dir=$1
  rm -rf "$dir"; mkdir -p "$dir"
  "${cli[@]}" bench-plan --grid "$grid" --out "$dir" "${quick[@]}" >&2
  write_pass_states "$dir"   # the forward pass's render state: bench_run.sh draws every job with it
  # The vertex cache's variants (GT_VERTEX_CACHE) carry their two compute kernels (internals.md, "Vertex cache").
  local cache=(vertex_cache noise+vertex_cache noise+height_color+vertex_cache)
  local drawn=(base noise noise+height_color paper_mode paper_mode+noise factor_readback factor_readback+noise
               readback+noise noise+height_color+noise_table lod+noise+height_color "${cache[@]}")
  # Always compiled afresh, the variants the plan draws only: a plan carried to the GPU with SPIR-V
  # older than Shaders/ times the old kernels under the new dispatch sizes, and nothing would say so.
  local only=()
  for v in "${drawn[@]}"; do only+=(--only "$v"); done
  bash "$RIG_DIR/shaders.sh" --spirv-only "${only[@]}" -j "$(nproc)" >/dev/null
  for v in "${cache[@]}"; do
    [ -f "$BUILD_DIR/spirv/$v/cache_factors.spv" ] && [ -f "$BUILD_DIR/spirv/$v/cache_vertices.spv" ] \
      || die "gt shaders wrote no $v/cache_factors.spv + cache_vertices.spv (GT_VERTEX_CACHE variants and kernels, internals.md)"
  done
  mkdir -p "$dir/spirv"
  for v in "${drawn[@]}"; do
    mkdir -p "$dir/spirv/$v"; cp "$BUILD_DIR/spirv/$v/"*.spv "$dir/spirv/$v/"
  done
  # The fair static mesh's vertex stage (rig only, GT_STATIC_MESH): reads baked vertices, same frag
  # (noise+height_color's, so GT_HEIGHT_COLOR: it hands the frag the baked height).
  glslangValidator -D -V -S vert -e vert_static --hlsl-iomap --shift-cbuffer-binding 0 --shift-texture-binding 2 \
    --shift-UAV-binding 5 -DGT_STATIC_MESH -DGT_HEIGHT_COLOR -o "$dir/spirv/static.spv" "$RIG_DIR/TerrainRig.hlsl" >/dev/null
  # The tessellator's floor (rig only): the fair variant's tiles with a domain stage that evaluates nothing.
  glslangValidator -D -V -S tese -e domain_floor --hlsl-iomap --shift-cbuffer-binding 0 --shift-texture-binding 2 \
    --shift-UAV-binding 5 -DGT_NOISE -DGT_HEIGHT_COLOR -o "$dir/spirv/floor.spv" "$RIG_DIR/bench_floor.hlsl" >/dev/null
  # The levels' own floor (rig only): the levels' vert and hull (GT_LOD) with the same flat domain stage.
  glslangValidator -D -V -S tese -e domain_floor --hlsl-iomap --shift-cbuffer-binding 0 --shift-texture-binding 2 \
    --shift-UAV-binding 5 -DGT_LOD -DGT_NOISE -DGT_HEIGHT_COLOR -o "$dir/spirv/floor_lod.spv" "$RIG_DIR/bench_floor.hlsl" >/dev/null \
    || die "glslang failed on bench_floor.hlsl with GT_LOD"
  # The domain-stage breakdown (rig only): one domain stage per part the plan names, -DPART_<NAME>.
  mkdir -p "$dir/spirv/parts"
  for part in $(grep -o '@SPV@/parts/[a-z_]*\.spv' "$dir/plan.tsv" | sed 's|.*/||; s|\.spv$||' | sort -u); do
    glslangValidator -D -V -S tese -e domain_part --hlsl-iomap --shift-cbuffer-binding 0 --shift-texture-binding 2 \
      --shift-UAV-binding 5 -DGT_NOISE -DGT_HEIGHT_COLOR "-DPART_${part^^}" -o "$dir/spirv/parts/$part.spv" \
      "$RIG_DIR/bench_domain_parts.hlsl" >/dev/null || die "glslang failed on bench_domain_parts.hlsl, part $part"
  done
  bash "$TOOLS_DIR/harness/test/compile.sh" "$dir/mesh-spv" >/dev/null
  cp "$dir/mesh-spv/mesh.vert.spv" "$dir/mesh-spv/mesh.frag.spv" "$dir/spirv/"; rm -rf "$dir/mesh-spv"
  cp "$RIG_DIR/bench_run.sh" "$RIG_DIR/bench_static_mesh.py" "$TOOLS_DIR/harness/test/make_grid_mesh.py" "$dir/"
  cp "$BUILD_DIR/harness/gt-harness" "$dir/"
}

report_of() {  # report_of RAW PLAN
  "${cli[@]}" bench-report --plan "$2" --raw "$1" --grid "$grid"
}

if [ -n "$docs" ]; then
  [ -n "$plan" ] || { plan="$bench/plan-docs"; make_plan "$plan"; }
  # The full table (.md) and its data (.tsv) stay beside the raw run (Tools~/bench/runs/...), outside
  # what the package ships; the manual gets its summary tables (the marked blocks of performance.md,
  # gt-cli bench-docs) and the plot.
  "${cli[@]}" bench-report --plan "$plan" --raw "$docs" --grid "$grid" --tsv "$docs/bench_table.tsv" > /dev/null
  "${cli[@]}" bench-docs --table "$docs/bench_table.md" --page "$PKG_DIR/Documentation~/performance.md"
  img="$PKG_DIR/Documentation~/images/accuracy_vs_time.png"
  py=python3; [ -x /usr/bin/python3 ] && /usr/bin/python3 -c "import matplotlib" 2>/dev/null && py=/usr/bin/python3   # the distribution's matplotlib
  "$py" "$RIG_DIR/bench_plot.py" "$docs/bench_table.tsv" "$img"
  "$py" "$RIG_DIR/png_palette.py" "$img" "$img" 16   # a plot's few line colours; the manual's pictures stay small
  cat "$docs/bench_table.md"
  exit 0
fi
if [ -n "$report" ]; then
  [ -n "$plan" ] || { plan="$bench/plan-report"; make_plan "$plan"; }
  report_of "$report" "$plan"
  exit 0
fi
if [ -n "$prepare" ]; then
  make_plan "$prepare"
  say "prepared $prepare ($(du -sh "$prepare" | cut -f1))"
  exit 0
fi
dir="$bench/plan"
make_plan "$dir"
raw="$bench/raw"
rm -rf "$raw"
bash "$dir/bench_run.sh" "$dir" "$dir/gt-harness" "$dir/spirv" "$raw" "${device[@]}" >&2
report_of "$raw" "$dir"
