#!/usr/bin/env bash
# Harness self-test: builds gt-harness, compiles the test shaders, runs selftest.py on lavapipe.
# Usage: Tools~/harness/test/selftest.sh [extra harness args, e.g. --device llvmpipe]
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
pkg="$(cd "$here/../../.." && pwd)"
build="${GT_BUILD_DIR:-$pkg/.build}"
cmake -S "$pkg/Tools~/harness" -B "$build/harness" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build/harness" -j "$(nproc)" >/dev/null
"$here/compile.sh" "$build/harness-test/spv"
if [ -z "${VK_ICD_FILENAMES:-}${VK_DRIVER_FILES:-}" ] && [ -f /usr/share/vulkan/icd.d/lvp_icd.x86_64.json ]; then
  export VK_ICD_FILENAMES=/usr/share/vulkan/icd.d/lvp_icd.x86_64.json
fi
exec python3 "$here/selftest.py" "$build/harness/gt-harness" "$build/harness-test/spv" "$build/harness-test/work" "$@"
