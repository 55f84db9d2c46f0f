#include "inputs.hpp"

#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include "check.hpp"

namespace gt {

namespace {

// TerrainParams and the camera: bound as uniform or storage buffers (--uniform-blocks), so both.
constexpr VkBufferUsageFlags kUniformBlockUsage = VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;

std::vector<uint8_t> readSized(const std::string& path, size_t exact, size_t multiple) {
    std::vector<uint8_t> bytes = readFile(path);
    if (exact && bytes.size() != exact)
        fail("'" + path + "' has " + std::to_string(bytes.size()) + " bytes; expected exactly " + std::to_string(exact));
    if (multiple && (bytes.empty() || bytes.size() % multiple != 0))
        fail("'" + path + "' has " + std::to_string(bytes.size()) + " bytes; expected a non-zero multiple of " +
             std::to_string(multiple));
    return bytes;
}

}  // namespace

Inputs loadInputs(const Gpu& gpu, const std::string& dir, const std::optional<std::array<float, 4>>& range,
                  uint64_t readbackFloats, bool fillNan, const std::string& snowDepth, const std::string& snowParams,
                  const std::string& paramsTail) {
    const std::string d = dir + "/";
    std::vector<uint8_t> params = readSized(d + "params.f32", kParamsBytes, 0);
    std::vector<uint8_t> camera = readSized(d + "camera.f32", kCameraBytes, 0);
    std::vector<uint8_t> points = readSized(d + "control_points.f32", 0, kPatchBytes);
    std::vector<uint8_t> regions = readSized(d + "regions.f32", 0, 16);
    std::vector<uint8_t> lines = readSized(d + "grid_lines.f32", 0, 4);
    if (regions.size() / 16 != points.size() / kPatchBytes)
        fail("control_points.f32 holds " + std::to_string(points.size() / kPatchBytes) + " patches but regions.f32 holds " +
             std::to_string(regions.size() / 16) + " regions");

    Inputs in;
    in.gregoryPatches = static_cast<uint32_t>(points.size() / kPatchBytes);
    std::memcpy(in.params.data(), params.data(), kParamsBytes);
    if (range) std::copy(range->begin(), range->end(), in.params.begin());

    // GT_SNOW: _SnowMapSize follows TerrainParams' eleven float4 in the same cbuffer.
    std::vector<uint8_t> snowSize, depth;
    if (!snowParams.empty()) {
        snowSize = readSized(snowParams, kSnowParamsBytes, 0);
        float r = 0;
        std::memcpy(&r, snowSize.data(), 4);
        if (!(r >= 1 && r <= 65536) || r != std::floor(r))
            fail("'" + snowParams + "': _SnowMapSize.x (R) must be a whole number in [1, 65536], got " + std::to_string(r));
        in.snow = true;
        in.snowResolution = static_cast<uint32_t>(r);
        depth = readSized(snowDepth, size_t(in.snowResolution) * in.snowResolution * 4, 0);
    }
    // GT_LOD: _LodLevels and _Ranges[] follow TerrainParams' eleven float4 in the same cbuffer.
    std::vector<uint8_t> tail;
    if (!paramsTail.empty()) {
        tail = readSized(paramsTail, 0, 16);
        if (tail.empty() || tail.size() > 1024)
            fail("'" + paramsTail + "': --params-tail holds " + std::to_string(tail.size()) + " bytes; it must hold 16 to 1024");
    }
    const size_t paramsBytes = kParamsBytes + (in.snow ? kSnowParamsBytes : 0) + tail.size();

    const VkBufferUsageFlags storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    in.bindings[kBindingParams] = createHostBuffer(gpu, paramsBytes, kUniformBlockUsage, true);
    std::memcpy(in.bindings[kBindingParams].mapped, in.params.data(), kParamsBytes);
    if (in.snow)
        std::memcpy(static_cast<uint8_t*>(in.bindings[kBindingParams].mapped) + kParamsBytes, snowSize.data(), kSnowParamsBytes);
    in.tailBytes = tail.size();
    if (!tail.empty())
        std::memcpy(static_cast<uint8_t*>(in.bindings[kBindingParams].mapped) + kParamsBytes, tail.data(), tail.size());
    in.bindings[kBindingCamera] = createDeviceBuffer(gpu, camera, kUniformBlockUsage);
    in.bindings[kBindingControlPoints] = createDeviceBuffer(gpu, points, storage);
    in.bindings[kBindingRegions] = createDeviceBuffer(gpu, regions, storage);
    in.bindings[kBindingGridLines] = createDeviceBuffer(gpu, lines, storage);

    // Readback: host-visible so the dump is a plain memcpy; pre-filled so unwritten slots show.
    const uint64_t floats = readbackFloats ? readbackFloats : 4;
    Buffer& rb = in.bindings[kBindingReadback];
    rb = createHostBuffer(gpu, floats * 4, storage);
    const float fill = fillNan ? std::numeric_limits<float>::quiet_NaN() : 0.0f;
    float* f = static_cast<float*>(rb.mapped);
    for (uint64_t i = 0; i < rb.size / 4; ++i) f[i] = fill;
    if (in.snow) in.bindings[kBindingSnowDepth] = createDeviceBuffer(gpu, depth, storage);
    return in;
}

void destroyInputs(const Gpu& gpu, Inputs& inputs) {
    for (Buffer& b : inputs.bindings) destroyBuffer(gpu, b);
}

Inputs copyWithOwnParams(const Gpu& gpu, const Inputs& inputs) {
    Inputs copy = inputs;
    const Buffer& from = inputs.bindings[kBindingParams];
    copy.bindings[kBindingParams] = createHostBuffer(gpu, from.size, kUniformBlockUsage, true);
    std::memcpy(copy.bindings[kBindingParams].mapped, from.mapped, from.size);
    return copy;
}

void destroyParamsCopy(const Gpu& gpu, Inputs& copy) {
    destroyBuffer(gpu, copy.bindings[kBindingParams]);
    copy = Inputs{};
}

const char* rigBindingName(uint32_t binding) {
    static const char* names[kBindingCountSnow] = {"TerrainParams", "RigCamera", "_ControlPoints", "_Regions",
                                                   "_GridLines", "_Readback", "_SnowDepth"};
    return binding < kBindingCountSnow ? names[binding] : nullptr;
}

std::vector<uint8_t> loadCameraPath(const Gpu& gpu, Inputs& inputs, const std::string& path) {
    std::vector<uint8_t> blocks = readSized(path, 0, kCameraBytes);
    destroyBuffer(gpu, inputs.bindings[kBindingCamera]);
    inputs.bindings[kBindingCamera] = createHostBuffer(gpu, kCameraBytes, kUniformBlockUsage, true);
    writeCamera(inputs, blocks, 0);
    return blocks;
}

void writeCamera(Inputs& inputs, const std::vector<uint8_t>& path, uint32_t frame) {
    const size_t block = frame % (path.size() / kCameraBytes);
    std::memcpy(inputs.bindings[kBindingCamera].mapped, path.data() + block * kCameraBytes, kCameraBytes);
}

void writeRange(Inputs& inputs, const std::array<float, 4>& range) {
    std::copy(range.begin(), range.end(), inputs.params.begin());
    std::memcpy(inputs.bindings[kBindingParams].mapped, range.data(), 16);
}

std::vector<uint8_t> loadParamsPath(Inputs& inputs, const std::string& path) {
    std::vector<uint8_t> records = readSized(path, 0, kParamsRecordBytes);
    for (size_t r = 0; r < records.size() / kParamsRecordBytes; ++r) {
        float flag;
        std::memcpy(&flag, records.data() + r * kParamsRecordBytes + kParamsBytes, 4);
        if (flag != 0.0f && flag != 1.0f)
            fail("--params-path '" + path + "': record " + std::to_string(r) + " has dispatch flag " +
                 std::to_string(flag) + " (expected 0 or 1)");
    }
    writeParams(inputs, records, 0);
    return records;
}

bool writeParams(Inputs& inputs, const std::vector<uint8_t>& path, uint32_t frame) {
    const size_t record = frame % (path.size() / kParamsRecordBytes);
    const uint8_t* p = path.data() + record * kParamsRecordBytes;
    std::memcpy(inputs.params.data(), p, kParamsBytes);
    std::memcpy(inputs.bindings[kBindingParams].mapped, p, kParamsBytes);
    float flag;
    std::memcpy(&flag, p + kParamsBytes, 4);
    return flag != 0.0f;
}

std::vector<uint8_t> loadParamsTailPath(Inputs& inputs, const std::string& path) {
    if (inputs.tailBytes == 0) fail("--params-tail-path '" + path + "' needs --params-tail");
    std::vector<uint8_t> records = readSized(path, 0, inputs.tailBytes);
    writeParamsTail(inputs, records, 0);
    return records;
}

void writeParamsTail(Inputs& inputs, const std::vector<uint8_t>& path, uint32_t frame) {
    const size_t record = frame % (path.size() / inputs.tailBytes);
    std::memcpy(static_cast<uint8_t*>(inputs.bindings[kBindingParams].mapped) + kParamsBytes,
                path.data() + record * inputs.tailBytes, inputs.tailBytes);
}

}  // namespace gt
