# gt mirror: pairs each HLSL file of Shaders/{Library,Terrain,Cache,Snow,Grid} with its Core twin in
# Runtime/Core and fails naming the file and function for a function on one side only, a different
# parameter shape, or a keyword that is #if in HLSL and a runtime bool in C# (Tools~/development.md,
# "The mirror"). Accepted differences, each with its reason: Tools~/rig/mirror-allow.txt. MirrorCheckTests runs the same check.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
[ $# -eq 0 ] || usage_error mirror "takes no options (got '$1')"
# Built here, not only by setup: the check reflects over Core as it is now.
dotnet build "$TOOLS_DIR/dotnet/Gt/Gt.csproj" -c Release -v quiet -nologo -o "$BUILD_DIR/gt-cli" >/dev/null \
  || dotnet build "$TOOLS_DIR/dotnet/Gt/Gt.csproj" -c Release -nologo -o "$BUILD_DIR/gt-cli"
"$BUILD_DIR/gt-cli/gt-cli" mirror --root "$PKG_DIR"
