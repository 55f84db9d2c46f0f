# gt unity-api: compiles Runtime/, Editor/ and the Samples~ scripts against the hand-written Unity API
# stubs in Tools~/UnityApiCheck (a stub from the documentation, not Unity's assemblies; see its README).
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
say "unity-api: building Tools~/UnityApiCheck"
dotnet build "$TOOLS_DIR/UnityApiCheck/UnityApiCheck.csproj" -c Release -nologo "$@"
