// Buffers and memory: device-local buffers filled once through a staging copy, host-visible
// ones for what the CPU writes or reads every frame, and a one-shot command helper.
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "device.hpp"
#include "vkcommon.hpp"

namespace gt {

// gt::Buffer (vkcommon.hpp): the harness's host-visible buffers are always coherent, kept mapped.

// Host-visible + coherent; prefers memory that is also device-local (resizable BAR) when
// preferDeviceLocal is set, so a per-frame uniform buffer is not read across the bus.
Buffer createHostBuffer(const Gpu& gpu, VkDeviceSize size, VkBufferUsageFlags usage, bool preferDeviceLocal = false);

// Device-local buffer of bytes.size() (at least 16) filled through a staging buffer.
Buffer createDeviceBuffer(const Gpu& gpu, const std::vector<uint8_t>& bytes, VkBufferUsageFlags usage);

// Device-local, uninitialised.
Buffer createDeviceBuffer(const Gpu& gpu, VkDeviceSize size, VkBufferUsageFlags usage);

void destroyBuffer(const Gpu& gpu, Buffer& buffer);

// A primary command buffer from pool (the graphics pool, or the async compute one).
VkCommandBuffer allocateCommandBuffer(const Gpu& gpu, VkCommandPool pool);

// Records into a fresh command buffer, submits, waits.
void submitOnce(const Gpu& gpu, const std::function<void(VkCommandBuffer)>& record);

}  // namespace gt
