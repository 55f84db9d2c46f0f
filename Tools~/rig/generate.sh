# gt generate: writes the generated side of each CPU<->GPU contract Core declares once with
# [GenerateHlsl] (TerrainParams: Shaders/Terrain/TerrainParams.cs.hlsl and its C# names) and the
# shader's keyword pragmas from ShaderKeywords.Sets, then the .meta of any new file. Commit what it writes; GeneratedContractTests fails on a stale one.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
[ $# -eq 0 ] || usage_error generate "takes no options (got '$1')"
# Built here, not only by setup: the declarations it reads are Core's current source.
dotnet build "$TOOLS_DIR/dotnet/Gt/Gt.csproj" -c Release -v quiet -nologo -o "$BUILD_DIR/gt-cli" >/dev/null \
  || dotnet build "$TOOLS_DIR/dotnet/Gt/Gt.csproj" -c Release -nologo -o "$BUILD_DIR/gt-cli"
"$BUILD_DIR/gt-cli/gt-cli" generate --root "$PKG_DIR"
python3 "$RIG_DIR/metas.py" "$PKG_DIR"
