#include "cli.hpp"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <utility>
#include <vector>

#include "check.hpp"
#include "inputs.hpp"

namespace gt {

namespace {

uint64_t parseUnsigned(const std::string& flag, const std::string& text, uint64_t maxValue) {
    if (text.empty() || text[0] == '-') fail(flag + ": expected a non-negative integer, got '" + text + "'");
    errno = 0;
    char* end = nullptr;
    unsigned long long v = std::strtoull(text.c_str(), &end, 10);
    if (errno != 0 || *end != '\0' || v > maxValue)
        fail(flag + ": expected an integer in [0, " + std::to_string(maxValue) + "], got '" + text + "'");
    return v;
}

// A finite number in [0, 1] for FLAG: a fraction of the range's size.
float parseFraction(const std::string& flag, const std::string& text) {
    char* end = nullptr;
    const float v = std::strtof(text.c_str(), &end);
    if (text.empty() || *end != '\0' || !std::isfinite(v) || v < 0.0f || v > 1.0f)
        fail(flag + ": expected a fraction in [0, 1], got '" + text + "'");
    return v;
}

std::array<float, 4> parseRange(const std::string& text) {
    std::array<float, 4> r{};
    std::stringstream ss(text);
    std::string item;
    int n = 0;
    while (std::getline(ss, item, ',')) {
        if (n == 4) fail("--range: expected 4 comma-separated numbers c,d,g,h, got '" + text + "'");
        char* end = nullptr;
        r[n] = std::strtof(item.c_str(), &end);
        if (item.empty() || *end != '\0' || !std::isfinite(r[n]))
            fail("--range: '" + item + "' is not a finite number (in '" + text + "')");
        ++n;
    }
    if (n != 4) fail("--range: expected 4 comma-separated numbers c,d,g,h, got '" + text + "'");
    if (!(r[0] < r[2]) || !(r[1] < r[3])) fail("--range: need c < g and d < h, got '" + text + "'");
    return r;
}

// "LEFT:RIGHT" split at the first colon (atLast: the last one, for a path that may hold colons).
std::pair<std::string, std::string> splitAtColon(const std::string& option, const std::string& form,
                                                 const std::string& value, bool atLast) {
    const size_t colon = atLast ? value.rfind(':') : value.find(':');
    if (colon == std::string::npos || colon == 0 || colon + 1 == value.size())
        fail(option + ": expected " + form + ", got '" + value + "'");
    return {value.substr(0, colon), value.substr(colon + 1)};
}

}  // namespace

// One numeric field of a compound value; the error names the option, the field and the whole value.
uint64_t parseField(const std::string& option, const std::string& value, const std::string& field,
                    const std::string& text, uint64_t minValue, uint64_t maxValue) {
    errno = 0;
    char* end = nullptr;
    const unsigned long long v = std::strtoull(text.c_str(), &end, 10);
    if (text.empty() || !std::isdigit(static_cast<unsigned char>(text[0])) || errno != 0 || *end != '\0' ||
        v < minValue || v > maxValue)
        fail(option + ": " + field + " '" + text + "' in '" + value + "' is not an integer in [" +
             std::to_string(minValue) + ", " + std::to_string(maxValue) + "]");
    return v;
}

namespace {
constexpr uint64_t kMaxStorageBinding = 1023;        // far above any real layout; catches typos
constexpr uint64_t kMaxStorageBytes = 0xffffffffull;  // maxStorageBufferRange is a uint32_t
}  // namespace

// The BINDING of a --storage, --storage-data, --image or --sampler value: not one of the rig's own.
uint32_t parseStorageBinding(const std::string& option, const std::string& value, const std::string& bindingText) {
    const auto binding = static_cast<uint32_t>(parseField(option, value, "BINDING", bindingText, 0, kMaxStorageBinding));
    if (const char* taken = rigBindingName(binding))
        fail(option + ": binding " + std::to_string(binding) + " in '" + value + "' is the rig's " + taken +
             " (bindings 0.." + std::to_string(kBindingCountSnow - 1) + " are taken)");
    return binding;
}

namespace {

StorageOption parseStorage(const std::string& value) {
    const std::string option = "--storage";
    const auto [bindingText, bytesText] = splitAtColon(option, "BINDING:BYTES", value, false);
    StorageOption s;
    s.binding = parseStorageBinding(option, value, bindingText);
    s.bytes = parseField(option, value, "BYTES", bytesText, 4, kMaxStorageBytes);
    if (s.bytes % 4 != 0)
        fail(option + ": BYTES " + bytesText + " in '" + value + "' is not a multiple of 4 (storage buffers hold 32-bit words)");
    return s;
}

// --storage-data BINDING:FILE: a storage buffer holding FILE's bytes (a non-zero multiple of 4;
// its size is checked when the file is read).
StorageOption parseStorageData(const std::string& value) {
    const std::string option = "--storage-data";
    const auto [bindingText, path] = splitAtColon(option, "BINDING:FILE", value, false);
    StorageOption s;
    s.binding = parseStorageBinding(option, value, bindingText);
    if (path.empty()) fail(option + ": FILE is empty in '" + value + "'");
    s.dataPath = path;
    return s;
}

ComputeOption parseCompute(const std::string& value) {
    const std::string option = "--compute";
    const auto [path, groupsText] = splitAtColon(option, "SPV:GX[,GY[,GZ]]", value, true);
    ComputeOption c;
    c.spec = value;
    c.path = path;
    static const char* fields[3] = {"GX", "GY", "GZ"};
    std::stringstream ss(groupsText);
    std::string item;
    size_t n = 0;
    while (std::getline(ss, item, ',')) {
        if (n == 3) fail(option + ": at most 3 work group counts GX,GY,GZ, got '" + value + "'");
        c.groups[n] = static_cast<uint32_t>(parseField(option, value, fields[n], item, 1, 0xffffffffull));
        ++n;
    }
    if (groupsText.back() == ',') fail(option + ": expected SPV:GX[,GY[,GZ]], got '" + value + "'");
    return c;
}

StorageDump parseDump(const std::string& value) {
    const std::string option = "--dump-storage";
    const auto [bindingText, path] = splitAtColon(option, "BINDING:FILE", value, false);
    StorageDump d;
    d.binding = static_cast<uint32_t>(parseField(option, value, "BINDING", bindingText, 0, kMaxStorageBinding));
    d.path = path;
    return d;
}

// --dump-storage-prefix BINDING:BYTES:FILE: the first BYTES (a non-zero multiple of 4).
StorageDump parseDumpPrefix(const std::string& value) {
    const std::string option = "--dump-storage-prefix";
    const auto [bindingText, rest] = splitAtColon(option, "BINDING:BYTES:FILE", value, false);
    const auto [bytesText, path] = splitAtColon(option, "BINDING:BYTES:FILE", rest, false);
    StorageDump d;
    d.binding = static_cast<uint32_t>(parseField(option, value, "BINDING", bindingText, 0, kMaxStorageBinding));
    d.path = path;
    d.bytes = parseField(option, value, "BYTES", bytesText, 4, 1ull << 40);
    if (d.bytes % 4 != 0) fail(option + ": BYTES must be a multiple of 4, got '" + value + "'");
    return d;
}

// A second --storage at the same binding would leave the shaders' view ambiguous: refuse it.
void addStorage(Options& o, const std::string& value, bool data = false) {
    const StorageOption s = data ? parseStorageData(value) : parseStorage(value);
    for (const StorageOption& earlier : o.storage)
        if (earlier.binding == s.binding)
            fail("--storage: binding " + std::to_string(s.binding) + " in '" + value + "' is already given (" +
                 std::to_string(earlier.binding) + ":" + std::to_string(earlier.bytes) + ")");
    o.storage.push_back(s);
}

// Each --dump-storage names a --storage buffer (checked after all options, in any order).
void checkDumps(const Options& o) {
    for (const StorageDump& d : o.dumps) {
        bool found = false;
        for (const StorageOption& s : o.storage) found |= s.binding == d.binding;
        if (!found)
            fail("--dump-storage: binding " + std::to_string(d.binding) + " in '" + std::to_string(d.binding) + ":" + d.path +
                 "' has no --storage buffer");
        for (const StorageOption& s : o.storage)
            if (s.binding == d.binding && d.bytes > s.bytes)
                fail("--dump-storage-prefix: " + std::to_string(d.bytes) + " bytes of binding " + std::to_string(d.binding) +
                     " for '" + d.path + "', but its --storage buffer holds " + std::to_string(s.bytes));
    }
}

}  // namespace

const char* usageText() {
    return R"(gt-harness: run SPIR-V terrain shaders headless on a Vulkan device.

  --batch FILE                   (alone) one run per line of FILE, options tab-separated, over one
                                 device, each distinct pipeline created once (README.md)
  --list-devices                 list physical devices and exit
  --device SUBSTR                pick the device whose name contains SUBSTR (case-insensitive)
  --uniform-blocks auto|uniform|storage   bind TerrainParams (b0) and the camera (b1) as compiled
                                 (uniform) or as storage buffers, the shaders' blocks rewritten to
                                 match (storage: lavapipe does not inline their values and compile
                                 the pipeline again per scene); auto (default): storage on lavapipe
  --vert F --tesc F --tese F --frag F   SPIR-V stages (no tesc/tese: fallback grid mode)
  --entry-vert/--entry-tesc/--entry-tese/--entry-frag NAME
                                 entry points (default: the module's only one, else
                                 vert / hull_shader / domain_shader / frag)
  --buffers DIR                  control_points.f32 regions.f32 grid_lines.f32 params.f32 camera.f32
  --range c,d,g,h                overrides _Range (first float4 of params.f32)
  --snow-depth F --snow-params F GT_SNOW: R*R float depth map at binding 6, and _SnowMapSize
                                 (16 bytes) appended to TerrainParams at binding 0
  --params-tail F                GT_LOD: F's bytes (a multiple of 16, at most 1024) appended to
                                 TerrainParams at binding 0 (_LodLevels, _Ranges[])
  --params-tail-path F           GT_LOD moving: F holds N records of --params-tail's size; frame f
                                 writes record f mod N after TerrainParams (the levels following a camera)
  --patches N                    patches drawn (tessellated mode)
  --control-points K             control points per patch (default 4)
  --grid-factor F --instances N  fallback mode: (F+1)^2-vertex grid, N instances
  --grid-indices I.u32           fallback mode: the grid's 2 F^2 triangles in this order instead of
                                 row by row (checked to be the same triangles, same winding)
  --static-mesh --mesh P.f32 I.u32   draw a static float3/uint32 mesh with --vert/--frag
  --width W --height H           render target size (default 256x256)
  --png FILE                     write the colour image as PNG
  --depth-out FILE               write the depth attachment after the last frame: W*H float32,
                                 row-major, top row first (the PNG's order)
  --depth-in FILE                the depth attachment starts as FILE (--depth-out's layout) instead
                                 of the clear: a depth prepass's depth kept for the next pass (one frame)
  --color-format R8G8B8A8_UNORM|R8G8B8A8_SNORM   the colour attachment (default UNORM); --png
                                 writes its bytes as stored (SNORM: two's complement)
  --target1 R8_UNORM|R16_UNORM|R32_SFLOAT:FILE   a second colour attachment (SV_Target1), cleared
                                 to 0, its raw texels written to FILE after the last frame
  --wireframe                    polygonMode LINE (needs fillModeNonSolid)
  --cull back|front|off          the drawn pass's render state, in ShaderLab's words (any case);
  --ztest less|lequal|equal|gequal|greater|notequal|always|never
  --zwrite on|off  --zclip on|off   defaults: ShaderLab's, Cull Back, ZTest LEqual, ZWrite On,
  --color-mask 0|RGBA|RGB|R|...  ZClip On, ColorMask RGBA. Front faces are clockwise in the
                                 (upright) image, as in Unity; ZClip off clamps depth
  --depth-bias UNITS,SLOPE       Unity's depth bias (SetGlobalDepthBias(bias, slopeBias); ShaderLab's
                                 Offset SLOPE, UNITS): away from the viewer, negated when reversed
  --stencil "Ref 1 WriteMask 9 Comp Always Pass Replace"   the pass's ShaderLab Stencil block (its
                                 body; Ref ReadMask WriteMask 0..255, Comp Pass Fail ZFail, each also
                                 with Front or Back): a D32_SFLOAT_S8_UINT attachment, stencil cleared
                                 to 0; without it D32 and no stencil test, as Unity's default
  --stencil-out FILE             write the stencil after the last frame: W*H bytes, top row first
  --stencil-in FILE              the stencil starts as FILE (--stencil-out's layout; one frame)
  --depth reversed|forward       depth convention (default reversed, as Unity on Vulkan: near 1,
                                 far 0, cleared to 0, ZTest turned around: LEqual draws GEQUAL);
                                 the camera's projection must use the same one
  --storage BINDING:BYTES        zero-filled device-local storage buffer at BINDING (>= 7), repeatable
  --storage-data BINDING:FILE    the same holding FILE's bytes (e.g. the tiled noise's table at 9)
  --image BINDING:FILE:FORMAT:W:H[:LAYERS]   a sampled 2D image (2D array with LAYERS) at BINDING,
                                 uploaded from FILE's raw texels; FORMAT R32_SFLOAT, R32G32_SFLOAT,
                                 R32G32B32A32_SFLOAT, R16G16B16A16_SFLOAT, R8G8B8A8_UNORM, R8G8B8A8_SRGB,
                                 D32 (a depth map, for comparison samplers); repeatable
  --sampler BINDING:linear|point[:clamp|repeat][:compare-OP]   a separate sampler at BINDING
                                 (default clamp); compare-less|lequal|greater|gequal|equal|notequal|
                                 always|never: a comparison sampler, passing when (reference OP texel)
  --compute SPV:GX[,GY[,GZ]]     each frame, before the render pass, dispatch the module's compute
                                 entry point over GX x GY x GZ groups; repeatable, run in order
  --dump-storage BINDING:FILE    write that storage buffer's bytes after the last frame, repeatable
  --dump-storage-prefix BINDING:BYTES:FILE   the same, its first BYTES only
  --readback FILE --readback-floats K   storage buffer of K floats at binding 5, dumped to FILE
  --readback-fill nan|zero       initial readback contents (default nan)
  --stats                        pipeline statistics of the last frame ("stat NAME VALUE")
  --frames N --warmup K          draw N measured frames after K warm-up frames
  --timestamps                   GPU time of each frame ("time ..." lines; with --compute also
                                 the compute part alone: "time compute_ms ...")
  --range-pan FRACTION           with --update-range-per-frame: pan the range to and fro by FRACTION
                                 sin(2 pi f / 100) of its size (diagonally) instead of the tiny shifts
  --update-range-per-frame       write a new _Range into the uniform buffer every frame (the last
                                 frame: the inputs' own range)
  --camera-path FILE             a moving camera: FILE holds N RigCamera blocks (176 bytes each, the
                                 layout of camera.f32); frame f draws with block f mod N
  --params-path FILE             frame f writes record f mod N of FILE into TerrainParams: the
                                 params.f32 block, then a float4 whose x = 1 runs the --compute
                                 passes that frame (0 reuses what they wrote; frame 0 always runs them)
  --compute-once                 run the --compute passes in the first frame only (later frames reuse their output)
  --no-compute-timestamp         with --timestamps, time only the whole frame (no timestamp between
                                 the --compute passes and the draw, so no "time compute_ms" lines)
  --resend-bytes B               re-upload B bytes through a staging copy every frame
  --placement-pad BYTES          allocate BYTES of device memory before the job's own buffers, so that
                                 they land elsewhere (where buffers land moves a frame: performance.md)
  --in-flight N                  N (1-3) frames queued at once, each with its own TerrainParams and
                                 --storage buffers (--dump-storage: the last frame's); frame_ms is then
                                 the period between frame ends (default 1: each frame waits for the last)
  --async-compute                with --in-flight >= 2: the --compute passes go to a queue of a
                                 compute-only family, alongside the graphics queue
  --max-vertices-per-draw V      split tessellated draws so each stays <= V generated vertices
                                 (default 65536 on lavapipe, 0 = no split elsewhere)
  --max-factor F                 per-patch tessellation factor bound for the split ((F+1)^2 vertices)
  --help
)";
}

namespace {
UniformBlocks parseUniformBlocks(const std::string& option, const std::string& v) {
    if (v == "auto") return UniformBlocks::Auto;
    if (v == "uniform") return UniformBlocks::Uniform;
    if (v == "storage") return UniformBlocks::Storage;
    fail(option + " '" + v + "': expected auto, uniform or storage");
}

// The colour attachments a pipeline's pass draws into that the rig reads back (4 bytes a texel).
VkFormat parseColorFormat(const std::string& option, const std::string& v) {
    if (v == "R8G8B8A8_UNORM") return VK_FORMAT_R8G8B8A8_UNORM;
    if (v == "R8G8B8A8_SNORM") return VK_FORMAT_R8G8B8A8_SNORM;
    fail(option + ": expected R8G8B8A8_UNORM or R8G8B8A8_SNORM, got '" + v + "'");
}

// --target1 FORMAT:FILE: the single-channel formats URP 14 gives its rendering-layers texture
// (RenderingLayerUtils.GetFormat: 8, 16, 24/32 bits).
void parseTarget1(Options& o, const std::string& option, const std::string& v) {
    const size_t colon = v.find(':');
    const std::string format = v.substr(0, colon);
    if (format == "R8_UNORM") o.target1Format = VK_FORMAT_R8_UNORM;
    else if (format == "R16_UNORM") o.target1Format = VK_FORMAT_R16_UNORM;
    else if (format == "R32_SFLOAT") o.target1Format = VK_FORMAT_R32_SFLOAT;
    else fail(option + ": expected R8_UNORM, R16_UNORM or R32_SFLOAT before ':FILE', got '" + v + "'");
    if (colon == std::string::npos || colon + 1 == v.size()) fail(option + ": expected FORMAT:FILE, got '" + v + "'");
    o.target1Path = v.substr(colon + 1);
}
}  // namespace

Options parseOptions(int argc, char** argv) {
    Options o;
    bool staticMesh = false;
    std::vector<std::string> args(argv + 1, argv + argc);
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        auto value = [&]() -> const std::string& {
            if (i + 1 >= args.size()) fail(a + ": missing value");
            return args[++i];
        };
        auto u32 = [&](uint64_t maxValue = 0xffffffffull) { return static_cast<uint32_t>(parseUnsigned(a, value(), maxValue)); };
        if (a == "--help" || a == "-h") { std::fputs(usageText(), stdout); std::exit(0); }
        else if (a == "--list-devices") o.listDevices = true;
        else if (a == "--device") o.deviceSubstring = value();
        else if (a == "--uniform-blocks") o.uniformBlocks = parseUniformBlocks(a, value());
        else if (a == "--vert") o.vertPath = value();
        else if (a == "--tesc") o.tescPath = value();
        else if (a == "--tese") o.tesePath = value();
        else if (a == "--frag") o.fragPath = value();
        else if (a == "--entry-vert") o.vertEntry = value();
        else if (a == "--entry-tesc") o.tescEntry = value();
        else if (a == "--entry-tese") o.teseEntry = value();
        else if (a == "--entry-frag") o.fragEntry = value();
        else if (a == "--buffers") o.buffersDir = value();
        else if (a == "--range") o.range = parseRange(value());
        else if (a == "--snow-depth") o.snowDepthPath = value();
        else if (a == "--snow-params") o.snowParamsPath = value();
        else if (a == "--params-tail") o.paramsTailPath = value();
        else if (a == "--params-tail-path") o.movingTailPath = value();
        else if (a == "--patches") o.patches = u32();
        else if (a == "--control-points") o.controlPoints = u32(32);
        else if (a == "--grid-factor") o.gridFactor = u32(4096);
        else if (a == "--instances") o.instances = u32();
        else if (a == "--grid-indices") o.gridIndicesPath = value();
        else if (a == "--params-path") o.paramsPath = value();
        else if (a == "--static-mesh") staticMesh = true;
        else if (a == "--mesh") { o.meshPositions = value(); o.meshIndices = value(); }
        else if (a == "--width") o.width = u32(16384);
        else if (a == "--height") o.height = u32(16384);
        else if (a == "--png") o.pngPath = value();
        else if (a == "--depth-out") o.depthOutPath = value();
        else if (a == "--depth-in") o.depthInPath = value();
        else if (a == "--color-format") o.colorFormat = parseColorFormat(a, value());
        else if (a == "--target1") parseTarget1(o, a, value());
        else if (a == "--wireframe") o.wireframe = true;
        else if (a == "--cull") o.state.cull = parseCull(a, value());
        else if (a == "--ztest") o.state.zTest = parseZTest(a, value());
        else if (a == "--zwrite") o.state.zWrite = parseOnOff(a, value());
        else if (a == "--zclip") o.state.zClip = parseOnOff(a, value());
        else if (a == "--depth-bias") parseDepthBias(a, value(), o.state);
        else if (a == "--color-mask") o.state.colorMask = parseColorMask(a, value());
        else if (a == "--stencil") o.state.stencil = parseStencil(a, value());
        else if (a == "--stencil-out") o.stencilOutPath = value();
        else if (a == "--stencil-in") o.stencilInPath = value();
        else if (a == "--depth") o.state.depth = parseDepth(a, value());
        else if (a == "--storage") addStorage(o, value());
        else if (a == "--storage-data") addStorage(o, value(), true);
        else if (a == "--image") o.images.push_back(parseImageOption(value()));
        else if (a == "--sampler") o.samplers.push_back(parseSamplerOption(value()));
        else if (a == "--compute") o.computes.push_back(parseCompute(value()));
        else if (a == "--dump-storage") o.dumps.push_back(parseDump(value()));
        else if (a == "--dump-storage-prefix") o.dumps.push_back(parseDumpPrefix(value()));
        else if (a == "--readback") o.readbackPath = value();
        else if (a == "--readback-floats") o.readbackFloats = parseUnsigned(a, value(), 1ull << 32);
        else if (a == "--readback-fill") {
            const std::string& v = value();
            if (v == "nan") o.readbackFillNan = true;
            else if (v == "zero") o.readbackFillNan = false;
            else fail("--readback-fill: expected 'nan' or 'zero', got '" + v + "'");
        }
        else if (a == "--stats") o.stats = true;
        else if (a == "--frames") o.frames = u32(1000000);
        else if (a == "--warmup") o.warmup = u32(1000000);
        else if (a == "--timestamps") o.timestamps = true;
        else if (a == "--update-range-per-frame") o.updateRangePerFrame = true;
        else if (a == "--range-pan") o.rangePan = parseFraction(a, value());
        else if (a == "--compute-once") o.computeOnce = true;
        else if (a == "--no-compute-timestamp") o.computeTimestamp = false;
        else if (a == "--camera-path") o.cameraPath = value();
        else if (a == "--in-flight") o.inFlight = u32(3);
        else if (a == "--async-compute") o.asyncCompute = true;
        else if (a == "--resend-bytes") o.resendBytes = parseUnsigned(a, value(), 1ull << 34);
        else if (a == "--placement-pad") o.placementPad = parseUnsigned(a, value(), 1ull << 34);
        else if (a == "--max-vertices-per-draw") o.maxVerticesPerDraw = parseUnsigned(a, value(), 1ull << 40);
        else if (a == "--max-factor") o.maxFactor = u32(4096);
        else fail("unknown argument '" + a + "' (see --help)");
    }
    if (o.listDevices) return o;

    if (o.vertPath.empty()) fail("--vert is required (see --help)");
    if (o.fragPath.empty()) fail("--frag is required (see --help)");
    if (o.buffersDir.empty()) fail("--buffers DIR is required (see --help)");
    if (o.frames == 0) fail("--frames: must be at least 1");
    if (o.width == 0 || o.height == 0) fail("--width/--height: must be at least 1");
    if (!o.paramsTailPath.empty() && !o.snowParamsPath.empty()) fail("--params-tail (GT_LOD) and --snow-params (GT_SNOW) do not combine");
    if (o.snowDepthPath.empty() != o.snowParamsPath.empty())
        fail("--snow-depth and --snow-params go together: give both or neither");
    if (o.tescPath.empty() != o.tesePath.empty()) fail("--tesc and --tese go together: give both or neither");
    if (!o.readbackPath.empty() && o.readbackFloats == 0) fail("--readback needs --readback-floats K (K > 0)");
    if (o.readbackPath.empty() && o.readbackFloats != 0) fail("--readback-floats needs --readback FILE");
    if (o.computeOnce && o.computes.empty()) fail("--compute-once needs at least one --compute SPV:GX,GY,GZ");
    if (!o.movingTailPath.empty() && o.paramsTailPath.empty()) fail("--params-tail-path needs --params-tail (its first record's size)");
    if (!o.paramsPath.empty() && o.updateRangePerFrame) fail("--params-path writes the whole TerrainParams every frame: drop --update-range-per-frame");
    if (!o.paramsPath.empty() && o.computeOnce) fail("--params-path decides per frame whether the --compute passes run: drop --compute-once");
    if (o.rangePan > 0.0f && !o.updateRangePerFrame) fail("--range-pan needs --update-range-per-frame");
    if (!o.computeTimestamp && o.inFlight > 1) fail("--no-compute-timestamp is for one frame in flight (--in-flight " + std::to_string(o.inFlight) + " given)");
    checkDumps(o);
    if (!o.depthOutPath.empty() && o.depthOutPath == o.pngPath)
        fail("--depth-out '" + o.depthOutPath + "' is also the --png file: give them different names");
    if (!o.depthInPath.empty() && o.frames != 1)
        fail("--depth-in loads the depth once: --frames must be 1 (" + std::to_string(o.frames) + " given)");
    for (const auto& [name, path] : {std::pair<const char*, const std::string&>{"--stencil-out", o.stencilOutPath},
                                     {"--stencil-in", o.stencilInPath}})
        if (!path.empty() && !o.state.stencil.enabled)
            fail(std::string(name) + " '" + path + "' needs the pass's stencil state: give --stencil");
    if (!o.stencilOutPath.empty() && (o.stencilOutPath == o.pngPath || o.stencilOutPath == o.depthOutPath))
        fail("--stencil-out '" + o.stencilOutPath + "' is also the --png or --depth-out file: give them different names");
    if (!o.stencilInPath.empty() && o.frames != 1)
        fail("--stencil-in loads the stencil once: --frames must be 1 (" + std::to_string(o.frames) + " given)");
    std::vector<uint32_t> storageBindings;
    for (const StorageOption& s : o.storage) storageBindings.push_back(s.binding);
    checkImageBindings(o.images, o.samplers, storageBindings);
    if (o.inFlight == 0) fail("--in-flight: must be at least 1");
    if (o.inFlight > 1) {
        // Each of these has one buffer that every frame would write or read at once.
        if (o.resendBytes) fail("--in-flight " + std::to_string(o.inFlight) + " cannot be combined with --resend-bytes");
        if (!o.readbackPath.empty()) fail("--in-flight " + std::to_string(o.inFlight) + " cannot be combined with --readback");
        if (!o.cameraPath.empty()) fail("--in-flight " + std::to_string(o.inFlight) + " cannot be combined with --camera-path");
        if (!o.paramsPath.empty()) fail("--in-flight " + std::to_string(o.inFlight) + " cannot be combined with --params-path");
        if (!o.movingTailPath.empty()) fail("--in-flight " + std::to_string(o.inFlight) + " cannot be combined with --params-tail-path");
    }
    if (o.asyncCompute && o.computes.empty()) fail("--async-compute needs at least one --compute SPV:GX,GY,GZ");
    if (o.asyncCompute && o.inFlight < 2)
        fail("--async-compute needs --in-flight 2 or more (with one frame at a time there is nothing to overlap)");

    if (staticMesh) {
        o.mode = Mode::StaticMesh;
        if (o.meshPositions.empty()) fail("--static-mesh needs --mesh positions.f32 indices.u32");
        if (!o.tescPath.empty()) fail("--static-mesh draws without tessellation: drop --tesc/--tese");
    } else if (o.tescPath.empty()) {
        o.mode = Mode::Fallback;
        if (o.gridFactor == 0) fail("fallback mode (no --tesc/--tese) needs --grid-factor F (F >= 1)");
        if (o.instances == 0) fail("--instances: must be at least 1");
    } else {
        o.mode = Mode::Tessellated;
        if (o.patches == 0) fail("tessellated mode needs --patches N (N >= 1)");
        if (o.controlPoints == 0) fail("--control-points: must be at least 1");
    }
    if (!o.gridIndicesPath.empty() && o.mode != Mode::Fallback)
        fail("--grid-indices reorders the fallback grid (--grid-factor F without --tesc/--tese)");
    return o;
}

}  // namespace gt
