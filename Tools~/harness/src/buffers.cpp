#include "buffers.hpp"

#include <cstring>

namespace gt {

namespace {

Buffer allocate(const Gpu& gpu, VkDeviceSize size, VkBufferUsageFlags usage,
                std::initializer_list<VkMemoryPropertyFlags> preferences) {
    BufferHeap heap;
    heap.device = gpu.device;
    heap.memory = gpu.memory;
    // Async compute: the compute family writes what the graphics family reads; concurrent
    // sharing makes that legal without a release/acquire pair on every frame.
    if (gpu.asyncCompute) heap.sharedFamilies = {gpu.queueFamily, gpu.computeFamily};
    return createBuffer(heap, size, usage, preferences);
}

constexpr VkMemoryPropertyFlags kHost = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;

}  // namespace

Buffer createHostBuffer(const Gpu& gpu, VkDeviceSize size, VkBufferUsageFlags usage, bool preferDeviceLocal) {
    if (preferDeviceLocal) return allocate(gpu, size, usage, {kHost | VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, kHost});
    return allocate(gpu, size, usage, {kHost | VK_MEMORY_PROPERTY_HOST_CACHED_BIT, kHost});
}

Buffer createDeviceBuffer(const Gpu& gpu, VkDeviceSize size, VkBufferUsageFlags usage) {
    return allocate(gpu, size, usage | VK_BUFFER_USAGE_TRANSFER_DST_BIT, {VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, kHost});
}

Buffer createDeviceBuffer(const Gpu& gpu, const std::vector<uint8_t>& bytes, VkBufferUsageFlags usage) {
    Buffer b = createDeviceBuffer(gpu, bytes.size(), usage);
    Buffer staging = createHostBuffer(gpu, b.size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
    std::memset(staging.mapped, 0, b.size);
    if (!bytes.empty()) std::memcpy(staging.mapped, bytes.data(), bytes.size());
    submitOnce(gpu, [&](VkCommandBuffer cmd) {
        VkBufferCopy region{0, 0, b.size};
        vkCmdCopyBuffer(cmd, staging.buffer, b.buffer, 1, &region);
    });
    destroyBuffer(gpu, staging);
    return b;
}

void destroyBuffer(const Gpu& gpu, Buffer& b) { destroyBuffer(gpu.device, b); }

VkCommandBuffer allocateCommandBuffer(const Gpu& gpu, VkCommandPool pool) { return allocateCommandBuffer(gpu.device, pool); }

void submitOnce(const Gpu& gpu, const std::function<void(VkCommandBuffer)>& record) {
    VkCommandBuffer cmd = allocateCommandBuffer(gpu, gpu.commandPool);
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    GT_VK(vkBeginCommandBuffer(cmd, &begin));
    record(cmd);
    GT_VK(vkEndCommandBuffer(cmd));
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &cmd;
    GT_VK(vkQueueSubmit(gpu.queue, 1, &submit, VK_NULL_HANDLE));
    GT_VK(vkQueueWaitIdle(gpu.queue));
    vkFreeCommandBuffers(gpu.device, gpu.commandPool, 1, &cmd);
}

}  // namespace gt
