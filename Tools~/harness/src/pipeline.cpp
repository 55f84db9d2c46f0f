#include "pipeline.hpp"

#include <algorithm>
#include <vector>

#include "batch.hpp"
#include "check.hpp"
#include "vkcommon.hpp"

namespace gt {

namespace {

// The rig's bindings (uniform buffers 0 and 1, storage buffers above) then the --storage ones.
// With gpu.uniformBlocksAsStorage, 0 and 1 are storage buffers too (the shaders' blocks were rewritten).
std::vector<DescriptorEntry> descriptorEntries(const Gpu& gpu, const Inputs& inputs, const std::vector<StorageBuffer>& storage) {
    std::vector<DescriptorEntry> entries;
    for (uint32_t i = 0; i < inputs.bindingCount(); ++i) {
        const bool uniform = i <= kBindingCamera && !gpu.uniformBlocksAsStorage;
        const VkDescriptorType type = uniform ? VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        entries.push_back({i, type, inputs.bindings[i].buffer});
    }
    for (const StorageBuffer& s : storage) entries.push_back({s.binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, s.buffer.buffer});
    return entries;
}

uint32_t countOf(const std::vector<DescriptorEntry>& entries, VkDescriptorType type) {
    uint32_t n = 0;
    for (const DescriptorEntry& e : entries) n += e.type == type ? 1 : 0;
    return n;
}

VkDescriptorSet allocateSet(const Gpu& gpu, const Pipeline& p) {
    VkDescriptorSetAllocateInfo ai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    ai.descriptorPool = p.pool;
    ai.descriptorSetCount = 1;
    ai.pSetLayouts = &p.setLayout;
    VkDescriptorSet set = VK_NULL_HANDLE;
    GT_VK(vkAllocateDescriptorSets(gpu.device, &ai, &set));
    return set;
}

void createDescriptors(const Gpu& gpu, Pipeline& p, uint32_t sets, const Inputs& inputs,
                       const std::vector<StorageBuffer>& storage, const std::vector<ImageDescriptor>& images) {
    const std::vector<DescriptorEntry> entries = descriptorEntries(gpu, inputs, storage);
    const uint32_t uniforms = countOf(entries, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER);
    const uint32_t storages = countOf(entries, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
    // Every binding is visible to every stage, so each stage counts all of them against its limit.
    const uint32_t limit = gpu.properties.limits.maxPerStageDescriptorStorageBuffers;
    if (storages > limit)
        fail("set 0 would hold " + std::to_string(storages) + " storage buffers (" + std::to_string(storage.size()) +
             " from --storage), more than " + gpu.properties.deviceName + "'s maxPerStageDescriptorStorageBuffers " +
             std::to_string(limit));

    // Compute included: the --compute kernels share this layout and read the rig's bindings too.
    std::vector<VkDescriptorSetLayoutBinding> b(entries.size() + images.size());
    for (size_t i = 0; i < b.size(); ++i) {
        const bool buffer = i < entries.size();
        b[i].binding = buffer ? entries[i].binding : images[i - entries.size()].binding;
        b[i].descriptorType = buffer ? entries[i].type : images[i - entries.size()].type;
        b[i].descriptorCount = 1;
        b[i].stageFlags = VK_SHADER_STAGE_ALL_GRAPHICS | VK_SHADER_STAGE_COMPUTE_BIT;
        p.bindings.push_back(b[i].binding);
    }
    p.images = images;
    std::sort(p.bindings.begin(), p.bindings.end());
    VkDescriptorSetLayoutCreateInfo li{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    li.bindingCount = static_cast<uint32_t>(b.size());
    li.pBindings = b.data();
    GT_VK(vkCreateDescriptorSetLayout(gpu.device, &li, nullptr, &p.setLayout));

    // Room for the frames-in-flight sets too (addFrameSet): same layout, other buffers.
    std::vector<VkDescriptorPoolSize> sizes = {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, std::max(uniforms, 1u) * sets},
                                               {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, storages * sets}};
    for (const ImageDescriptor& d : images) sizes.push_back({d.type, sets});
    VkDescriptorPoolCreateInfo pi{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    pi.maxSets = sets;
    pi.poolSizeCount = static_cast<uint32_t>(sizes.size());
    pi.pPoolSizes = sizes.data();
    GT_VK(vkCreateDescriptorPool(gpu.device, &pi, nullptr, &p.pool));
    p.set = allocateSet(gpu, p);
    writeBufferDescriptors(gpu.device, p.set, entries);
    writeImageDescriptors(gpu.device, p.set, images);
}

VkPipelineShaderStageCreateInfo stage(VkShaderStageFlagBits s, const ShaderModule& m) {
    VkPipelineShaderStageCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    info.stage = s;
    info.module = m.module;
    info.pName = m.entry.c_str();
    return info;
}

}  // namespace

void checkShaderDescriptors(const ShaderModule& shader, const std::string& option, const Pipeline& pipeline) {
    for (const DescriptorUse& d : shader.descriptors) {
        const bool bound = d.set == 0 && std::binary_search(pipeline.bindings.begin(), pipeline.bindings.end(), d.binding);
        if (bound) continue;
        std::string have;
        for (uint32_t b : pipeline.bindings) have += (have.empty() ? "" : " ") + std::to_string(b);
        const std::string hint = d.set != 0 ? "the harness binds set 0 only"
                                 : d.binding == kBindingSnowDepth ? "give --snow-depth and --snow-params"
                                 : "give --storage " + std::to_string(d.binding) + ":BYTES (a buffer), --image " +
                                       std::to_string(d.binding) + ":... (a texture) or --sampler " +
                                       std::to_string(d.binding) + ":... (a sampler)";
        fail(option + " '" + shader.path + "' uses set " + std::to_string(d.set) + " binding " + std::to_string(d.binding) +
             ", which this run does not bind (set 0 has " + have + "): " + hint);
    }
}

Pipeline createPipeline(const Gpu& gpu, const PipelineDesc& d, const RenderTarget& target, const Inputs& inputs,
                        const std::vector<StorageBuffer>& storage, const std::vector<ImageDescriptor>& images) {
    Pipeline p;
    createDescriptors(gpu, p, d.descriptorSets, inputs, storage, images);
    checkShaderDescriptors(d.vert, "--vert", p);
    if (d.mode == Mode::Tessellated) {
        checkShaderDescriptors(d.tesc, "--tesc", p);
        checkShaderDescriptors(d.tese, "--tese", p);
    }
    checkShaderDescriptors(d.frag, "--frag", p);
    VkPipelineLayoutCreateInfo pl{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    pl.setLayoutCount = 1;
    pl.pSetLayouts = &p.setLayout;
    GT_VK(vkCreatePipelineLayout(gpu.device, &pl, nullptr, &p.layout));

    const bool tess = d.mode == Mode::Tessellated;
    std::vector<VkPipelineShaderStageCreateInfo> stages = {stage(VK_SHADER_STAGE_VERTEX_BIT, d.vert)};
    if (tess) {
        stages.push_back(stage(VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT, d.tesc));
        stages.push_back(stage(VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT, d.tese));
    }
    stages.push_back(stage(VK_SHADER_STAGE_FRAGMENT_BIT, d.frag));

    // Static mesh: float3 positions at location 0 (HLSL POSITION). Other modes: no vertex
    // buffer at all, the vertex stage builds everything from SV_VertexID / SV_InstanceID.
    VkVertexInputBindingDescription vb{0, 12, VK_VERTEX_INPUT_RATE_VERTEX};
    VkVertexInputAttributeDescription va{0, 0, VK_FORMAT_R32G32B32_SFLOAT, 0};
    VkPipelineVertexInputStateCreateInfo vi{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    if (d.mode == Mode::StaticMesh) {
        vi.vertexBindingDescriptionCount = 1;
        vi.pVertexBindingDescriptions = &vb;
        vi.vertexAttributeDescriptionCount = 1;
        vi.pVertexAttributeDescriptions = &va;
    }
    VkPipelineInputAssemblyStateCreateInfo ia{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
    ia.topology = tess ? VK_PRIMITIVE_TOPOLOGY_PATCH_LIST : VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    VkPipelineTessellationStateCreateInfo ts{VK_STRUCTURE_TYPE_PIPELINE_TESSELLATION_STATE_CREATE_INFO};
    ts.patchControlPoints = d.controlPoints;
    if (tess && d.controlPoints > gpu.properties.limits.maxTessellationPatchSize)
        fail("--control-points " + std::to_string(d.controlPoints) + " exceeds the device's maxTessellationPatchSize " +
             std::to_string(gpu.properties.limits.maxTessellationPatchSize));

    // Negative viewport height (Vulkan 1.1): clip-space +y is up, as in D3D/HLSL and Unity's
    // projection, so images come out upright; facing is decided after it (render_state.hpp).
    VkViewport viewport{0.0f, static_cast<float>(target.height), static_cast<float>(target.width),
                        -static_cast<float>(target.height), 0.0f, 1.0f};
    VkRect2D scissor{{0, 0}, {target.width, target.height}};
    VkPipelineViewportStateCreateInfo vp{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
    vp.viewportCount = 1;
    vp.pViewports = &viewport;
    vp.scissorCount = 1;
    vp.pScissors = &scissor;

    VkPipelineRasterizationStateCreateInfo rs{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
    rs.polygonMode = d.wireframe ? VK_POLYGON_MODE_LINE : VK_POLYGON_MODE_FILL;
    rs.cullMode = vulkanCullMode(d.state.cull);
    rs.frontFace = VK_FRONT_FACE_CLOCKWISE;   // Unity's front faces: clockwise in the upright image
    rs.depthClampEnable = d.state.zClip ? VK_FALSE : VK_TRUE;
    rs.depthBiasEnable = d.state.depthBiasUnits != 0.0f || d.state.depthBiasSlope != 0.0f;
    rs.depthBiasConstantFactor = vulkanDepthBias(d.state.depthBiasUnits, d.state.depth);
    rs.depthBiasSlopeFactor = vulkanDepthBias(d.state.depthBiasSlope, d.state.depth);
    rs.lineWidth = 1.0f;
    VkPipelineMultisampleStateCreateInfo ms{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
    ms.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
    VkPipelineDepthStencilStateCreateInfo ds{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
    ds.depthTestEnable = VK_TRUE;
    ds.depthWriteEnable = d.state.zWrite ? VK_TRUE : VK_FALSE;
    ds.depthCompareOp = vulkanCompareOp(d.state.zTest, d.state.depth);
    ds.stencilTestEnable = d.state.stencil.enabled ? VK_TRUE : VK_FALSE;
    ds.front = vulkanStencil(d.state.stencil, d.state.stencil.front);
    ds.back = vulkanStencil(d.state.stencil, d.state.stencil.back);
    VkPipelineColorBlendAttachmentState blend[2]{};
    blend[0].colorWriteMask = blend[1].colorWriteMask = d.state.colorMask;   // ShaderLab's ColorMask: every target
    VkPipelineColorBlendStateCreateInfo cb{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
    cb.attachmentCount = target.color1Format != VK_FORMAT_UNDEFINED ? 2 : 1;
    cb.pAttachments = blend;

    VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
    info.stageCount = static_cast<uint32_t>(stages.size());
    info.pStages = stages.data();
    info.pVertexInputState = &vi;
    info.pInputAssemblyState = &ia;
    info.pTessellationState = tess ? &ts : nullptr;
    info.pViewportState = &vp;
    info.pRasterizationState = &rs;
    info.pMultisampleState = &ms;
    info.pDepthStencilState = &ds;
    info.pColorBlendState = &cb;
    info.layout = p.layout;
    info.renderPass = target.renderPass;
    const std::string key = pipelineKey(gpu, d, target, p);
    if ((p.pipeline = keptPipeline(key))) return p;
    VkResult r = vkCreateGraphicsPipelines(gpu.device, VK_NULL_HANDLE, 1, &info, nullptr, &p.pipeline);
    if (r != VK_SUCCESS) fail("vkCreateGraphicsPipelines failed (" + resultName(r) + "): check the SPIR-V stages and entry points");
    keepPipeline(key, p);
    return p;
}

VkDescriptorSet addFrameSet(const Gpu& gpu, const Pipeline& pipeline, const Inputs& inputs,
                            const std::vector<StorageBuffer>& storage) {
    const std::vector<DescriptorEntry> entries = descriptorEntries(gpu, inputs, storage);
    std::vector<uint32_t> bindings;
    for (const DescriptorEntry& e : entries) bindings.push_back(e.binding);
    for (const ImageDescriptor& d : pipeline.images) bindings.push_back(d.binding);
    std::sort(bindings.begin(), bindings.end());
    if (bindings != pipeline.bindings) fail("addFrameSet: the frame's buffers do not match set 0's bindings");
    VkDescriptorSet set = allocateSet(gpu, pipeline);
    writeBufferDescriptors(gpu.device, set, entries);
    writeImageDescriptors(gpu.device, set, pipeline.images);
    return set;
}

void destroyPipeline(const Gpu& gpu, Pipeline& p) {
    if (p.pipeline && !keptByBatch(p.pipeline)) vkDestroyPipeline(gpu.device, p.pipeline, nullptr);
    if (p.layout && !keptByBatch(p.layout)) vkDestroyPipelineLayout(gpu.device, p.layout, nullptr);
    if (p.pool) vkDestroyDescriptorPool(gpu.device, p.pool, nullptr);
    if (p.setLayout && !keptByBatch(p.setLayout)) vkDestroyDescriptorSetLayout(gpu.device, p.setLayout, nullptr);
    p = Pipeline{};
}

}  // namespace gt
