# gt sculpt-bench: CPU cost of one sculpt dab on an n x n grid, before issue 36 (whole-grid hash,
# conversions, validations, upload packing and query rebuild per dab) and now (the changed patches
# only), the whole-grid check a load pays once, and the bytes a whole-grid step records for Undo.
# A benchmark: it prints, it asserts nothing.
#   gt sculpt-bench [--patches N (256)] [--dabs D (20)] [--radius-patches R (2)]
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
cli="$BUILD_DIR/gt-cli/gt-cli"
dotnet build "$TOOLS_DIR/dotnet/Gt/Gt.csproj" -c Release -v quiet -nologo -o "$BUILD_DIR/gt-cli" >/dev/null
exec "$cli" sculpt-bench "$@"
