#!/usr/bin/env bash
# Compiles the self-test HLSL to SPIR-V with the package's register mapping
# (Tools~/rig/README.md "Descriptor bindings": b0->0, b1->1, t0..t2->2..4, u0->5; the vertex cache's
# t5/t6 and u2/u3 -> 7/8, the --storage bindings of the compute tests):
#   --hlsl-iomap            shifts apply per HLSL register class (b/t/u), not per SPIR-V kind
#   --stb 2                 t registers (StructuredBuffer) start at binding 2
#   --suavb 5               u registers (RWStructuredBuffer) start at binding 5
#   (b registers are unshifted: b0 -> 0, b1 -> 1)
# Usage: compile.sh OUT_DIR
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
out="${1:?usage: compile.sh OUT_DIR}"
mkdir -p "$out"
map=(--hlsl-iomap --stb 2 --suavb 5)
c() {  # c STAGE ENTRY SOURCE OUTPUT [DEFINES...]
  local stage=$1 entry=$2 src=$3 dst=$4; shift 4
  glslangValidator -D -V -S "$stage" -e "$entry" "${map[@]}" "$@" -o "$out/$dst" "$here/$src" >/dev/null \
    || { glslangValidator -D -V -S "$stage" -e "$entry" "${map[@]}" "$@" -o "$out/$dst" "$here/$src"; exit 1; }
  spirv-val "$out/$dst"
}
c vert vert tiles.hlsl tiles.vert.spv
c tesc hull_shader tiles.hlsl tiles.tesc.spv
c tese domain_shader tiles.hlsl tiles.tese.spv
c tese domain_shader tiles.hlsl tiles_readback.tese.spv -DGT_READBACK
c vert vert_fallback tiles.hlsl fallback.vert.spv
c vert vert_fallback tiles.hlsl fallback_readback.vert.spv -DGT_READBACK
c frag frag tiles.hlsl tiles.frag.spv
c tese domain_shader tiles.hlsl tiles_storage.tese.spv -DGT_STORAGE_TEST
c vert vert_fallback tiles.hlsl fallback_storage.vert.spv -DGT_STORAGE_TEST
c comp pattern storage_pattern.hlsl pattern.comp.spv
c comp probe sampling.hlsl sampling.comp.spv
c comp tile_flags tile_scale.hlsl tile_flags.comp.spv
c comp tile_scale tile_scale.hlsl tile_scale.comp.spv
c vert vert mesh.hlsl mesh.vert.spv
c frag frag mesh.hlsl mesh.frag.spv
