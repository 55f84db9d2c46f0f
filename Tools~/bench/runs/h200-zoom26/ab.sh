#!/usr/bin/env bash
# ab.sh OUT PLAN56 FULLPARTS_TAG TAG=REF|TAG=WT ... : an A/B folder of the domain-stage jobs (fs_m32_f63, fs_m32_f31)
set -euo pipefail
out=$1 plan=$2 fullparts=$3; shift 3
WT=/work/wt-zoom26
rm -rf "$out"; mkdir -p "$out/spirv" "$out/jobs"
cp -r "$plan/jobs/fs_m32_f63" "$plan/jobs/fs_m32_f31" "$plan/jobs/orders" "$out/jobs/"
cp "$plan/gt-harness" "$plan/bench_run.sh" "$plan/bench_static_mesh.py" "$plan/make_grid_mesh.py" "$out/"
cp "$plan/spirv/static.spv" "$plan/spirv/floor.spv" "$plan/spirv/mesh.vert.spv" "$plan/spirv/mesh.frag.spv" "$out/spirv/"
mkdir -p "$out/spirv/noise+height_color"; cp "$plan/spirv/noise+height_color/frag.spv" "$out/spirv/noise+height_color/"
mkdir -p "$out/spirv/readback+noise"; cp "$plan/spirv/readback+noise/"{fallback,frag}.spv "$out/spirv/readback+noise/"
G=(glslangValidator -D -V --hlsl-iomap --shift-cbuffer-binding 0 --shift-texture-binding 2 --shift-UAV-binding 5)
tags=()
for spec in "$@"; do
  tag=${spec%%=*} ref=${spec#*=}; tags+=("$tag")
  if [ "$ref" = WT ]; then src=$WT; elif [ -d "$ref" ]; then src=$ref; else src=/tmp/z26/src-$tag; rm -rf "$src"; mkdir -p "$src"; git -C $WT archive "$ref" Shaders 'Tools~/rig' | tar -x -C "$src"; fi
  rig="$src/Tools~/rig"; d="$out/spirv/$tag"; mkdir -p "$d/nhc" "$d/base" "$d/parts" "$d/cache"
  for st in "vert vert" "tesc hull_shader" "tese domain_shader" "frag frag"; do set -- $st
    "${G[@]}" -S $1 -e $2 -DGT_NOISE -DGT_HEIGHT_COLOR -o "$d/nhc/$1.spv" "$rig/TerrainRig.hlsl" >/dev/null
    "${G[@]}" -S $1 -e $2 -DGT_NOISE -DGT_HEIGHT_COLOR -DGT_VERTEX_CACHE -o "$d/cache/$1.spv" "$rig/TerrainRig.hlsl" >/dev/null
  done
  "${G[@]}" -S comp -e CacheTileFactors -DGT_NOISE -DGT_HEIGHT_COLOR -DGT_VERTEX_CACHE -o "$d/cache/cache_factors.spv" "$rig/TerrainRig.hlsl" >/dev/null
  "${G[@]}" -S comp -e CacheTileVertices -DGT_NOISE -DGT_HEIGHT_COLOR -DGT_VERTEX_CACHE -o "$d/cache/cache_vertices.spv" "$rig/TerrainRig.hlsl" >/dev/null
  "${G[@]}" -S tese -e domain_shader -o "$d/base/tese.spv" "$rig/TerrainRig.hlsl" >/dev/null
  parts="full minimal plain"; [ "$tag" = "$fullparts" ] && parts="full minimal plain no_lookup no_range no_deriv no_gregory no_octaves one_octave cheap_hash plain_split no_normal no_colour"
  for p in $parts; do "${G[@]}" -S tese -e domain_part -DGT_NOISE -DGT_HEIGHT_COLOR "-DPART_${p^^}" -o "$d/parts/$p.spv" "$rig/bench_domain_parts.hlsl" >/dev/null; done
  for x in "${EXTRA_TESE[@]:-}"; do [ -z "$x" ] && continue; n=${x%%:*} defs=${x#*:}
    # shellcheck disable=SC2086
    "${G[@]}" -S tese -e domain_shader -DGT_NOISE -DGT_HEIGHT_COLOR $defs -o "$d/nhc/tese-$n.spv" "$rig/TerrainRig.hlsl" >/dev/null; done
done
# plan: shared jobs once, then per tag interleaved
: > "$out/plan.tsv"
for s in f63 f31; do
  id=fs_m32_$s
  grep -P "^$id:(bake|static|static-strips)\t" "$plan/plan.tsv" >> "$out/plan.tsv"
  for job in terrain plain tess-floor part-full part-minimal part-plain cached terrain; do
    for tag in "${tags[@]}"; do
      line=$(grep -P "^$id:$job\t" "$plan/plan.tsv" | head -1)
      line=${line//@SPV@\/noise+height_color+vertex_cache\//@SPV@/$tag/cache/}
      line=${line//@SPV@\/noise+height_color\//@SPV@/$tag/nhc/}
      line=${line//@SPV@\/base\//@SPV@/$tag/base/}
      line=${line//@SPV@\/parts\//@SPV@/$tag/parts/}
      n=$(grep -c -P "^$id:$job-$tag(-again)?\t" "$out/plan.tsv" || true)
      name="$job-$tag"; [ "$n" -gt 0 ] && name="$job-$tag-again"
      printf '%s\n' "${line/#$id:$job	/$id:$name	}" >> "$out/plan.tsv"
    done
  done
  for tag in "${tags[@]}"; do
    for p in $(ls "$out/spirv/$tag/parts" | sed 's/\.spv$//'); do
      case $p in full|minimal|plain) continue ;; esac
      line=$(grep -P "^$id:part-full\t" "$plan/plan.tsv"); line=${line//@SPV@\/noise+height_color\//@SPV@/$tag/nhc/}
      line=${line//@SPV@\/parts\/full.spv/@SPV@/$tag/parts/$p.spv}
      printf '%s\n' "${line/#$id:part-full	/$id:part-$p-$tag	}" >> "$out/plan.tsv"
    done
    for t in $(ls "$out/spirv/$tag/nhc" | grep '^tese-' | sed 's/^tese-//; s/\.spv$//'); do
      line=$(grep -P "^$id:terrain\t" "$plan/plan.tsv"); line=${line//@SPV@\/noise+height_color\//@SPV@/$tag/nhc/}
      line=${line//@SPV@\/$tag\/nhc\/tese.spv/@SPV@/$tag/nhc/tese-$t.spv}
      printf '%s\n' "${line/#$id:terrain	/$id:t-$t-$tag	}" >> "$out/plan.tsv"
    done
  done
done
cat > "$out/run.sh" <<'R'
#!/usr/bin/env bash
d=$(cd "$(dirname "$0")" && pwd); o=$1
bash "$d/bench_run.sh" "$d" "$d/gt-harness" "$d/spirv" "$o" --device NVIDIA
grep -E "^== |time frame_ms_median|time compute_ms_median|clipping_invocations|^exit|skipped" "$o/results.txt" > "$o/summary.txt"
R
echo "$(wc -l < "$out/plan.tsv") jobs; $(du -sh "$out" | cut -f1)"
