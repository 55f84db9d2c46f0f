# gt pipeline_pass_all: every variant of every pass of each pipeline's tessellated SubShader drawn once by the harness,
# bindings filled by name from the scene (Tools~/rig/pipeline_pass_all.py says how), then the AllVariants tests. Needs gt
# setup. Not part of gt test.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
python3 "$RIG_DIR/pipeline_pass_all.py" "$@"
# Then the AllVariants test category (gt test leaves it out): URP's cascades drawn for real, 2 and 4 of them
# (PipelinePassCascadeTests), unless the run was narrowed (--list, --pass, --keyword, or --pipeline without URP).
args=" $* "
[[ $args == *" --list "* || $args == *" --pass "* || $args == *" --keyword "* ]] && exit 0
[[ $args == *" --pipeline "* && $args != *" --pipeline URP "* ]] && exit 0
dotnet test "$TOOLS_DIR/dotnet/Tests/GregoryTerrain.Tests.csproj" -c Release --no-build -nologo -o "$BUILD_DIR/tests" \
  --filter "TestCategory=AllVariants" --logger "console;verbosity=normal"
