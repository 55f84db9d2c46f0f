#include "frames.hpp"

#include <chrono>
#include <cmath>
#include <cstring>

#include "check.hpp"
#include "queries.hpp"

namespace gt {

void recordDraws(VkCommandBuffer cmd, const DrawWork& w) {
    if (w.mode == Mode::Tessellated) {
        // firstVertex over whole patches: SV_VertexID (= firstVertex + index) stays global,
        // SV_PrimitiveID restarts at 0 in each draw.
        for (const PatchRange& r : w.draws)
            vkCmdDraw(cmd, r.patchCount * w.controlPoints, 1, r.firstPatch * w.controlPoints, 0);
        return;
    }
    if (w.mode == Mode::StaticMesh) {
        VkDeviceSize offset = 0;
        vkCmdBindVertexBuffers(cmd, 0, 1, &w.positions.buffer, &offset);
    }
    vkCmdBindIndexBuffer(cmd, w.indices.buffer, 0, VK_INDEX_TYPE_UINT32);
    vkCmdDrawIndexed(cmd, w.indexCount, w.instances, 0, 0, 0);
}

void waitFrameFence(const Gpu& gpu, VkFence fence, uint32_t frame) {
    const VkResult r = vkWaitForFences(gpu.device, 1, &fence, VK_TRUE, 600ull * 1000 * 1000 * 1000);
    if (r == VK_TIMEOUT) fail("frame " + std::to_string(frame) + " did not finish within 600 s");
    GT_VK(r);
}

std::array<float, 4> frameRange(const std::array<float, 4>& base, uint32_t frame, uint32_t frames, float pan) {
    if (frame + 1 == frames) return base;
    const float k = pan > 0.0f ? pan * static_cast<float>(std::sin(2.0 * 3.14159265358979 * (frame % 100) / 100.0))
                               : 1e-4f * static_cast<float>(frame % 8);
    const float dx = (base[2] - base[0]) * k;
    const float dy = (base[3] - base[1]) * k;
    return {base[0] + dx, base[1] + dy, base[2] + dx, base[3] + dy};
}

FrameResults runFrames(const Gpu& gpu, const RenderTarget& target, const Pipeline& pipeline, Inputs& inputs,
                       const DrawWork& work, const std::vector<ComputePass>& compute, const FrameSettings& s) {
    StatsQuery stats;
    TimestampQuery times;
    if (s.stats) stats = createStatsQuery(gpu);
    // With a pre-pass, a middle timestamp after its last dispatch: query 0 top, 1 compute end, 2 frame end.
    // (--compute-once: no middle timestamp, the frames measured have no pre-pass.)
    // --params-path picks per frame between the two command buffers, like --compute-once after frame 0.
    const bool someFramesReuse = s.computeOnce || !s.paramsPath.empty();
    const bool timeCompute = s.timestamps && s.computeTimestamp && !compute.empty() && !someFramesReuse;
    if (s.timestamps) times = createTimestampQuery(gpu, timeCompute ? 3 : 2);
    const uint32_t frameEndQuery = timeCompute ? 2 : 1;

    // Re-send baseline: host writes B bytes into a staging buffer, the GPU copies them into a
    // device-local buffer before the render pass (inside the timed region).
    Buffer staging, geometry;
    if (s.resendBytes) {
        staging = createHostBuffer(gpu, s.resendBytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
        geometry = createDeviceBuffer(gpu, s.resendBytes,
                                      VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    }

    // One frame's command buffer; withCompute = false leaves the pre-pass out (--compute-once).
    auto recordFrame = [&](bool withCompute) {
    VkCommandBuffer cmd = allocateCommandBuffer(gpu, gpu.commandPool);
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    GT_VK(vkBeginCommandBuffer(cmd, &begin));
    if (times.pool) vkCmdResetQueryPool(cmd, times.pool, 0, times.count);
    if (stats.pool) vkCmdResetQueryPool(cmd, stats.pool, 0, 1);
    if (times.pool) vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, times.pool, 0);
    // The pre-pass first, so that its timestamp pair brackets the kernels alone (not the re-send copy).
    if (withCompute) recordComputePasses(cmd, gpu, compute, pipeline, pipeline.set, true);
    if (timeCompute) vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, times.pool, 1);
    if (s.resendBytes) {
        VkBufferCopy region{0, 0, s.resendBytes};
        vkCmdCopyBuffer(cmd, staging.buffer, geometry.buffer, 1, &region);
        VkMemoryBarrier b{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
        b.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        b.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_VERTEX_ATTRIBUTE_READ_BIT;
        vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_VERTEX_INPUT_BIT |
                             VK_PIPELINE_STAGE_VERTEX_SHADER_BIT, 0, 1, &b, 0, nullptr, 0, nullptr);
    }
    if (stats.pool) vkCmdBeginQuery(cmd, stats.pool, 0, 0);
    beginRenderPass(cmd, target);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline.pipeline);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline.layout, 0, 1, &pipeline.set, 0, nullptr);
    recordDraws(cmd, work);
    vkCmdEndRenderPass(cmd);
    if (stats.pool) vkCmdEndQuery(cmd, stats.pool, 0);
    if (times.pool) vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, times.pool, frameEndQuery);
    // Shader writes to the readback buffer become visible to the host after the fence.
    VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    toHost.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    VkPipelineStageFlags writers = VK_PIPELINE_STAGE_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT;
    if (gpu.enabled.tessellationShader) writers |= VK_PIPELINE_STAGE_TESSELLATION_EVALUATION_SHADER_BIT;
    if (!compute.empty()) writers |= VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;  // a kernel may write _Readback too
    vkCmdPipelineBarrier(cmd, writers, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &toHost, 0, nullptr, 0, nullptr);
    GT_VK(vkEndCommandBuffer(cmd));
    return cmd;
    };
    VkCommandBuffer cmd = recordFrame(true);
    VkCommandBuffer reuseCmd = someFramesReuse ? recordFrame(false) : VK_NULL_HANDLE;

    VkFence fence = VK_NULL_HANDLE;
    VkFenceCreateInfo fi{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    GT_VK(vkCreateFence(gpu.device, &fi, nullptr, &fence));
    std::array<float, 4> baseRange{inputs.params[0], inputs.params[1], inputs.params[2], inputs.params[3]};

    FrameResults results;
    const uint32_t total = s.warmup + s.frames;
    for (uint32_t f = 0; f < total; ++f) {
        const auto t0 = std::chrono::steady_clock::now();
        if (s.updateRange) writeRange(inputs, frameRange(baseRange, f, total, s.rangePan));
        if (!s.cameraPath.empty()) writeCamera(inputs, s.cameraPath, f);
        if (!s.paramsTailPath.empty()) writeParamsTail(inputs, s.paramsTailPath, f);
        bool dispatch = !s.computeOnce || f == 0;
        if (!s.paramsPath.empty()) dispatch = writeParams(inputs, s.paramsPath, f) || f == 0;
        if (dispatch && f >= s.warmup) ++results.dispatchedFrames;
        if (s.resendBytes) std::memset(staging.mapped, static_cast<int>(f & 0xff), s.resendBytes);
        VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
        submit.commandBufferCount = 1;
        submit.pCommandBuffers = dispatch ? &cmd : &reuseCmd;
        GT_VK(vkQueueSubmit(gpu.queue, 1, &submit, fence));
        waitFrameFence(gpu, fence, f);
        GT_VK(vkResetFences(gpu.device, 1, &fence));
        const auto t1 = std::chrono::steady_clock::now();
        if (f < s.warmup) continue;
        results.cpuMs.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
        if (!times.pool) continue;
        const std::vector<double> ms = readMsSinceFirst(gpu, times);
        results.gpuMs.push_back(ms.back());
        if (timeCompute) results.computeMs.push_back(ms.front());
    }
    if (stats.pool) results.stats = readStats(gpu, stats);
    if (s.updateRange) writeRange(inputs, baseRange);

    vkDestroyFence(gpu.device, fence, nullptr);
    vkFreeCommandBuffers(gpu.device, gpu.commandPool, 1, &cmd);
    if (reuseCmd) vkFreeCommandBuffers(gpu.device, gpu.commandPool, 1, &reuseCmd);
    destroyBuffer(gpu, staging);
    destroyBuffer(gpu, geometry);
    destroyQuery(gpu, stats.pool);
    destroyQuery(gpu, times.pool);
    return results;
}

}  // namespace gt
