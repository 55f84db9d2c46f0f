# gt test: setup, then every test (Core, rig, shaders, GPU through the harness) in one NUnit run.
# Ends with one line "N passed, N failed" (", N skipped" only if a test was skipped).
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
bash "$RIG_DIR/setup.sh"

results="$BUILD_DIR/test-results"
rm -rf "$results"; mkdir -p "$results"
set +e
dotnet test "$TOOLS_DIR/dotnet/Tests/GregoryTerrain.Tests.csproj" -c Release --no-build -nologo \
  -o "$BUILD_DIR/tests" --logger "trx;LogFileName=results.trx" --results-directory "$results" \
  --logger "console;verbosity=normal" "$@"
rc=$?
set -e
trx="$results/results.trx"
[ -f "$trx" ] || die "dotnet test wrote no results (exit $rc)"
python3 - "$trx" "$rc" <<'PY'
import sys, xml.etree.ElementTree as ET
trx, rc = sys.argv[1], int(sys.argv[2])
ns = {"t": "http://microsoft.com/schemas/VisualStudio/TeamTest/2010"}
c = ET.parse(trx).getroot().find("t:ResultSummary/t:Counters", ns)
passed, failed = int(c.get("passed")), int(c.get("failed")) + int(c.get("error")) + int(c.get("timeout"))
skipped = int(c.get("total")) - int(c.get("executed"))
line = f"{passed} passed, {failed} failed" + (f", {skipped} skipped" if skipped else "")
print(line)
sys.exit(1 if failed or rc or passed == 0 else 0)
PY
