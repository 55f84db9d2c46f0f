#include "storage.hpp"

#include <algorithm>

#include "check.hpp"

namespace gt {

std::vector<StorageBuffer> createStorageBuffers(const Gpu& gpu, const std::vector<StorageOption>& options) {
    const uint64_t range = gpu.properties.limits.maxStorageBufferRange;
    std::vector<StorageBuffer> storage;
    std::vector<size_t> filled;   // indices of the buffers that hold a file's bytes, not zeros
    for (const StorageOption& given : options) {
        StorageOption o = given;
        std::vector<uint8_t> data;
        if (!o.dataPath.empty()) {
            data = readFile(o.dataPath);
            if (data.empty() || data.size() % 4 != 0)
                fail("--storage-data: '" + o.dataPath + "' has " + std::to_string(data.size()) +
                     " bytes; expected a non-zero multiple of 4 (storage buffers hold 32-bit words)");
            o.bytes = data.size();
        }
        if (o.bytes > range)
            fail("--storage: BYTES " + std::to_string(o.bytes) + " in '" + std::to_string(o.binding) + ":" +
                 std::to_string(o.bytes) + "' exceeds " + gpu.properties.deviceName + "'s maxStorageBufferRange " +
                 std::to_string(range));
        StorageBuffer s;
        s.binding = o.binding;
        s.bytes = o.bytes;
        // TRANSFER_SRC for --dump-storage (TRANSFER_DST, for the fill, is added by createDeviceBuffer).
        const VkBufferUsageFlags usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
        if (data.empty()) {
            s.buffer = createDeviceBuffer(gpu, o.bytes, usage);
        } else {
            s.buffer = createDeviceBuffer(gpu, data, usage);   // filled through a staging copy, waited for
            filled.push_back(storage.size());
        }
        storage.push_back(s);
    }
    if (storage.size() == filled.size()) return storage;
    submitOnce(gpu, [&](VkCommandBuffer cmd) {
        for (size_t i = 0; i < storage.size(); i++)
            if (std::find(filled.begin(), filled.end(), i) == filled.end())
                vkCmdFillBuffer(cmd, storage[i].buffer.buffer, 0, VK_WHOLE_SIZE, 0);
        // The zeros must be visible to whatever reads or writes the buffers first in later
        // submissions (a compute kernel, or a graphics stage when no kernel writes it).
        VkMemoryBarrier zeros{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
        zeros.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        zeros.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_READ_BIT;
        vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0, 1, &zeros, 0,
                             nullptr, 0, nullptr);
    });
    return storage;
}

uint64_t dumpStorage(const Gpu& gpu, const std::vector<StorageBuffer>& storage, const StorageDump& dump) {
    const StorageBuffer* source = nullptr;
    for (const StorageBuffer& s : storage)
        if (s.binding == dump.binding) source = &s;
    if (!source) fail("--dump-storage: binding " + std::to_string(dump.binding) + " has no --storage buffer");

    const uint64_t bytes = dump.bytes ? dump.bytes : source->bytes;
    Buffer host = createHostBuffer(gpu, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    submitOnce(gpu, [&](VkCommandBuffer cmd) {
        // Shader writes of the frames (compute or graphics) -> this copy; the copy -> the host read.
        VkMemoryBarrier written{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
        written.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
        written.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
        vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 1, &written, 0,
                             nullptr, 0, nullptr);
        VkBufferCopy region{0, 0, bytes};
        vkCmdCopyBuffer(cmd, source->buffer.buffer, host.buffer, 1, &region);
        VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
        toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
        vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &toHost, 0, nullptr, 0,
                             nullptr);
    });
    try {
        writeFile(dump.path, host.mapped, bytes);
    } catch (const Error& e) {
        destroyBuffer(gpu, host);
        fail("--dump-storage '" + std::to_string(dump.binding) + ":" + dump.path + "': " + e.what());
    }
    destroyBuffer(gpu, host);
    return bytes;
}

void destroyStorageBuffers(const Gpu& gpu, std::vector<StorageBuffer>& storage) {
    for (StorageBuffer& s : storage) destroyBuffer(gpu, s.buffer);
    storage.clear();
}

}  // namespace gt
