#include "buffers.hpp"

#include <cstdio>
#include <cstring>
#include <fstream>

#include "check.hpp"

namespace gt {

namespace {

int findMemoryType(const Gpu& gpu, uint32_t typeBits, VkMemoryPropertyFlags required) {
    for (uint32_t i = 0; i < gpu.memory.memoryTypeCount; ++i)
        if ((typeBits & (1u << i)) && (gpu.memory.memoryTypes[i].propertyFlags & required) == required)
            return static_cast<int>(i);
    return -1;
}

Buffer allocate(const Gpu& gpu, VkDeviceSize size, VkBufferUsageFlags usage,
                std::initializer_list<VkMemoryPropertyFlags> preferences) {
    Buffer b;
    b.size = size < 16 ? 16 : size;  // never a zero-sized buffer
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = b.size;
    info.usage = usage;
    // Async compute: the compute family writes what the graphics family reads; concurrent
    // sharing makes that legal without a release/acquire pair on every frame.
    const uint32_t families[2] = {gpu.queueFamily, gpu.computeFamily};
    info.sharingMode = gpu.asyncCompute ? VK_SHARING_MODE_CONCURRENT : VK_SHARING_MODE_EXCLUSIVE;
    info.queueFamilyIndexCount = gpu.asyncCompute ? 2 : 0;
    info.pQueueFamilyIndices = gpu.asyncCompute ? families : nullptr;
    GT_VK(vkCreateBuffer(gpu.device, &info, nullptr, &b.buffer));
    VkMemoryRequirements req{};
    vkGetBufferMemoryRequirements(gpu.device, b.buffer, &req);
    int type = -1;
    VkMemoryPropertyFlags chosen = 0;
    for (VkMemoryPropertyFlags flags : preferences) {
        type = findMemoryType(gpu, req.memoryTypeBits, flags);
        if (type >= 0) { chosen = flags; break; }
    }
    if (type < 0) fail("no memory type for a buffer of " + std::to_string(size) + " bytes");
    VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    alloc.allocationSize = req.size;
    alloc.memoryTypeIndex = static_cast<uint32_t>(type);
    VkResult r = vkAllocateMemory(gpu.device, &alloc, nullptr, &b.memory);
    if (r != VK_SUCCESS) fail("cannot allocate " + std::to_string(req.size) + " bytes of buffer memory: " + resultName(r));
    GT_VK(vkBindBufferMemory(gpu.device, b.buffer, b.memory, 0));
    if (chosen & VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT) GT_VK(vkMapMemory(gpu.device, b.memory, 0, VK_WHOLE_SIZE, 0, &b.mapped));
    return b;
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

void destroyBuffer(const Gpu& gpu, Buffer& b) {
    if (b.mapped) vkUnmapMemory(gpu.device, b.memory);
    if (b.buffer) vkDestroyBuffer(gpu.device, b.buffer, nullptr);
    if (b.memory) vkFreeMemory(gpu.device, b.memory, nullptr);
    b = Buffer{};
}

VkCommandBuffer allocateCommandBuffer(const Gpu& gpu, VkCommandPool pool) {
    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = pool;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    GT_VK(vkAllocateCommandBuffers(gpu.device, &alloc, &cmd));
    return cmd;
}

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

std::vector<uint8_t> readFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    if (!in) fail("cannot open '" + path + "'");
    std::streamsize n = in.tellg();
    in.seekg(0);
    std::vector<uint8_t> bytes(static_cast<size_t>(n));
    if (n > 0 && !in.read(reinterpret_cast<char*>(bytes.data()), n)) fail("cannot read '" + path + "'");
    return bytes;
}

void writeFile(const std::string& path, const void* data, size_t size) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (!out) fail("cannot create '" + path + "'");
    out.write(static_cast<const char*>(data), static_cast<std::streamsize>(size));
    if (!out) fail("cannot write '" + path + "'");
}

}  // namespace gt
