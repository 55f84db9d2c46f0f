// Device selection: instance without any window-system extension, one physical device picked
// by name, one queue that does graphics (and so transfers; and compute when --compute asks), with
// --async-compute a second queue of a compute-only family, the features the run asks for.
#pragma once
#include <string>
#include <vulkan/vulkan.h>

namespace gt {

struct FeatureRequest {
    bool tessellation = false;    // tessellationShader
    bool wireframe = false;       // fillModeNonSolid
    bool depthClamp = false;      // depthClamp (--zclip off)
    bool vertexStores = false;    // vertexPipelineStoresAndAtomics (readback from the domain/vertex stage)
    bool statistics = false;      // pipelineStatisticsQuery
    bool compute = false;         // the queue must also do compute (--compute pre-pass in the frame)
    bool timeline = false;        // timelineSemaphore (Vulkan 1.2): frames in flight (--in-flight 2)
    bool asyncCompute = false;    // a second queue from a compute-only family (--async-compute)
};

struct Gpu {
    VkInstance instance = VK_NULL_HANDLE;
    VkPhysicalDevice physical = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    VkQueue queue = VK_NULL_HANDLE;
    uint32_t queueFamily = 0;
    VkCommandPool commandPool = VK_NULL_HANDLE;
    // --async-compute: a queue of a family with compute and no graphics, its own pool. Buffers are
    // then created VK_SHARING_MODE_CONCURRENT over both families (no ownership transfers).
    VkQueue computeQueue = VK_NULL_HANDLE;
    uint32_t computeFamily = 0;
    VkCommandPool computePool = VK_NULL_HANDLE;
    bool asyncCompute = false;

    VkPhysicalDeviceProperties properties{};
    VkPhysicalDeviceMemoryProperties memory{};
    VkPhysicalDeviceFeatures enabled{};  // what was turned on
    std::string driverName, driverInfo;  // VK_KHR_driver_properties / Vulkan 1.2, "" if unavailable
    bool isLavapipe = false;             // Mesa's CPU driver (llvmpipe): Tools~/rig/README.md, "The rig's drivers"
    // The rig's uniform blocks (TerrainParams, the camera) bound as storage buffers: see
    // uniformBlocksAsStorage in spirv.hpp. Set by --uniform-blocks before any shader is loaded.
    bool uniformBlocksAsStorage = false;
    uint32_t timestampValidBits = 0;     // of the chosen queue family; 0 = no timestamps
};

// Prints one line per physical device: "device INDEX NAME | type T | api X.Y.Z | driver ...".
void listDevices();

// Creates the instance and the device. Throws gt::Error naming the missing feature, or the
// substring that matched no device.
Gpu createGpu(const std::string& nameSubstring, const FeatureRequest& request);

void destroyGpu(Gpu& gpu);

// Prints the chosen device: "device name ...", "device api ...", "device driver ...".
void printDevice(const Gpu& gpu);

}  // namespace gt
