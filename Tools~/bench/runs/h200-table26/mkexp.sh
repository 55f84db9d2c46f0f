#!/usr/bin/env bash
set -euo pipefail
P=/work/main/.carry/plan; E=/work/main/.carry/exp; RIG=/work/main/Tools~/rig
rm -rf $E; mkdir -p $E/spirv/parts $E/jobs
cp -r $P/jobs/fs_m32_f63 $P/jobs/fs_m32_f31 $P/jobs/orders $E/jobs/
cp $P/gt-harness $P/bench_run.sh $P/bench_static_mesh.py $P/make_grid_mesh.py $E/
cp $P/spirv/static.spv $P/spirv/floor.spv $E/spirv/
cp -r $P/spirv/noise+height_color $P/spirv/readback+noise $E/spirv/
G=(glslangValidator -D -V --hlsl-iomap --shift-cbuffer-binding 0 --shift-texture-binding 2 --shift-UAV-binding 5)
"${G[@]}" -S tese -e domain_shader -DGT_NOISE -DGT_HEIGHT_COLOR -o $E/spirv/noise+height_color/tese-new.spv $RIG/TerrainRig.hlsl >/dev/null
"${G[@]}" -S tese -e domain_shader -DGT_NOISE -DGT_HEIGHT_COLOR -DEXP_NO_SEGMENT -o $E/spirv/noise+height_color/tese-noseg.spv $RIG/TerrainRig.hlsl >/dev/null
parts="full colour_local no_colour plain table_cells table_cells-cl table_coef-cl"
for p in $parts; do
  defs=(); n=${p%-cl}; [ "$n" != "$p" ] && defs+=(-DPART_COLOUR_LOCAL)
  "${G[@]}" -S tese -e domain_part -DGT_NOISE -DGT_HEIGHT_COLOR "-DPART_${n^^}" "${defs[@]}" -o "$E/spirv/parts/$p.spv" "$RIG/bench_domain_parts.hlsl" >/dev/null
done
: > $E/plan.tsv
for id in fs_m32_f63 fs_m32_f31; do
  grep -P "^$id:(bake|static|tess-floor)\t" $P/plan.tsv >> $E/plan.tsv
  base=$(grep -P "^$id:part-full\t" $P/plan.tsv)
  terr=$(grep -P "^$id:terrain\t" $P/plan.tsv)
  for round in 1 2; do
    printf '%s\n' "${terr/$id:terrain/$id:r$round-terrain}" >> $E/plan.tsv
    t2=${terr/$id:terrain/$id:r$round-terrain-new}; printf '%s\n' "${t2//tese.spv/tese-new.spv}" >> $E/plan.tsv
    t3=${terr/$id:terrain/$id:r$round-terrain-noseg}; printf '%s\n' "${t3//tese.spv/tese-noseg.spv}" >> $E/plan.tsv
    for p in $parts; do
      extra=""
      case $p in table_cells*) extra=" --storage 9:2097152";; table_coef*) extra=" --storage 9:3145728";; esac
      line=${base//parts\/full.spv/parts\/$p.spv}; line=${line/$id:part-full/$id:r$round-$p}
      printf '%s%s\n' "$line" "$extra" >> $E/plan.tsv
    done
  done
done
wc -l $E/plan.tsv; du -sh $E
