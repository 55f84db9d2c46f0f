# gt pipeline_pass_all: every variant of every pass of each pipeline's tessellated SubShader drawn once by the harness,
# bindings filled by name from the scene (Tools~/rig/pipeline_pass_all.py says how). Needs gt setup. Not part of gt test.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
python3 "$RIG_DIR/pipeline_pass_all.py" "$@"
