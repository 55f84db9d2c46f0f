// The frame loop: one command buffer recorded once and submitted once per frame (each frame its
// own vkQueueSubmit + fence wait), with an optional compute pre-pass, per-frame range update,
// geometry re-send, timestamps and pipeline statistics.
#pragma once
#include <array>
#include <string>
#include <utility>
#include <vector>

#include "buffers.hpp"
#include "cli.hpp"
#include "compute.hpp"
#include "draw_split.hpp"
#include "inputs.hpp"
#include "pipeline.hpp"
#include "target.hpp"

namespace gt {

// What one frame draws.
struct DrawWork {
    Mode mode = Mode::Tessellated;
    uint32_t controlPoints = 4;
    std::vector<PatchRange> draws;  // tessellated: one vkCmdDraw per range
    Buffer indices;                 // fallback and static mesh: uint32 index buffer
    uint32_t indexCount = 0;
    uint32_t instances = 1;
    Buffer positions;               // static mesh: float3 vertex buffer
};

struct FrameSettings {
    uint32_t frames = 1, warmup = 0;
    bool timestamps = false, stats = false, updateRange = false;
    float rangePan = 0.0f;  // --range-pan: amplitude of the range's pan, a fraction of its size (0: the tiny shifts)
    std::vector<uint8_t> paramsPath;  // --params-path: (TerrainParams, dispatch flag) records, frame f draws record f mod N
    std::vector<uint8_t> cameraPath;  // --camera-path: RigCamera blocks, frame f draws with block f mod N
    std::vector<uint8_t> paramsTailPath;  // --params-tail-path: GT_LOD tails, frame f draws record f mod N
    // --compute-once: the pre-pass runs in the first frame only; later frames reuse what it wrote
    // (the vertex cache of a frame where nothing changed).
    bool computeOnce = false;
    // --no-compute-timestamp: no timestamp between the pre-pass and the draw (a bottom-of-pipe
    // timestamp there waits for the kernels, so it may keep the render pass from starting under them).
    bool computeTimestamp = true;
    uint64_t resendBytes = 0;
};

struct FrameResults {
    std::vector<double> gpuMs;      // measured frames only (with timestamps)
    std::vector<double> computeMs;  // the compute pre-pass alone, measured frames (timestamps + --compute)
    std::vector<double> cpuMs;  // submit to fence, measured frames only
    std::vector<std::pair<std::string, uint64_t>> stats;  // of the last frame
    uint32_t dispatchedFrames = 0;  // measured frames whose command buffer ran the --compute passes
};

// The frame's draw calls (inside the render pass, pipeline and set bound).
void recordDraws(VkCommandBuffer cmd, const DrawWork& work);

// Waits for frame's fence; a frame that has not finished after 600 s fails naming it.
void waitFrameFence(const Gpu& gpu, VkFence fence, uint32_t frame);

// The per-frame _Range of --update-range-per-frame: the base range shifted by a tiny,
// frame-dependent fraction of its size, so the values really change every frame, or with pan > 0
// (--range-pan) by pan sin(2 pi f / 100) of its size, a pan to and fro; the last of `frames`
// frames draws the base range itself, so what a run leaves (picture, statistics, dumps) is of the
// range its inputs name.
std::array<float, 4> frameRange(const std::array<float, 4>& base, uint32_t frame, uint32_t frames, float pan);

// compute: the pre-pass dispatched before the render pass of every frame (may be empty).
FrameResults runFrames(const Gpu& gpu, const RenderTarget& target, const Pipeline& pipeline, Inputs& inputs,
                       const DrawWork& work, const std::vector<ComputePass>& compute, const FrameSettings& settings);

}  // namespace gt
