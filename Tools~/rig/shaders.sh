# gt shaders: compile every stage of every keyword variant (shader_variants.txt) to SPIR-V with
# glslang's HLSL front end, validate, check the descriptor bindings, cross-compile to GLSL 4.50,
# GLSL ES 3.20 and MSL, and recompile the GLSL; and the same stage with Microsoft's DXC (HLSL 2018).
# One line per variant and stage, then the counts.
# Outputs: $BUILD_DIR/spirv/<variant>/<stage>.spv (+ .glsl/.metal and a .log per stage).
#   gt shaders [--only VARIANT]... [-j JOBS] [--spirv-only] [--no-cache]   (--spirv-only: SPIR-V, spirv-val and the
#   binding check only, what the GPU tests and the bench draw)
# GT_SHADER_INCLUDES: extra include folders (':'-separated), searched after Shaders/ itself.
# The SPIR-V of a stage glslang compiled before from the same text and options comes from .build/shader-cache
# (GT_SHADER_CACHE to move it; --no-cache: compile every stage); every later check runs on it as on a fresh one.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
for tool in glslangValidator spirv-val spirv-cross python3; do
  command -v "$tool" >/dev/null || die "$tool is not on PATH (run: gt setup)"
done
out="$BUILD_DIR/spirv"
inc=()
IFS=':' read -r -a dirs <<< "${GT_SHADER_INCLUDES:-}"
for d in "${dirs[@]}"; do [ -n "$d" ] && inc+=(-I "$d"); done
exec python3 "$RIG_DIR/shaders.py" "$out" --clean "${inc[@]}" "$@"
