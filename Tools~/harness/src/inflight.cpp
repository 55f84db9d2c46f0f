#include "inflight.hpp"

#include <cstdio>

#include "check.hpp"
#include "queries.hpp"

namespace gt {

namespace {

// What one frame slot owns. Slot 0 borrows the run's own params and storage buffers and set 0.
struct Slot {
    Inputs inputs;                     // slots >= 1: copyWithOwnParams
    std::vector<StorageBuffer> storage;  // slots >= 1: their own --storage buffers
    VkDescriptorSet set = VK_NULL_HANDLE;
    VkCommandBuffer pre = VK_NULL_HANDLE, draw = VK_NULL_HANDLE;
    VkFence fence = VK_NULL_HANDLE;
    TimestampQuery times;  // 0: the draw's command buffer begins, 1: it ends
    StatsQuery stats;
    bool submitted = false;
};

// The pool of the queue the pre-pass goes to.
VkCommandPool prePassPool(const Gpu& gpu) { return gpu.asyncCompute ? gpu.computePool : gpu.commandPool; }

VkSemaphore createTimeline(const Gpu& gpu) {
    VkSemaphoreTypeCreateInfo type{VK_STRUCTURE_TYPE_SEMAPHORE_TYPE_CREATE_INFO};
    type.semaphoreType = VK_SEMAPHORE_TYPE_TIMELINE;
    type.initialValue = 0;
    VkSemaphoreCreateInfo info{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    info.pNext = &type;
    VkSemaphore s = VK_NULL_HANDLE;
    GT_VK(vkCreateSemaphore(gpu.device, &info, nullptr, &s));
    return s;
}

VkCommandBuffer recordPrePass(const Gpu& gpu, const Pipeline& pipeline, const std::vector<ComputePass>& compute,
                              const Slot& slot) {
    VkCommandBuffer cmd = allocateCommandBuffer(gpu, prePassPool(gpu));
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    GT_VK(vkBeginCommandBuffer(cmd, &begin));
    recordComputePasses(cmd, gpu, compute, pipeline, slot.set, false);
    GT_VK(vkEndCommandBuffer(cmd));
    return cmd;
}

VkCommandBuffer recordDraw(const Gpu& gpu, const RenderTarget& target, const Pipeline& pipeline, const DrawWork& work,
                           const Slot& slot) {
    VkCommandBuffer cmd = allocateCommandBuffer(gpu, gpu.commandPool);
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    GT_VK(vkBeginCommandBuffer(cmd, &begin));
    if (slot.times.pool) {
        vkCmdResetQueryPool(cmd, slot.times.pool, 0, slot.times.count);
        vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, slot.times.pool, 0);
    }
    if (slot.stats.pool) vkCmdResetQueryPool(cmd, slot.stats.pool, 0, 1);
    // All frames draw into one colour and depth image: the render pass's external dependency
    // (target.cpp) orders this frame's attachment writes after the previous frame's; the vertex and
    // tessellation stages are free to start while the previous frame still shades.
    if (slot.stats.pool) vkCmdBeginQuery(cmd, slot.stats.pool, 0, 0);
    beginRenderPass(cmd, target);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline.pipeline);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline.layout, 0, 1, &slot.set, 0, nullptr);
    recordDraws(cmd, work);
    vkCmdEndRenderPass(cmd);
    if (slot.stats.pool) vkCmdEndQuery(cmd, slot.stats.pool, 0);
    if (slot.times.pool) vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, slot.times.pool, 1);
    GT_VK(vkEndCommandBuffer(cmd));
    return cmd;
}

// One vkQueueSubmit of one command buffer with at most one timeline wait and one timeline signal.
void submit(VkQueue queue, VkCommandBuffer cmd, VkSemaphore wait, uint64_t waitValue, VkPipelineStageFlags waitStages,
            VkSemaphore signal, uint64_t signalValue, VkFence fence) {
    VkTimelineSemaphoreSubmitInfo values{VK_STRUCTURE_TYPE_TIMELINE_SEMAPHORE_SUBMIT_INFO};
    values.waitSemaphoreValueCount = wait ? 1 : 0;
    values.pWaitSemaphoreValues = &waitValue;
    values.signalSemaphoreValueCount = 1;
    values.pSignalSemaphoreValues = &signalValue;
    VkSubmitInfo info{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    info.pNext = &values;
    info.waitSemaphoreCount = wait ? 1 : 0;
    info.pWaitSemaphores = &wait;
    info.pWaitDstStageMask = &waitStages;
    info.commandBufferCount = 1;
    info.pCommandBuffers = &cmd;
    info.signalSemaphoreCount = 1;
    info.pSignalSemaphores = &signal;
    GT_VK(vkQueueSubmit(queue, 1, &info, fence));
}

}  // namespace

