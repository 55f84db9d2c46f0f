# gt shaderlab: compiles every pass of Shaders/GregoryTerrain.shader with glslang, each stage its
# pragmas name, against a labelled MOCK of Unity's shader libraries (Tools~/rig/unity-mock).
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
say "shaderlab: compiling the ShaderLab passes (Unity libraries mocked: syntax/type check only)"
python3 "$RIG_DIR/shaderlab.py" "$@"
