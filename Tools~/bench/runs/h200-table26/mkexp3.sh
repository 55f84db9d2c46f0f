#!/usr/bin/env bash
set -euo pipefail
P=/work/main/.carry/plan2; E=/work/main/.carry/exp; RIG=/work/main/Tools~/rig
rm -rf $E; mkdir -p $E/spirv/parts $E/jobs
cp -r $P/jobs/fs_m32_f63 $P/jobs/fs_m32_f31 $P/jobs/orders $E/jobs/
cp $P/gt-harness $P/bench_run.sh $P/bench_static_mesh.py $P/make_grid_mesh.py $E/
cp $P/spirv/static.spv $P/spirv/floor.spv $E/spirv/
cp -r $P/spirv/noise+height_color $P/spirv/readback+noise $E/spirv/
G=(glslangValidator -D -V --hlsl-iomap --shift-cbuffer-binding 0 --shift-texture-binding 2 --shift-UAV-binding 5)
parts="full noise_first region_early noise_first+region_early table_coef table_coef+noise_first"
for p in $parts; do
  defs=(); for d in ${p//+/ }; do defs+=("-DPART_${d^^}"); done
  "${G[@]}" -S tese -e domain_part -DGT_NOISE -DGT_HEIGHT_COLOR "${defs[@]}" -o "$E/spirv/parts/$p.spv" "$RIG/bench_domain_parts.hlsl" >/dev/null
done
: > $E/plan.tsv
for id in fs_m32_f63 fs_m32_f31; do
  grep -P "^$id:(bake|static|tess-floor|terrain)\t" $P/plan.tsv >> $E/plan.tsv
  base=$(grep -P "^$id:part-full\t" $P/plan.tsv)
  for round in 1 2; do
    for p in $parts; do
      extra=""; case $p in table_coef*) extra=" --storage 9:3145728";; esac
      line=${base//parts\/full.spv/parts\/$p.spv}; line=${line/$id:part-full/$id:r$round-$p}
      printf '%s%s\n' "$line" "$extra" >> $E/plan.tsv
    done
  done
done
wc -l $E/plan.tsv
