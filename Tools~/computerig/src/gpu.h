// The Vulkan side of gt-compute: instance, device, buffers, one compute pipeline, one submission.
#pragma once
#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <vector>

#include "cli.h"
#include "vkcommon.hpp"

struct GpuBuffer {
    uint32_t binding = 0;
    bool uniform = false;
    VkDeviceSize size = 0;      // the argument's bytes (the buffers may be larger: at least 16)
    gt::Buffer device;          // device-local, what the kernel sees
    gt::Buffer staging;         // host-visible, kept mapped, for upload and readback
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
    void AddBuffer(const BufferArg& arg, const std::vector<uint8_t>& contents);

    // Builds the pipeline, records upload, `repeat` dispatches (barrier between), readback; waits.
    RunResult Run(const std::vector<uint32_t>& spirv, const std::string& entry, const uint32_t groups[3],
                  uint32_t repeat, bool timestamps);

    // The bytes of storage buffer `binding` after Run.
    std::vector<uint8_t> Read(uint32_t binding) const;

private:
    VkInstance instance_ = VK_NULL_HANDLE;
    VkPhysicalDevice physical_ = VK_NULL_HANDLE;
    VkDevice device_ = VK_NULL_HANDLE;
    VkQueue queue_ = VK_NULL_HANDLE;
    uint32_t queueFamily_ = 0;
    uint32_t timestampBits_ = 0;
    float timestampPeriodNs_ = 1.0f;
    std::string deviceName_;
    gt::BufferHeap heap_;  // device_ and its memory types
    std::vector<GpuBuffer> buffers_;
    bool stagingCoherent_ = true;
};
