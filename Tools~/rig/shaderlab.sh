# gt shaderlab: compiles every pass, variant and stage of Shaders/GregoryTerrain.shader (and every
# Shaders/**/*.compute kernel) with glslang and DXC against Unity's real shader libraries
# (../shared/unity-shaderlib), lints them for FXC's rules (fxc_lint.py), then as a Built-in-only,
# URP-only and HDRP-only project would import it.
# Options: --package DIR, --check pipelines|projects, --pipeline URP,HDRP,Builtin,Compute, --counts, --quiet.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
say "shaderlab: compiling the shaders against Unity's real shader libraries (glslang and DXC, desktop Vulkan defines)"
python3 "$RIG_DIR/shaderlab.py" "$@"
