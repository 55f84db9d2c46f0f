// The rig's input files (little-endian float32, written by the C# rig's GpuLayout) and the six
// descriptor bindings of Tools~/rig/README.md "Descriptor bindings".
#pragma once
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "buffers.hpp"

namespace gt {

constexpr uint32_t kBindingParams = 0;         // b0 TerrainParams, 10 float4
constexpr uint32_t kBindingCamera = 1;         // b1 RigCamera
constexpr uint32_t kBindingControlPoints = 2;  // t0 StructuredBuffer<float4>, 20 per patch
constexpr uint32_t kBindingRegions = 3;        // t1 StructuredBuffer<float4>
constexpr uint32_t kBindingGridLines = 4;      // t2 StructuredBuffer<float>
constexpr uint32_t kBindingReadback = 5;       // u0 RWStructuredBuffer<float4> (rig only)
constexpr uint32_t kBindingSnowDepth = 6;      // t4 StructuredBuffer<float> (GT_SNOW only)
constexpr uint32_t kBindingCount = 6;          // without snow
constexpr uint32_t kBindingCountSnow = 7;      // with --snow-depth

constexpr size_t kParamsBytes = 11 * 16;            // _Range .. _OriginSurface
constexpr size_t kCameraBytes = 2 * 64 + 3 * 16;    // two float4x4 + three float4
constexpr size_t kPatchBytes = 20 * 16;             // 20 float4 control points
constexpr size_t kSnowParamsBytes = 16;             // _SnowMapSize = (R, 1/R, depthCap, 0)

struct Inputs {
    std::array<Buffer, kBindingCountSnow> bindings;
    std::array<float, kParamsBytes / 4> params{};  // the CPU copy of TerrainParams (range patched)
    uint32_t gregoryPatches = 0;                    // control_points.f32 / 320 bytes
    bool snow = false;                              // --snow-depth given: binding 6 exists, params + 16 bytes
    uint32_t snowResolution = 0;                    // R of the snow map
    size_t tailBytes = 0;                           // --params-tail's bytes after TerrainParams (GT_LOD)
    uint32_t bindingCount() const { return snow ? kBindingCountSnow : kBindingCount; }
};

// Reads DIR/{params,camera,control_points,regions,grid_lines}.f32, checks their sizes, patches
// _Range, uploads. params is host-visible (the per-frame range goes there); the readback
// buffer (binding 5) holds readbackFloats floats (a 16-byte dummy when 0), pre-filled.
// With snowDepth/snowParams (both or neither, GT_SNOW variants): snowParams' 16 bytes are appended
// to TerrainParams (binding 0 grows to 192 bytes) and snowDepth (R*R floats, R = its first float)
// goes to binding 6.
Inputs loadInputs(const Gpu& gpu, const std::string& dir, const std::optional<std::array<float, 4>>& range,
                  uint64_t readbackFloats, bool fillNan, const std::string& snowDepth = "",
                  const std::string& snowParams = "", const std::string& paramsTail = "");

void destroyInputs(const Gpu& gpu, Inputs& inputs);

// The name of the rig's buffer at binding ("TerrainParams", ..., "_SnowDepth"), or nullptr when
// the binding is free for --storage. Binding 6 counts as taken even without snow: the contract
// reserves it for _SnowDepth, so a --storage there would silently change meaning in GT_SNOW runs.
const char* rigBindingName(uint32_t binding);

// A copy of inputs whose params buffer (binding 0) is its own, same bytes; every other binding
// is shared. Destroy only that buffer (destroyParamsCopy), for a frame in flight.
Inputs copyWithOwnParams(const Gpu& gpu, const Inputs& inputs);
void destroyParamsCopy(const Gpu& gpu, Inputs& copy);

// Writes a new _Range (the first float4) into the host-visible params buffer.
void writeRange(Inputs& inputs, const std::array<float, 4>& range);

// --camera-path: reads path's RigCamera blocks (a non-zero multiple of kCameraBytes) and replaces
// binding 1 by a host-visible buffer holding the first, so writeCamera can move the camera.
std::vector<uint8_t> loadCameraPath(const Gpu& gpu, Inputs& inputs, const std::string& path);

// Copies block (frame mod N) of a camera path into binding 1.
void writeCamera(Inputs& inputs, const std::vector<uint8_t>& path, uint32_t frame);

// --params-path: records of a whole TerrainParams block (params.f32's bytes) and a float4 whose x
// says whether that frame runs the --compute passes (1) or reuses their output (0).
constexpr size_t kParamsRecordBytes = kParamsBytes + 16;
inline size_t paramsRecordBytes(const Inputs&) { return kParamsRecordBytes; }

// Reads a --params-path file (a non-zero multiple of kParamsRecordBytes; every flag 0 or 1) and
// writes its first record, so the first frame draws it.
std::vector<uint8_t> loadParamsPath(Inputs& inputs, const std::string& path);

// Copies record (frame mod N)'s TerrainParams into binding 0 (and the CPU copy); returns its flag.
bool writeParams(Inputs& inputs, const std::vector<uint8_t>& path, uint32_t frame);

// --params-tail-path: reads records of inputs.tailBytes each (a non-zero multiple) and writes the first.
std::vector<uint8_t> loadParamsTailPath(Inputs& inputs, const std::string& path);

// Copies record (frame mod N) of a --params-tail-path after TerrainParams in binding 0.
void writeParamsTail(Inputs& inputs, const std::vector<uint8_t>& path, uint32_t frame);

}  // namespace gt
