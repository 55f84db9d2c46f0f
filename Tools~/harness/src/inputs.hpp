// The rig's input files (little-endian float32, written by the C# rig's GpuLayout) and the six
// descriptor bindings of Documentation~/internals.md "Descriptor bindings".
#pragma once
#include <array>
#include <optional>
#include <string>

#include "buffers.hpp"

namespace gt {

constexpr uint32_t kBindingParams = 0;         // b0 TerrainParams, 9 float4
constexpr uint32_t kBindingCamera = 1;         // b1 RigCamera
constexpr uint32_t kBindingControlPoints = 2;  // t0 StructuredBuffer<float4>, 20 per patch
constexpr uint32_t kBindingRegions = 3;        // t1 StructuredBuffer<float4>
constexpr uint32_t kBindingGridLines = 4;      // t2 StructuredBuffer<float>
constexpr uint32_t kBindingReadback = 5;       // u0 RWStructuredBuffer<float4> (rig only)
constexpr uint32_t kBindingCount = 6;

constexpr size_t kParamsBytes = 9 * 16;             // _Range .. _ColorHigh
constexpr size_t kCameraBytes = 2 * 64 + 3 * 16;    // two float4x4 + three float4
constexpr size_t kPatchBytes = 20 * 16;             // 20 float4 control points

struct Inputs {
    std::array<Buffer, kBindingCount> bindings;
    std::array<float, kParamsBytes / 4> params{};  // the CPU copy of TerrainParams (range patched)
    uint32_t gregoryPatches = 0;                    // control_points.f32 / 320 bytes
};

// Reads DIR/{params,camera,control_points,regions,grid_lines}.f32, checks their sizes, patches
// _Range, uploads. params is host-visible (the per-frame range goes there); the readback
// buffer (binding 5) holds readbackFloats floats (a 16-byte dummy when 0), pre-filled.
Inputs loadInputs(const Gpu& gpu, const std::string& dir, const std::optional<std::array<float, 4>>& range,
                  uint64_t readbackFloats, bool fillNan);

void destroyInputs(const Gpu& gpu, Inputs& inputs);

// Writes a new _Range (the first float4) into the host-visible params buffer.
void writeRange(Inputs& inputs, const std::array<float, 4>& range);

}  // namespace gt
