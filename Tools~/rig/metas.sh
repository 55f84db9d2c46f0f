# gt metas: writes the missing .meta files (stable GUIDs); never changes an existing one.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
python3 "$RIG_DIR/metas.py" "$PKG_DIR"
