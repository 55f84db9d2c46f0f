#include "device.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstring>
#include <vector>

#include "vkcommon.hpp"

namespace gt {

namespace {

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

const char* typeText(VkPhysicalDeviceType t) {
    switch (t) {
        case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return "integrated";
        case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return "discrete";
        case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return "virtual";
        case VK_PHYSICAL_DEVICE_TYPE_CPU: return "cpu";
        default: return "other";
    }
}

bool hasDeviceExtension(VkPhysicalDevice pd, const char* name) {
    uint32_t n = 0;
    vkEnumerateDeviceExtensionProperties(pd, nullptr, &n, nullptr);
    std::vector<VkExtensionProperties> ext(n);
    vkEnumerateDeviceExtensionProperties(pd, nullptr, &n, ext.data());
    for (const auto& e : ext)
        if (std::strcmp(e.extensionName, name) == 0) return true;
    return false;
}

struct DriverText {
    std::string name, info;
    VkDriverId id = static_cast<VkDriverId>(0);
};

DriverText driverText(VkPhysicalDevice pd) {
    VkPhysicalDeviceProperties p{};
    vkGetPhysicalDeviceProperties(pd, &p);
    DriverText t;
    if (p.apiVersion < VK_API_VERSION_1_2 && !hasDeviceExtension(pd, VK_KHR_DRIVER_PROPERTIES_EXTENSION_NAME)) return t;
    VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
    VkPhysicalDeviceProperties2 p2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
    p2.pNext = &driver;
    vkGetPhysicalDeviceProperties2(pd, &p2);
    t.name = driver.driverName;
    t.info = driver.driverInfo;
    t.id = driver.driverID;
    return t;
}

bool isLavapipe(const VkPhysicalDeviceProperties& p, const DriverText& d) {
    std::string n = lower(p.deviceName);
    return d.id == VK_DRIVER_ID_MESA_LLVMPIPE || n.find("llvmpipe") != std::string::npos ||
           n.find("lavapipe") != std::string::npos;
}

// The first family with graphics (and compute, when asked: the pre-pass is recorded in the same
// command buffer as the draw, so one queue must do both).
int graphicsQueueFamily(VkPhysicalDevice pd, bool compute, uint32_t* timestampBits) {
    const std::vector<VkQueueFamilyProperties> q = queueFamilies(pd);
    const VkQueueFlags needed = VK_QUEUE_GRAPHICS_BIT | (compute ? VK_QUEUE_COMPUTE_BIT : 0);
    for (uint32_t i = 0; i < q.size(); ++i)
        if ((q[i].queueFlags & needed) == needed) {
            *timestampBits = q[i].timestampValidBits;
            return static_cast<int>(i);
        }
    return -1;
}

// The first family with compute and without graphics: on desktop GPUs the queues that run
// alongside the graphics queue (NVIDIA's family 2, AMD's "async compute").
int computeOnlyQueueFamily(VkPhysicalDevice pd) {
    const std::vector<VkQueueFamilyProperties> q = queueFamilies(pd);
    for (uint32_t i = 0; i < q.size(); ++i)
        if ((q[i].queueFlags & VK_QUEUE_COMPUTE_BIT) && !(q[i].queueFlags & VK_QUEUE_GRAPHICS_BIT)) return static_cast<int>(i);
    return -1;
}

bool supportsTimelineSemaphores(VkPhysicalDevice pd) {
    VkPhysicalDeviceTimelineSemaphoreFeatures timeline{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_TIMELINE_SEMAPHORE_FEATURES};
    VkPhysicalDeviceFeatures2 f2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    f2.pNext = &timeline;
    vkGetPhysicalDeviceFeatures2(pd, &f2);
    return timeline.timelineSemaphore == VK_TRUE;
}

}  // namespace

void listDevices() {
    VkInstance instance = createInstance("gt-harness");
    auto list = physicalDevices(instance);
    for (size_t i = 0; i < list.size(); ++i) {
        VkPhysicalDeviceProperties p{};
        vkGetPhysicalDeviceProperties(list[i], &p);
        DriverText d = driverText(list[i]);
        std::printf("device %zu %s | type %s | api %s | driver %s %s\n", i, p.deviceName, typeText(p.deviceType),
                    versionText(p.apiVersion).c_str(), d.name.c_str(), d.info.c_str());
    }
    if (list.empty()) std::printf("no Vulkan devices\n");
    vkDestroyInstance(instance, nullptr);
}

Gpu createGpu(const std::string& nameSubstring, const FeatureRequest& request) {
    Gpu gpu;
    gpu.instance = createInstance("gt-harness");
    auto list = physicalDevices(gpu.instance);
    if (list.empty()) fail("no Vulkan physical device found (is a driver installed? VK_ICD_FILENAMES?)");

    std::string names;
    for (VkPhysicalDevice pd : list) {
        VkPhysicalDeviceProperties p{};
        vkGetPhysicalDeviceProperties(pd, &p);
        names += std::string(names.empty() ? "" : ", ") + "'" + p.deviceName + "'";
        if (lower(p.deviceName).find(lower(nameSubstring)) != std::string::npos) {
            gpu.physical = pd;
            break;
        }
    }
    if (!gpu.physical) fail("--device '" + nameSubstring + "' matches none of the devices: " + names);

    vkGetPhysicalDeviceProperties(gpu.physical, &gpu.properties);
    vkGetPhysicalDeviceMemoryProperties(gpu.physical, &gpu.memory);
    if (gpu.properties.apiVersion < VK_API_VERSION_1_1)
        fail(std::string(gpu.properties.deviceName) + " supports only Vulkan " + versionText(gpu.properties.apiVersion) +
             "; need 1.1 (negative viewport height)");
    DriverText d = driverText(gpu.physical);
    gpu.driverName = d.name;
    gpu.driverInfo = d.info;
    gpu.isLavapipe = isLavapipe(gpu.properties, d);

    int family = graphicsQueueFamily(gpu.physical, request.compute, &gpu.timestampValidBits);
    if (family < 0)
        fail(std::string(gpu.properties.deviceName) + " has no graphics queue" +
             (request.compute ? " that also does compute (needed for --compute)" : ""));
    gpu.queueFamily = static_cast<uint32_t>(family);
    if (request.asyncCompute) {
        const int computeFamily = computeOnlyQueueFamily(gpu.physical);
        if (computeFamily < 0)
            fail("--async-compute: " + std::string(gpu.properties.deviceName) +
                 " has no queue family with compute and without graphics (drop --async-compute: the pre-pass then "
                 "runs on the graphics queue)");
        gpu.computeFamily = static_cast<uint32_t>(computeFamily);
        gpu.asyncCompute = true;
    }
    const bool timeline = request.timeline || request.asyncCompute;
    if (timeline && (gpu.properties.apiVersion < VK_API_VERSION_1_2 || !supportsTimelineSemaphores(gpu.physical)))
        fail(std::string(gpu.properties.deviceName) +
             " lacks the Vulkan 1.2 feature timelineSemaphore, needed for --in-flight above 1 and --async-compute");

    VkPhysicalDeviceFeatures supported{};
    vkGetPhysicalDeviceFeatures(gpu.physical, &supported);
    const std::string dev = gpu.properties.deviceName;
    auto need = [&](bool wanted, VkBool32 has, VkBool32& enable, const char* feature, const char* why) {
        if (!wanted) return;
        if (!has) fail(dev + " lacks the Vulkan feature " + feature + ", needed for " + why);
        enable = VK_TRUE;
    };
    need(request.tessellation, supported.tessellationShader, gpu.enabled.tessellationShader, "tessellationShader",
         "the tessellated draw (use the fallback mode: no --tesc/--tese)");
    need(request.wireframe, supported.fillModeNonSolid, gpu.enabled.fillModeNonSolid, "fillModeNonSolid", "--wireframe");
    need(request.depthClamp, supported.depthClamp, gpu.enabled.depthClamp, "depthClamp", "--zclip off");
    need(request.vertexStores, supported.vertexPipelineStoresAndAtomics, gpu.enabled.vertexPipelineStoresAndAtomics,
         "vertexPipelineStoresAndAtomics", "--readback (the domain/vertex stage writes _Readback)");
    need(request.statistics, supported.pipelineStatisticsQuery, gpu.enabled.pipelineStatisticsQuery,
         "pipelineStatisticsQuery", "--stats");
    // Turned on whenever available: harmless, and a statistics query may then count tessellation.
    gpu.enabled.tessellationShader = supported.tessellationShader;

    float priority = 1.0f;
    VkDeviceQueueCreateInfo queueInfos[2] = {{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO},
                                             {VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO}};
    queueInfos[0].queueFamilyIndex = gpu.queueFamily;
    queueInfos[0].queueCount = 1;
    queueInfos[0].pQueuePriorities = &priority;
    queueInfos[1] = queueInfos[0];
    queueInfos[1].queueFamilyIndex = gpu.computeFamily;
    VkPhysicalDeviceTimelineSemaphoreFeatures timelineFeature{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_TIMELINE_SEMAPHORE_FEATURES};
    timelineFeature.timelineSemaphore = VK_TRUE;
    VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    info.pNext = timeline ? &timelineFeature : nullptr;
    info.queueCreateInfoCount = gpu.asyncCompute ? 2 : 1;
    info.pQueueCreateInfos = queueInfos;
    info.pEnabledFeatures = &gpu.enabled;
    GT_VK(vkCreateDevice(gpu.physical, &info, nullptr, &gpu.device));
    vkGetDeviceQueue(gpu.device, gpu.queueFamily, 0, &gpu.queue);
    gpu.commandPool = createCommandPool(gpu.device, gpu.queueFamily, VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT);
    if (gpu.asyncCompute) {
        vkGetDeviceQueue(gpu.device, gpu.computeFamily, 0, &gpu.computeQueue);
        gpu.computePool = createCommandPool(gpu.device, gpu.computeFamily, VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT);
    }
    return gpu;
}

void destroyGpu(Gpu& gpu) {
    if (gpu.device) {
        vkDeviceWaitIdle(gpu.device);
        if (gpu.commandPool) vkDestroyCommandPool(gpu.device, gpu.commandPool, nullptr);
        if (gpu.computePool) vkDestroyCommandPool(gpu.device, gpu.computePool, nullptr);
        vkDestroyDevice(gpu.device, nullptr);
    }
    if (gpu.instance) vkDestroyInstance(gpu.instance, nullptr);
    gpu = Gpu{};
}

void printDevice(const Gpu& gpu) {
    const auto& p = gpu.properties;
    std::printf("device name %s\n", p.deviceName);
    std::printf("device type %s\n", typeText(p.deviceType));
    std::printf("device api %s\n", versionText(p.apiVersion).c_str());
    std::printf("device driver_version 0x%08x\n", p.driverVersion);
    std::printf("device driver %s | %s\n", gpu.driverName.empty() ? "unknown" : gpu.driverName.c_str(),
                gpu.driverInfo.c_str());
    std::printf("device lavapipe %d\n", gpu.isLavapipe ? 1 : 0);
    if (gpu.asyncCompute) std::printf("device async_compute_family %u\n", gpu.computeFamily);
}

}  // namespace gt
