# Shared paths and helpers for the rig's scripts. Sourced, never run.
set -euo pipefail
RIG_DIR="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
TOOLS_DIR="$(dirname "$RIG_DIR")"
PKG_DIR="$(dirname "$TOOLS_DIR")"
# Build outputs live outside the package so Unity never sees them and git ignores them.
BUILD_DIR="${GT_BUILD_DIR:-$PKG_DIR/.build}"
mkdir -p "$BUILD_DIR"
export DOTNET_CLI_TELEMETRY_OPTOUT=1 DOTNET_NOLOGO=1 DOTNET_SKIP_FIRST_TIME_EXPERIENCE=1
# lavapipe compiles a tessellated pipeline in ~4.5 CPU s, and again for each new set of the uniform
# values its branches read (it specialises on them); its disk cache makes a repeat ~0.3 s. A cache
# of this build's own keeps a checkout's compiles apart from other checkouts' (~/.cache held 4,700).
export MESA_SHADER_CACHE_DIR="${MESA_SHADER_CACHE_DIR:-$BUILD_DIR/mesa-shader-cache}"

say() { printf '[gt] %s\n' "$*" >&2; }
die() { printf '[gt] error: %s\n' "$*" >&2; exit 1; }
