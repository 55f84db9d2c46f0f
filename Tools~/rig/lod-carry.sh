# gt lod-carry DEST [--terrains M1,M2,...]: assembles the self-contained folder that
# Tools~/rig/lod-device.sh runs (on lavapipe here, or carried to a GPU machine): the prebuilt
# gt-harness, the SPIR-V of the levels (lod+noise) and of today's single-range draw (noise+range_origin), and per
# terrain width (default 100 km and 1,000 km) the ground-level view of `gt-cli lod-scene` (camera 2 m
# up, M = 16, adaptive factors at 1 px) plus the single range over the whole terrain from the same
# camera at M = 64 tiles and the uniform factor F whose 2 x 64^2 x F^2 triangles come nearest the
# levels' count on lavapipe (clipping invocations; the device prints its own counts), and the render
# state of the shader's forward pass (pass_state_*.args, write_pass_states). A Vulkan loader
# .deb found in $PKG_DIR/.gl is copied to DEST/.gl. Then: bash DEST/lod-device.sh DEST [--device NVIDIA]
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
dest="${1:?usage: gt lod-carry DEST [--terrains M1,M2,...]}"; shift
terrains="100000,1000000"
while [ $# -gt 0 ]; do
  case "$1" in
    --terrains) check_number lod-carry "$1" metres,... "${2-}"; terrains=$2; shift ;;
    *) usage_error lod-carry "unknown argument '$1'" ;;
  esac
  shift
done
harness="$BUILD_DIR/harness/gt-harness"; cli="$BUILD_DIR/gt-cli/gt-cli"
[ -x "$harness" ] && [ -x "$cli" ] || die "harness or gt-cli not built (run: gt setup)"
rm -rf "$dest"; mkdir -p "$dest/bin" "$dest/spv"
cp "$harness" "$dest/bin/"
cp "$RIG_DIR/lod-device.sh" "$RIG_DIR/options.py" "$dest/"
write_pass_states "$dest"   # the forward pass's render state, for lod-device.sh
read -ra state < "$dest/pass_state_tessellated.args"
tmp="$BUILD_DIR/lod-carry-spirv"; rm -rf "$tmp"
# The single range is drawn around the same range origin as the levels (lod-scene sends one), so it
# needs the origin's code: without GT_RANGE_ORIGIN a stage draws a sent origin as 0.
GT_BUILD_DIR="$tmp" bash "$TOOLS_DIR/gt" shaders --only lod+noise --only noise+range_origin >/dev/null \
  || die "gt shaders failed (run it alone to see why)"
for v in lod:lod+noise single:noise+range_origin; do
  mkdir -p "$dest/spv/${v%%:*}"
  for s in vert tesc tese frag; do cp "$tmp/spirv/${v#*:}/$s.spv" "$dest/spv/${v%%:*}/"; done
done
: > "$dest/runs.txt"
IFS=, read -r -a list <<< "$terrains"
for m in "${list[@]}"; do
  name="t$m"; mkdir -p "$dest/$name"
  "$cli" lod-scene --out "$dest/$name/lod" --terrain-m "$m" > "$dest/$name/lod.txt"
  patches=$(awk '$1 == "patches" { print $2 }' "$dest/$name/lod.txt")
  "$harness" --vert "$dest/spv/lod/vert.spv" --tesc "$dest/spv/lod/tesc.spv" --tese "$dest/spv/lod/tese.spv" \
    --frag "$dest/spv/lod/frag.spv" --buffers "$dest/$name/lod" --params-tail "$dest/$name/lod/lod_tail.f32" \
    --patches "$patches" --storage "7:$((64 * patches))" --storage 8:16 --width 1920 --height 1080 "${state[@]}" --stats --device llvmpipe > "$dest/$name/lod-lavapipe.txt" \
    || die "the levels' draw failed on lavapipe ($dest/$name/lod-lavapipe.txt)"
  tris=$(awk '$1 == "stat" && $2 == "clipping_invocations" { print $3 }' "$dest/$name/lod-lavapipe.txt")
  f=$(python3 -c "import math; print(max(1, min(64, round(math.sqrt($tris / (2 * 64 * 64))))))")
  # The same camera and grid, one range (the whole terrain) at M = 64 and the uniform factor F.
  "$cli" lod-scene --out "$dest/$name/single" --terrain-m "$m" --tiles 64 --factor "$f" > "$dest/$name/single.txt"
  echo "$name $m $patches $tris $f" >> "$dest/runs.txt"
  say "$name: $patches level tiles, $tris triangles on lavapipe; single range 64 x 64 tiles at F = $f ($((2 * 64 * 64 * f * f)) triangles)"
done
if ls "$PKG_DIR"/.gl/*.deb >/dev/null 2>&1; then mkdir -p "$dest/.gl"; cp "$PKG_DIR"/.gl/*.deb "$dest/.gl/"; fi
say "assembled $(du -sh "$dest" | cut -f1) in $dest; run: bash $dest/lod-device.sh $dest [--device NVIDIA]"