FrameResults runFramesInFlight(const Gpu& gpu, const RenderTarget& target, const Pipeline& pipeline, Inputs& inputs,
                               const std::vector<StorageBuffer>& storage, const std::vector<StorageOption>& storageOptions,
                               const std::vector<StorageDump>& dumps, const DrawWork& work,
                               const std::vector<ComputePass>& compute, const FrameSettings& s, uint32_t inFlight) {
    std::vector<Slot> slots(inFlight);
    for (uint32_t i = 0; i < inFlight; ++i) {
        Slot& slot = slots[i];
        if (i == 0) {
            slot.inputs = inputs;
            slot.storage = storage;
            slot.set = pipeline.set;
        } else {
            slot.inputs = copyWithOwnParams(gpu, inputs);
            slot.storage = createStorageBuffers(gpu, storageOptions);
            slot.set = addFrameSet(gpu, pipeline, slot.inputs, slot.storage);
        }
        if (s.timestamps) slot.times = createTimestampQuery(gpu, 2);
        if (s.stats) slot.stats = createStatsQuery(gpu);
        if (!compute.empty()) slot.pre = recordPrePass(gpu, pipeline, compute, slot);
        slot.draw = recordDraw(gpu, target, pipeline, work, slot);
        VkFenceCreateInfo fi{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
        GT_VK(vkCreateFence(gpu.device, &fi, nullptr, &slot.fence));
    }
    VkSemaphore cached = createTimeline(gpu), drawn = createTimeline(gpu);
    VkQueue preQueue = gpu.asyncCompute ? gpu.computeQueue : gpu.queue;
    const std::array<float, 4> baseRange{inputs.params[0], inputs.params[1], inputs.params[2], inputs.params[3]};

    FrameResults results;
    const uint32_t total = s.warmup + s.frames;
    std::vector<uint64_t> frameEnd(total, 0);
    auto collect = [&](Slot& slot, uint32_t frame) {
        waitFrameFence(gpu, slot.fence, frame);
        GT_VK(vkResetFences(gpu.device, 1, &slot.fence));
        slot.submitted = false;
        if (slot.times.pool) frameEnd[frame] = readTicks(gpu, slot.times)[1];
    };
    for (uint32_t f = 0; f < total; ++f) {
        Slot& slot = slots[f % inFlight];
        if (slot.submitted) collect(slot, f - inFlight);
        if (s.updateRange) writeRange(slot.inputs, frameRange(baseRange, f, total, s.rangePan));
        const bool pre = slot.pre && (!s.computeOnce || f < inFlight);
        if (pre) {
            // Frame f - inFlight read this slot's buffers; value 0 (no such frame yet) is already reached.
            const uint64_t previousReader = f >= inFlight ? f - inFlight + 1 : 0;
            submit(preQueue, slot.pre, previousReader ? drawn : VK_NULL_HANDLE, previousReader,
                   VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, cached, f + 1, VK_NULL_HANDLE);
        }
        submit(gpu.queue, slot.draw, pre ? cached : VK_NULL_HANDLE, f + 1, graphicsShaderStages(gpu), drawn, f + 1,
               slot.fence);
        slot.submitted = true;
    }
    for (uint32_t k = 0; k < inFlight && k < total; ++k) {
        const uint32_t f = total - 1 - k;
        collect(slots[f % inFlight], f);
    }

    // The period between consecutive frame ends: what a frame costs when frames overlap.
    if (s.timestamps)
        for (uint32_t f = s.warmup > 0 ? s.warmup : 1; f < total; ++f)
            results.gpuMs.push_back(ticksToMs(slots[0].times, frameEnd[f - 1], frameEnd[f]));
    if (s.stats) results.stats = readStats(gpu, slots[(total - 1) % inFlight].stats);
    if (s.updateRange) writeRange(inputs, baseRange);

    GT_VK(vkDeviceWaitIdle(gpu.device));
    for (const StorageDump& d : dumps) {
        const uint64_t bytes = dumpStorage(gpu, slots[(total - 1) % inFlight].storage, d);
        std::printf("storage %u %s bytes %llu\n", d.binding, d.path.c_str(), static_cast<unsigned long long>(bytes));
    }
    vkDestroySemaphore(gpu.device, cached, nullptr);
    vkDestroySemaphore(gpu.device, drawn, nullptr);
    for (uint32_t i = 0; i < inFlight; ++i) {
        Slot& slot = slots[i];
        vkDestroyFence(gpu.device, slot.fence, nullptr);
        if (slot.pre) vkFreeCommandBuffers(gpu.device, prePassPool(gpu), 1, &slot.pre);
        vkFreeCommandBuffers(gpu.device, gpu.commandPool, 1, &slot.draw);
        destroyQuery(gpu, slot.times.pool);
        destroyQuery(gpu, slot.stats.pool);
        if (i == 0) continue;
        destroyParamsCopy(gpu, slot.inputs);
        destroyStorageBuffers(gpu, slot.storage);
    }
    return results;
}

}  // namespace gt
