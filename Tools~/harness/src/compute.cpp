#include "compute.hpp"

#include "check.hpp"

namespace gt {

VkPipelineStageFlags graphicsShaderStages(const Gpu& gpu) {
    VkPipelineStageFlags s = VK_PIPELINE_STAGE_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT;
    if (gpu.enabled.tessellationShader)
        s |= VK_PIPELINE_STAGE_TESSELLATION_CONTROL_SHADER_BIT | VK_PIPELINE_STAGE_TESSELLATION_EVALUATION_SHADER_BIT;
    return s;
}

namespace {

void memoryBarrier(VkCommandBuffer cmd, VkPipelineStageFlags src, VkAccessFlags srcAccess, VkPipelineStageFlags dst,
                   VkAccessFlags dstAccess) {
    VkMemoryBarrier b{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    b.srcAccessMask = srcAccess;
    b.dstAccessMask = dstAccess;
    vkCmdPipelineBarrier(cmd, src, dst, 0, 1, &b, 0, nullptr, 0, nullptr);
}

void checkGroupCounts(const Gpu& gpu, const ComputeOption& o) {
    static const char* fields[3] = {"GX", "GY", "GZ"};
    for (int i = 0; i < 3; ++i) {
        const uint32_t limit = gpu.properties.limits.maxComputeWorkGroupCount[i];
        if (o.groups[i] > limit)
            fail("--compute: " + std::string(fields[i]) + " " + std::to_string(o.groups[i]) + " in '" + o.spec +
                 "' exceeds " + gpu.properties.deviceName + "'s maxComputeWorkGroupCount[" + std::to_string(i) + "] " +
                 std::to_string(limit));
    }
}

ComputePass createComputePass(const Gpu& gpu, const ComputeOption& o, const Pipeline& graphics) {
    checkGroupCounts(gpu, o);
    ComputePass pass;
    pass.groups = o.groups;
    try {
        pass.shader = loadShader(gpu, o.path, kExecutionModelGLCompute, "", "");
    } catch (const Error& e) {
        fail("--compute '" + o.spec + "': " + e.what());
    }
    try {
        checkShaderDescriptors(pass.shader, "--compute", graphics);
    } catch (const Error&) {
        destroyShader(gpu, pass.shader);
        throw;
    }
    VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    info.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    info.stage.module = pass.shader.module;
    info.stage.pName = pass.shader.entry.c_str();
    info.layout = graphics.layout;  // the same set 0 as the draw: one vkCmdBindDescriptorSets per bind point
    const VkResult r = vkCreateComputePipelines(gpu.device, VK_NULL_HANDLE, 1, &info, nullptr, &pass.pipeline);
    if (r != VK_SUCCESS) {
        destroyShader(gpu, pass.shader);
        fail("--compute '" + o.spec + "': vkCreateComputePipelines returned " + resultName(r) + " (entry point '" +
             info.stage.pName + "')");
    }
    return pass;
}

}  // namespace

std::vector<ComputePass> createComputePasses(const Gpu& gpu, const std::vector<ComputeOption>& options,
                                             const Pipeline& graphics) {
    std::vector<ComputePass> passes;
    try {
        for (const ComputeOption& o : options) passes.push_back(createComputePass(gpu, o, graphics));
    } catch (...) {
        destroyComputePasses(gpu, passes);
        throw;
    }
    return passes;
}

void recordComputePasses(VkCommandBuffer cmd, const Gpu& gpu, const std::vector<ComputePass>& passes,
                         const Pipeline& graphics, VkDescriptorSet set, bool frameBarriers) {
    if (passes.empty()) return;
    const VkPipelineStageFlags graphicsStages = graphicsShaderStages(gpu);
    const VkAccessFlags readWrite = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT;
    // The command buffer is submitted once per frame: this frame's kernels must not overwrite what
    // the previous frame's draw is still reading, nor race its kernels' writes. The fence wait
    // between frames orders execution on the host side only; this barrier is the device-side rule.
    // (Frames in flight: semaphores do this, and on a compute-only queue no graphics stage exists.)
    if (frameBarriers)
        memoryBarrier(cmd, graphicsStages | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT,
                      VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, readWrite);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, graphics.layout, 0, 1, &set, 0, nullptr);
    for (size_t i = 0; i < passes.size(); ++i) {
        // Kernel i+1 reads (and may rewrite) what kernel i wrote: e.g. the vertex cache's second
        // kernel reads the tile factors of the first.
        if (i > 0)
            memoryBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT,
                          VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, readWrite);
        const ComputePass& p = passes[i];
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, p.pipeline);
        vkCmdDispatch(cmd, p.groups[0], p.groups[1], p.groups[2]);
    }
    // The draw's hull/domain (or vertex) stages read the kernels' output.
    if (frameBarriers)
        memoryBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT, graphicsStages,
                      VK_ACCESS_SHADER_READ_BIT);
}

void destroyComputePasses(const Gpu& gpu, std::vector<ComputePass>& passes) {
    for (ComputePass& p : passes) {
        if (p.pipeline) vkDestroyPipeline(gpu.device, p.pipeline, nullptr);
        destroyShader(gpu, p.shader);
    }
    passes.clear();
}

}  // namespace gt
