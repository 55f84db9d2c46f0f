// The graphics pipeline and its one descriptor set: set 0 with the rig's bindings 0..5 (6 with
// snow) of internals.md plus the --storage buffers and the --image / --sampler descriptors at their
// bindings; the compute pre-pass (compute.hpp) uses the same layout and set.
#pragma once
#include <vector>

#include "cli.hpp"
#include "images.hpp"
#include "inputs.hpp"
#include "spirv.hpp"
#include "storage.hpp"
#include "target.hpp"

namespace gt {

struct PipelineDesc {
    Mode mode = Mode::Tessellated;
    uint32_t controlPoints = 4;  // patch size for the tessellated mode
    bool wireframe = false;
    RenderState state;       // the drawn pass's Cull, ZTest, ZWrite, ZClip, ColorMask and depth convention
    ShaderModule vert, tesc, tese, frag;  // tesc/tese empty outside the tessellated mode
    uint32_t descriptorSets = 1;          // set 0 of each frame in flight (--in-flight), see addFrameSet
};

struct Pipeline {
    VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
    VkDescriptorPool pool = VK_NULL_HANDLE;
    VkDescriptorSet set = VK_NULL_HANDLE;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VkPipeline pipeline = VK_NULL_HANDLE;
    std::vector<uint32_t> bindings;  // of set 0, ascending
    std::vector<ImageDescriptor> images;  // --image / --sampler: the same in every frame's set
};

Pipeline createPipeline(const Gpu& gpu, const PipelineDesc& desc, const RenderTarget& target, const Inputs& inputs,
                        const std::vector<StorageBuffer>& storage, const std::vector<ImageDescriptor>& images = {});
void destroyPipeline(const Gpu& gpu, Pipeline& pipeline);

// Another set 0 of the same layout over another frame's buffers (frames in flight: each has its
// own TerrainParams and --storage buffers). At most desc.descriptorSets - 1 of them; freed with
// the pipeline's pool.
VkDescriptorSet addFrameSet(const Gpu& gpu, const Pipeline& pipeline, const Inputs& inputs,
                            const std::vector<StorageBuffer>& storage);

// Throws gt::Error when the shader uses a descriptor the layout lacks (another set, or a binding
// of set 0 not bound in this run), naming the shader, the option that gave it and what to add.
void checkShaderDescriptors(const ShaderModule& shader, const std::string& option, const Pipeline& pipeline);

}  // namespace gt
