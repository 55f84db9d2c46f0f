# gt pipeline_pictures: the same scene through the standalone rig, URP, HDRP and Built-in side by side, and where
# they agree (Tools~/rig/pipeline_pictures.py says how). Needs gt setup and a python3 with PIL.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
/usr/bin/python3 "$RIG_DIR/pipeline_pictures.py" "$@"
