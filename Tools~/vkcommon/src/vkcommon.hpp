// The Vulkan setup both rig runners share (gt-harness draws, gt-compute dispatches): headless
// instance, devices and queue families, buffers with a memory preference list, shader modules,
// command pools and buffers, whole files. Each runner picks its own device and queues from these.
#pragma once
#include <cstdint>
#include <initializer_list>
#include <string>
#include <vector>
#include <vulkan/vulkan.h>

#include "check.hpp"

namespace gt {

// "1.2.3".
std::string versionText(uint32_t version);

// A headless instance (no extensions: nothing may depend on a display) at Vulkan 1.2 when the
// loader has it, else 1.1. Throws gt::Error when the loader is older than 1.1 or finds no driver.
VkInstance createInstance(const char* applicationName);

std::vector<VkPhysicalDevice> physicalDevices(VkInstance instance);

std::vector<VkQueueFamilyProperties> queueFamilies(VkPhysicalDevice device);

// The first queue family whose flags include all of `needed`, or -1.
int queueFamilyWith(VkPhysicalDevice device, VkQueueFlags needed);

VkCommandPool createCommandPool(VkDevice device, uint32_t family, VkCommandPoolCreateFlags flags);

// A primary command buffer from pool.
VkCommandBuffer allocateCommandBuffer(VkDevice device, VkCommandPool pool);

struct Buffer {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkDeviceSize size = 0;
    VkMemoryPropertyFlags memoryFlags = 0;  // the preference that was met
    void* mapped = nullptr;                 // non-null for host-visible memory (kept mapped)
};

// Where buffers come from: the device, its memory types, and the queue families that share the
// buffers (two or more: VK_SHARING_MODE_CONCURRENT, no ownership transfers; else exclusive).
struct BufferHeap {
    VkDevice device = VK_NULL_HANDLE;
    VkPhysicalDeviceMemoryProperties memory{};
    std::vector<uint32_t> sharedFamilies;
};

// The first memory type in typeBits with all of `required`, or -1.
int findMemoryType(const VkPhysicalDeviceMemoryProperties& memory, uint32_t typeBits, VkMemoryPropertyFlags required);

// A buffer of max(size, 16) bytes (never zero-sized) in the first memory type that meets one of
// `preferences`, tried in order; mapped when that memory is host-visible. Throws gt::Error naming
// the size when no memory type fits or the allocation fails.
Buffer createBuffer(const BufferHeap& heap, VkDeviceSize size, VkBufferUsageFlags usage,
                    std::initializer_list<VkMemoryPropertyFlags> preferences);

void destroyBuffer(VkDevice device, Buffer& buffer);

// One buffer descriptor of a set: the whole buffer at `binding`.
struct DescriptorEntry {
    uint32_t binding;
    VkDescriptorType type;
    VkBuffer buffer;
};

// Points each entry's binding of `set` at its buffer (one descriptor each, VK_WHOLE_SIZE).
void writeBufferDescriptors(VkDevice device, VkDescriptorSet set, const std::vector<DescriptorEntry>& entries);

// The module of SPIR-V words (checked by the caller).
VkShaderModule createShaderModule(VkDevice device, const std::vector<uint32_t>& words);

// The whole file; throws gt::Error naming it when it cannot be read.
std::vector<uint8_t> readFile(const std::string& path);

void writeFile(const std::string& path, const void* data, size_t size);

// The file as SPIR-V words; throws gt::Error naming it when its size or magic number is not SPIR-V's.
std::vector<uint32_t> readSpirv(const std::string& path);

}  // namespace gt
