# gt pipeline_pass: URP's DepthOnly and ForwardLit, Built-in's ForwardBase drawn by the harness, their bindings
# filled by name from a scene (Tools~/rig/pipeline_pass.py says how). Needs gt setup (gt-cli, harness).
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
python3 "$RIG_DIR/pipeline_pass.py" "$@"
