// The Vulkan side of gt-compute: instance, device, buffers, one compute pipeline, one submission.
#pragma once
#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <vector>

#include "cli.h"

struct GpuBuffer {
    uint32_t binding = 0;
    bool uniform = false;
    VkDeviceSize size = 0;
    VkBuffer buffer = VK_NULL_HANDLE;        // device-local, what the kernel sees
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkBuffer staging = VK_NULL_HANDLE;       // host-visible, for upload and readback
    VkDeviceMemory stagingMemory = VK_NULL_HANDLE;
    void* mapped = nullptr;
};

struct RunResult {
    std::vector<double> dispatchMs; // one per dispatch when timed
};

class Gpu {
public:
    // Prints every physical device's name (for --list-devices).
    static void ListDevices();

    // Opens the first device whose name contains `nameSubstring` (any device if empty) that has a
    // compute queue; throws std::runtime_error with the reason otherwise.
    explicit Gpu(const std::string& nameSubstring);
    ~Gpu();
    Gpu(const Gpu&) = delete;
    Gpu& operator=(const Gpu&) = delete;

    const std::string& DeviceName() const { return deviceName_; }

    // Creates the buffer of one --uniform/--buffer/--zeros argument and fills its staging copy.
    void AddBuffer(const BufferArg& arg, const std::vector<char>& contents);

    // Builds the pipeline, records upload, `repeat` dispatches (barrier between), readback; waits.
    RunResult Run(const std::vector<uint32_t>& spirv, const std::string& entry, const uint32_t groups[3],
                  uint32_t repeat, bool timestamps);

    // The bytes of storage buffer `binding` after Run.
    std::vector<char> Read(uint32_t binding) const;

private:
    uint32_t MemoryType(uint32_t typeBits, VkMemoryPropertyFlags want) const;
    void CreateBuffer(VkDeviceSize size, VkBufferUsageFlags usage, VkMemoryPropertyFlags props,
                      VkBuffer* buffer, VkDeviceMemory* memory, bool* coherent = nullptr);

    VkInstance instance_ = VK_NULL_HANDLE;
    VkPhysicalDevice physical_ = VK_NULL_HANDLE;
    VkDevice device_ = VK_NULL_HANDLE;
    VkQueue queue_ = VK_NULL_HANDLE;
    uint32_t queueFamily_ = 0;
    uint32_t timestampBits_ = 0;
    float timestampPeriodNs_ = 1.0f;
    std::string deviceName_;
    VkPhysicalDeviceMemoryProperties memoryProps_{};
    std::vector<GpuBuffer> buffers_;
    bool stagingCoherent_ = true;
};
