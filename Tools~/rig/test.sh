# gt test: setup, then every test (Core, rig, shaders, GPU through the harness) in one NUnit run.
# Ends with the slowest fixtures, the command's own time and one line "N passed, N failed" (", N skipped"
# only if a test was skipped).
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
started=$SECONDS
GT_PYTHON="${GT_PYTHON:-$(resolve_python)}" || die "python3 did not start"
export GT_PYTHON
bash "$RIG_DIR/setup.sh"
setup_s=$((SECONDS - started))

# The AllVariants category (URP's cascades, PipelinePassCascadeTests: about a minute of drawing a cascade count) runs
# under gt pipeline_pass_all, not here; a --filter of the caller's replaces this one.
lane=(--filter "TestCategory!=AllVariants")
for arg in "$@"; do [ "$arg" = --filter ] && lane=(); done
results="$BUILD_DIR/test-results"
rm -rf "$results"; mkdir -p "$results"
set +e
dotnet test "$TOOLS_DIR/dotnet/Tests/GregoryTerrain.Tests.csproj" -c Release --no-build -nologo \
  -o "$BUILD_DIR/tests" --logger "trx;LogFileName=results.trx" --results-directory "$results" \
  --logger "console;verbosity=normal" "${lane[@]}" "$@"
rc=$?
set -e
trx="$results/results.trx"
[ -f "$trx" ] || die "dotnet test wrote no results (exit $rc)"
python3 - "$trx" "$rc" "$setup_s" "$((SECONDS - started))" <<'PY'
import sys, xml.etree.ElementTree as ET
from datetime import datetime
trx, rc, setup_s, total_s = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4])
ns = {"t": "http://microsoft.com/schemas/VisualStudio/TeamTest/2010"}
root = ET.parse(trx).getroot()

def stamp(text):
    # TRX writes 7 fractional digits and an offset; fromisoformat takes at most 6 before Python 3.11.
    head, _, rest = text.partition(".")
    digits = "".join(ch for ch in rest if ch.isdigit())[:6]
    offset = text[-6:] if text[-6] in "+-" else "+00:00"
    return datetime.fromisoformat(f"{head}.{digits or '0'}{offset}")

# Wall time per fixture: first start to last end of its tests (fixtures overlap when tests run in parallel).
test_ids = {d.get("id"): d.find("t:TestMethod", ns).get("className") for d in root.iterfind("t:TestDefinitions/t:UnitTest", ns)}
by_class = {}
for r in root.iterfind("t:Results/t:UnitTestResult", ns):
    cls = test_ids.get(r.get("testId"), "?").rsplit(".", 1)[-1]
    s, e = stamp(r.get("startTime")), stamp(r.get("endTime"))
    lo, hi = by_class.get(cls, (s, e))
    by_class[cls] = (min(lo, s), max(hi, e))
slowest = sorted(((hi - lo).total_seconds(), cls) for cls, (lo, hi) in by_class.items())[::-1][:8]
print("slowest fixtures (first start to last end, s): " + ", ".join(f"{cls} {sec:.0f}" for sec, cls in slowest))
print(f"test command: {total_s} s ({total_s / 60:.1f} min): setup {setup_s} s, tests {total_s - setup_s} s")
c = root.find("t:ResultSummary/t:Counters", ns)
passed, failed = int(c.get("passed")), int(c.get("failed")) + int(c.get("error")) + int(c.get("timeout"))
skipped = int(c.get("total")) - int(c.get("executed"))
line = f"{passed} passed, {failed} failed" + (f", {skipped} skipped" if skipped else "")
print(line)
sys.exit(1 if failed or rc or passed == 0 else 0)
PY
