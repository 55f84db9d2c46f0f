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

# python3 on PATH may be a version manager's shim (pyenv's: a bash script and two more processes,
# ~0.12 CPU s a call, three times python's own start-up); gt test resolves the interpreter once into
# GT_PYTHON, which every script it starts (and their scripts) then calls directly.
python3() {
  if [ -n "${GT_PYTHON:-}" ]; then "$GT_PYTHON" "$@"; else command python3 "$@"; fi
}
resolve_python() { command python3 -c 'import sys; print(sys.executable)'; }

say() { printf '[gt] %s\n' "$*" >&2; }
die() { printf '[gt] error: %s\n' "$*" >&2; exit 1; }
# A bad command line: "gt CMD: MESSAGE", exit 2 (gt-cli's exit code for bad usage).
usage_error() { printf 'gt %s: %s\n' "$1" "$2" >&2; exit 2; }
# check_number CMD OPTION FORM VALUE: exit 2 with "gt CMD: OPTION VALUE is out of range (LO..HI)"
# unless VALUE is a number of FORM (a range of options.py's RANGES; NAME,... a list; size WxH).
# Called as each option is read, so a bad value stops the command before any work.
check_number() { python3 "$RIG_DIR/options.py" "$@" || exit 2; }

# The render state the rig's variants draw with: the forward pass's Cull, ZTest, ZWrite, ZClip and
# ColorMask in Shaders/GregoryTerrain.shader (render_state.py), as harness options.
#   pass_state tessellated|fallback          prints them (one line)
#   pass_state_args ARRAY tessellated|fallback   sets the array ARRAY to them
#   write_pass_states DIR                    DIR/pass_state_tessellated.args and _fallback.args, for
#                                            folders carried to a machine without the package
pass_state() { python3 "$RIG_DIR/render_state.py" --draw "$1" || die "render_state.py --draw $1 failed"; }
pass_state_args() {
  local -n _state=$1
  local line
  line=$(pass_state "$2") || exit 1
  read -ra _state <<< "$line"
}
write_pass_states() {
  local draw
  for draw in tessellated fallback; do pass_state "$draw" > "$1/pass_state_$draw.args"; done
}
