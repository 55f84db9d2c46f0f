#include "vkcommon.hpp"

#include <cstring>
#include <fstream>

namespace gt {

std::string versionText(uint32_t v) {
    return std::to_string(VK_API_VERSION_MAJOR(v)) + "." + std::to_string(VK_API_VERSION_MINOR(v)) + "." +
           std::to_string(VK_API_VERSION_PATCH(v));
}

VkInstance createInstance(const char* applicationName) {
    // Vulkan 1.2 when the loader has it (driver properties and timeline semaphores are core there), else 1.1.
    uint32_t loaderVersion = VK_API_VERSION_1_0;
    auto enumerateVersion = reinterpret_cast<PFN_vkEnumerateInstanceVersion>(
        vkGetInstanceProcAddr(VK_NULL_HANDLE, "vkEnumerateInstanceVersion"));
    if (enumerateVersion) enumerateVersion(&loaderVersion);
    if (loaderVersion < VK_API_VERSION_1_1) fail("the Vulkan loader supports only " + versionText(loaderVersion) + "; need 1.1");

    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = applicationName;
    app.apiVersion = loaderVersion >= VK_API_VERSION_1_2 ? VK_API_VERSION_1_2 : VK_API_VERSION_1_1;
    VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    info.pApplicationInfo = &app;  // no extensions: nothing here may depend on a display
    VkInstance instance = VK_NULL_HANDLE;
    VkResult r = vkCreateInstance(&info, nullptr, &instance);
    if (r == VK_ERROR_INCOMPATIBLE_DRIVER)
        fail("no Vulkan driver found (VK_ERROR_INCOMPATIBLE_DRIVER); for lavapipe set "
             "VK_ICD_FILENAMES=/usr/share/vulkan/icd.d/lvp_icd.x86_64.json");
    GT_VK(r);
    return instance;
}

std::vector<VkPhysicalDevice> physicalDevices(VkInstance instance) {
    uint32_t n = 0;
    GT_VK(vkEnumeratePhysicalDevices(instance, &n, nullptr));
    std::vector<VkPhysicalDevice> list(n);
    GT_VK(vkEnumeratePhysicalDevices(instance, &n, list.data()));
    list.resize(n);
    return list;
}

std::vector<VkQueueFamilyProperties> queueFamilies(VkPhysicalDevice pd) {
    uint32_t n = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(pd, &n, nullptr);
    std::vector<VkQueueFamilyProperties> q(n);
    vkGetPhysicalDeviceQueueFamilyProperties(pd, &n, q.data());
    q.resize(n);
    return q;
}

int queueFamilyWith(VkPhysicalDevice pd, VkQueueFlags needed) {
    const std::vector<VkQueueFamilyProperties> q = queueFamilies(pd);
    for (uint32_t i = 0; i < q.size(); ++i)
        if ((q[i].queueFlags & needed) == needed) return static_cast<int>(i);
    return -1;
}

VkCommandPool createCommandPool(VkDevice device, uint32_t family, VkCommandPoolCreateFlags flags) {
    VkCommandPoolCreateInfo info{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    info.flags = flags;
    info.queueFamilyIndex = family;
    VkCommandPool pool = VK_NULL_HANDLE;
    GT_VK(vkCreateCommandPool(device, &info, nullptr, &pool));
    return pool;
}

VkCommandBuffer allocateCommandBuffer(VkDevice device, VkCommandPool pool) {
    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = pool;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    GT_VK(vkAllocateCommandBuffers(device, &alloc, &cmd));
    return cmd;
}

int findMemoryType(const VkPhysicalDeviceMemoryProperties& memory, uint32_t typeBits, VkMemoryPropertyFlags required) {
    for (uint32_t i = 0; i < memory.memoryTypeCount; ++i)
        if ((typeBits & (1u << i)) && (memory.memoryTypes[i].propertyFlags & required) == required)
            return static_cast<int>(i);
    return -1;
}

Buffer createBuffer(const BufferHeap& heap, VkDeviceSize size, VkBufferUsageFlags usage,
                    std::initializer_list<VkMemoryPropertyFlags> preferences) {
    Buffer b;
    b.size = size < 16 ? 16 : size;  // never a zero-sized buffer
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = b.size;
    info.usage = usage;
    const bool concurrent = heap.sharedFamilies.size() > 1;
    info.sharingMode = concurrent ? VK_SHARING_MODE_CONCURRENT : VK_SHARING_MODE_EXCLUSIVE;
    info.queueFamilyIndexCount = concurrent ? static_cast<uint32_t>(heap.sharedFamilies.size()) : 0;
    info.pQueueFamilyIndices = concurrent ? heap.sharedFamilies.data() : nullptr;
    GT_VK(vkCreateBuffer(heap.device, &info, nullptr, &b.buffer));
    VkMemoryRequirements req{};
    vkGetBufferMemoryRequirements(heap.device, b.buffer, &req);
    int type = -1;
    for (VkMemoryPropertyFlags flags : preferences) {
        type = findMemoryType(heap.memory, req.memoryTypeBits, flags);
        if (type >= 0) { b.memoryFlags = flags; break; }
    }
    if (type < 0) {
        vkDestroyBuffer(heap.device, b.buffer, nullptr);
        fail("no memory type for a buffer of " + std::to_string(size) + " bytes");
    }
    VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    alloc.allocationSize = req.size;
    alloc.memoryTypeIndex = static_cast<uint32_t>(type);
    VkResult r = vkAllocateMemory(heap.device, &alloc, nullptr, &b.memory);
    if (r != VK_SUCCESS) {
        vkDestroyBuffer(heap.device, b.buffer, nullptr);
        fail("cannot allocate " + std::to_string(req.size) + " bytes of buffer memory: " + resultName(r));
    }
    GT_VK(vkBindBufferMemory(heap.device, b.buffer, b.memory, 0));
    if (b.memoryFlags & VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT) GT_VK(vkMapMemory(heap.device, b.memory, 0, VK_WHOLE_SIZE, 0, &b.mapped));
    return b;
}

void destroyBuffer(VkDevice device, Buffer& b) {
    if (b.mapped) vkUnmapMemory(device, b.memory);
    if (b.buffer) vkDestroyBuffer(device, b.buffer, nullptr);
    if (b.memory) vkFreeMemory(device, b.memory, nullptr);
    b = Buffer{};
}

void writeBufferDescriptors(VkDevice device, VkDescriptorSet set, const std::vector<DescriptorEntry>& entries) {
    std::vector<VkDescriptorBufferInfo> infos(entries.size());
    std::vector<VkWriteDescriptorSet> writes(entries.size());
    for (size_t i = 0; i < entries.size(); ++i) {
        infos[i] = {entries[i].buffer, 0, VK_WHOLE_SIZE};
        writes[i] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        writes[i].dstSet = set;
        writes[i].dstBinding = entries[i].binding;
        writes[i].descriptorCount = 1;
        writes[i].descriptorType = entries[i].type;
        writes[i].pBufferInfo = &infos[i];
    }
    vkUpdateDescriptorSets(device, static_cast<uint32_t>(writes.size()), writes.data(), 0, nullptr);
}

VkShaderModule createShaderModule(VkDevice device, const std::vector<uint32_t>& words) {
    VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    info.codeSize = words.size() * sizeof(uint32_t);
    info.pCode = words.data();
    VkShaderModule module = VK_NULL_HANDLE;
    GT_VK(vkCreateShaderModule(device, &info, nullptr, &module));
    return module;
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

std::vector<uint32_t> readSpirv(const std::string& path) {
    constexpr uint32_t kMagic = 0x07230203;
    std::vector<uint8_t> bytes = readFile(path);
    if (bytes.size() < 20 || bytes.size() % 4 != 0)
        fail("'" + path + "' is not SPIR-V (" + std::to_string(bytes.size()) + " bytes, not a multiple of 4 >= 20)");
    std::vector<uint32_t> words(bytes.size() / 4);
    std::memcpy(words.data(), bytes.data(), bytes.size());
    if (words[0] != kMagic) fail("'" + path + "' is not SPIR-V (bad magic number)");
    return words;
}

}  // namespace gt
