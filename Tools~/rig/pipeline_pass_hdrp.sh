# gt pipeline_pass_hdrp: HDRP's DepthForwardOnly and ForwardOnly drawn by the harness beside URP's ForwardLit, their
# bindings filled by name from the same scene in HDRP's units (Tools~/rig/pipeline_pass_hdrp.py says how). Needs gt setup.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
python3 "$RIG_DIR/pipeline_pass_hdrp.py" "$@"
