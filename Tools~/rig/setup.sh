# gt setup: installs what the rig needs on a fresh Debian machine, then restores and builds.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

APT_PACKAGES=(glslang-tools spirv-tools spirv-cross mesa-vulkan-drivers libvulkan-dev libvulkan1
              vulkan-tools libpng-dev cmake g++ python3-matplotlib python3-numpy optipng)

missing=()
for p in "${APT_PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  say "installing: ${missing[*]}"
  if [ "$(id -u)" -ne 0 ]; then SUDO=sudo; else SUDO=; fi
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
for tool in glslangValidator spirv-val spirv-cross dotnet cmake; do
  command -v "$tool" >/dev/null || die "$tool is not on PATH after setup"
done

say "restoring and building the C# projects"
dotnet build "$TOOLS_DIR/dotnet/Tests/GregoryTerrain.Tests.csproj" -c Release -v quiet -nologo \
  -o "$BUILD_DIR/tests" >/dev/null || dotnet build "$TOOLS_DIR/dotnet/Tests/GregoryTerrain.Tests.csproj" -c Release -nologo -o "$BUILD_DIR/tests"
dotnet build "$TOOLS_DIR/dotnet/Gt/Gt.csproj" -c Release -v quiet -nologo -o "$BUILD_DIR/gt-cli" >/dev/null \
  || dotnet build "$TOOLS_DIR/dotnet/Gt/Gt.csproj" -c Release -nologo -o "$BUILD_DIR/gt-cli"

if [ -f "$TOOLS_DIR/harness/CMakeLists.txt" ]; then
  say "building the Vulkan harness"
  cmake -S "$TOOLS_DIR/harness" -B "$BUILD_DIR/harness" -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$BUILD_DIR/harness" -j "$(nproc)" >/dev/null || cmake --build "$BUILD_DIR/harness"
fi
if [ -f "$TOOLS_DIR/computerig/CMakeLists.txt" ]; then
  say "building the Vulkan compute runner"
  cmake -S "$TOOLS_DIR/computerig" -B "$BUILD_DIR/computerig" -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$BUILD_DIR/computerig" -j "$(nproc)" >/dev/null || cmake --build "$BUILD_DIR/computerig"
fi
say "setup done"
