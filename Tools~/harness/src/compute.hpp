// The compute pre-pass of --compute: kernels dispatched in order at the start of every frame,
// before the render pass, sharing the graphics pipeline's layout and descriptor set (so a kernel
// sees TerrainParams, the camera, the patch buffers and the --storage buffers at the bindings the
// graphics stages use; the vertex cache writes _TileFactors/_VertexCache there for the draw).
#pragma once
#include <array>
#include <vector>

#include "cli.hpp"
#include "pipeline.hpp"
#include "spirv.hpp"

namespace gt {

struct ComputePass {
    ShaderModule shader;  // its only compute entry point
    VkPipeline pipeline = VK_NULL_HANDLE;
    std::array<uint32_t, 3> groups{1, 1, 1};
};

// One pipeline per --compute option, in order, with the graphics pipeline's layout. Throws
// gt::Error naming the option and value (file, entry points, work group counts over the limits).
std::vector<ComputePass> createComputePasses(const Gpu& gpu, const std::vector<ComputeOption>& options,
                                             const Pipeline& graphics);

// Records the pre-pass over `set` (graphics.set, or a frame-in-flight set): the dispatches in order
// with a compute->compute barrier between two; with frameBarriers also a barrier ordering it after
// the previous frame's shader accesses and one making its writes visible to the graphics shader
// stages (frames in flight order these with semaphores instead). Nothing when passes is empty.
void recordComputePasses(VkCommandBuffer cmd, const Gpu& gpu, const std::vector<ComputePass>& passes,
                         const Pipeline& graphics, VkDescriptorSet set, bool frameBarriers);

// The graphics shader stages that may read what the kernels wrote (tessellation stages only when
// the feature is on: naming them otherwise is invalid).
VkPipelineStageFlags graphicsShaderStages(const Gpu& gpu);

void destroyComputePasses(const Gpu& gpu, std::vector<ComputePass>& passes);

}  // namespace gt
