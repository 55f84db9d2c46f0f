#include "gpu.h"

#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace {

void Check(VkResult r, const char* what)
{
    if (r != VK_SUCCESS) throw std::runtime_error(std::string(what) + " failed (VkResult " + std::to_string(r) + ")");
}

VkInstance CreateInstance()
{
    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "gt-compute";
    app.apiVersion = VK_API_VERSION_1_1;
    VkInstanceCreateInfo ci{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    ci.pApplicationInfo = &app;
    VkInstance instance = VK_NULL_HANDLE;
    Check(vkCreateInstance(&ci, nullptr, &instance), "vkCreateInstance");
    return instance;
}

std::vector<VkPhysicalDevice> PhysicalDevices(VkInstance instance)
{
    uint32_t n = 0;
    Check(vkEnumeratePhysicalDevices(instance, &n, nullptr), "vkEnumeratePhysicalDevices");
    std::vector<VkPhysicalDevice> devices(n);
    Check(vkEnumeratePhysicalDevices(instance, &n, devices.data()), "vkEnumeratePhysicalDevices");
    return devices;
}

// The first queue family with compute; UINT32_MAX if none.
uint32_t ComputeFamily(VkPhysicalDevice pd, uint32_t* timestampBits)
{
    uint32_t n = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(pd, &n, nullptr);
    std::vector<VkQueueFamilyProperties> families(n);
    vkGetPhysicalDeviceQueueFamilyProperties(pd, &n, families.data());
    for (uint32_t i = 0; i < n; ++i)
        if (families[i].queueFlags & VK_QUEUE_COMPUTE_BIT) {
            *timestampBits = families[i].timestampValidBits;
            return i;
        }
    return UINT32_MAX;
}

VkMemoryBarrier FullBarrier()
{
    VkMemoryBarrier b{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    b.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT;
    b.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_UNIFORM_READ_BIT |
                      VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_HOST_READ_BIT;
    return b;
}

} // namespace

void Gpu::ListDevices()
{
    VkInstance instance = CreateInstance();
    for (VkPhysicalDevice pd : PhysicalDevices(instance)) {
        VkPhysicalDeviceProperties p;
        vkGetPhysicalDeviceProperties(pd, &p);
        std::printf("device %s\n", p.deviceName);
    }
    vkDestroyInstance(instance, nullptr);
}

Gpu::Gpu(const std::string& nameSubstring)
{
    instance_ = CreateInstance();
    std::string seen;
    for (VkPhysicalDevice pd : PhysicalDevices(instance_)) {
        VkPhysicalDeviceProperties p;
        vkGetPhysicalDeviceProperties(pd, &p);
        seen += std::string(seen.empty() ? "" : ", ") + p.deviceName;
        if (!nameSubstring.empty() && std::string(p.deviceName).find(nameSubstring) == std::string::npos) continue;
        uint32_t bits = 0;
        uint32_t family = ComputeFamily(pd, &bits);
        if (family == UINT32_MAX) continue;
        physical_ = pd;
        queueFamily_ = family;
        timestampBits_ = p.limits.timestampComputeAndGraphics ? bits : 0;
        timestampPeriodNs_ = p.limits.timestampPeriod;
        deviceName_ = p.deviceName;
        break;
    }
    if (physical_ == VK_NULL_HANDLE)
        throw std::runtime_error("no Vulkan device with a compute queue matches '" + nameSubstring + "' (devices: " +
                                 (seen.empty() ? "none" : seen) + ")");
    vkGetPhysicalDeviceMemoryProperties(physical_, &memoryProps_);

    float priority = 1.0f;
    VkDeviceQueueCreateInfo qci{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    qci.queueFamilyIndex = queueFamily_;
    qci.queueCount = 1;
    qci.pQueuePriorities = &priority;
    VkDeviceCreateInfo dci{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    dci.queueCreateInfoCount = 1;
    dci.pQueueCreateInfos = &qci;
    Check(vkCreateDevice(physical_, &dci, nullptr, &device_), "vkCreateDevice");
    vkGetDeviceQueue(device_, queueFamily_, 0, &queue_);
}

Gpu::~Gpu()
{
    if (device_ != VK_NULL_HANDLE) {
        vkDeviceWaitIdle(device_);
        for (GpuBuffer& b : buffers_) {
            vkDestroyBuffer(device_, b.buffer, nullptr);
            vkFreeMemory(device_, b.memory, nullptr);
            vkDestroyBuffer(device_, b.staging, nullptr);
            vkFreeMemory(device_, b.stagingMemory, nullptr);
        }
        vkDestroyDevice(device_, nullptr);
    }
    if (instance_ != VK_NULL_HANDLE) vkDestroyInstance(instance_, nullptr);
}

uint32_t Gpu::MemoryType(uint32_t typeBits, VkMemoryPropertyFlags want) const
{
    for (uint32_t i = 0; i < memoryProps_.memoryTypeCount; ++i)
        if ((typeBits & (1u << i)) && (memoryProps_.memoryTypes[i].propertyFlags & want) == want) return i;
    return UINT32_MAX;
}

void Gpu::CreateBuffer(VkDeviceSize size, VkBufferUsageFlags usage, VkMemoryPropertyFlags props, VkBuffer* buffer,
                       VkDeviceMemory* memory, bool* coherent)
{
    VkBufferCreateInfo bci{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    bci.size = size;
    bci.usage = usage;
    bci.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    Check(vkCreateBuffer(device_, &bci, nullptr, buffer), "vkCreateBuffer");
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(device_, *buffer, &req);
    uint32_t type = MemoryType(req.memoryTypeBits, props | (coherent ? VK_MEMORY_PROPERTY_HOST_COHERENT_BIT : 0));
    if (coherent) *coherent = type != UINT32_MAX;
    if (type == UINT32_MAX) type = MemoryType(req.memoryTypeBits, props);
    if (type == UINT32_MAX) throw std::runtime_error("no memory type for a buffer of " + std::to_string(size) + " bytes");
    VkMemoryAllocateInfo mai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    mai.allocationSize = req.size;
    mai.memoryTypeIndex = type;
    Check(vkAllocateMemory(device_, &mai, nullptr, memory), "vkAllocateMemory");
    Check(vkBindBufferMemory(device_, *buffer, *memory, 0), "vkBindBufferMemory");
}

void Gpu::AddBuffer(const BufferArg& arg, const std::vector<char>& contents)
{
    GpuBuffer b;
    b.binding = arg.binding;
    b.uniform = arg.uniform;
    b.size = contents.size();
    if (b.size == 0) throw std::runtime_error("binding " + std::to_string(arg.binding) + ": empty buffer");
    VkBufferUsageFlags usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT |
                               (arg.uniform ? VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT : VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    CreateBuffer(b.size, usage, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, &b.buffer, &b.memory);
    bool coherent = true;
    CreateBuffer(b.size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                 VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT, &b.staging, &b.stagingMemory, &coherent);
    stagingCoherent_ = stagingCoherent_ && coherent;
    Check(vkMapMemory(device_, b.stagingMemory, 0, VK_WHOLE_SIZE, 0, &b.mapped), "vkMapMemory");
    std::memcpy(b.mapped, contents.data(), contents.size());
    if (!coherent) {
        VkMappedMemoryRange range{VK_STRUCTURE_TYPE_MAPPED_MEMORY_RANGE};
        range.memory = b.stagingMemory;
        range.size = VK_WHOLE_SIZE;
        Check(vkFlushMappedMemoryRanges(device_, 1, &range), "vkFlushMappedMemoryRanges");
    }
    buffers_.push_back(b);
}

RunResult Gpu::Run(const std::vector<uint32_t>& spirv, const std::string& entry, const uint32_t groups[3],
                   uint32_t repeat, bool timestamps)
{
    if (timestamps && timestampBits_ == 0) throw std::runtime_error(deviceName_ + " has no compute timestamps");

    // Descriptor set 0: exactly the given bindings.
    std::vector<VkDescriptorSetLayoutBinding> layoutBindings;
    uint32_t uniforms = 0, storages = 0;
    for (const GpuBuffer& b : buffers_) {
        VkDescriptorSetLayoutBinding lb{};
        lb.binding = b.binding;
        lb.descriptorType = b.uniform ? VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        lb.descriptorCount = 1;
        lb.stageFlags = VK_SHADER_STAGE_COMPUTE_BIT;
        layoutBindings.push_back(lb);
        (b.uniform ? uniforms : storages)++;
    }
    VkDescriptorSetLayoutCreateInfo dlci{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    dlci.bindingCount = static_cast<uint32_t>(layoutBindings.size());
    dlci.pBindings = layoutBindings.data();
    VkDescriptorSetLayout setLayout;
    Check(vkCreateDescriptorSetLayout(device_, &dlci, nullptr, &setLayout), "vkCreateDescriptorSetLayout");

    VkPipelineLayoutCreateInfo plci{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    plci.setLayoutCount = 1;
    plci.pSetLayouts = &setLayout;
    VkPipelineLayout pipelineLayout;
    Check(vkCreatePipelineLayout(device_, &plci, nullptr, &pipelineLayout), "vkCreatePipelineLayout");

    VkShaderModuleCreateInfo smci{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    smci.codeSize = spirv.size() * sizeof(uint32_t);
    smci.pCode = spirv.data();
    VkShaderModule module;
    Check(vkCreateShaderModule(device_, &smci, nullptr, &module), "vkCreateShaderModule");

    VkComputePipelineCreateInfo cpci{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    cpci.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    cpci.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    cpci.stage.module = module;
    cpci.stage.pName = entry.c_str();
    cpci.layout = pipelineLayout;
    VkPipeline pipeline;
    Check(vkCreateComputePipelines(device_, VK_NULL_HANDLE, 1, &cpci, nullptr, &pipeline), "vkCreateComputePipelines");

    std::vector<VkDescriptorPoolSize> sizes;
    if (uniforms) sizes.push_back({VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, uniforms});
    if (storages) sizes.push_back({VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, storages});
    VkDescriptorPoolCreateInfo dpci{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    dpci.maxSets = 1;
    dpci.poolSizeCount = static_cast<uint32_t>(sizes.size());
    dpci.pPoolSizes = sizes.data();
    VkDescriptorPool pool;
    Check(vkCreateDescriptorPool(device_, &dpci, nullptr, &pool), "vkCreateDescriptorPool");
    VkDescriptorSetAllocateInfo dsai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    dsai.descriptorPool = pool;
    dsai.descriptorSetCount = 1;
    dsai.pSetLayouts = &setLayout;
    VkDescriptorSet set;
    Check(vkAllocateDescriptorSets(device_, &dsai, &set), "vkAllocateDescriptorSets");
    std::vector<VkDescriptorBufferInfo> infos(buffers_.size());
    std::vector<VkWriteDescriptorSet> writes(buffers_.size());
    for (size_t i = 0; i < buffers_.size(); ++i) {
        infos[i] = {buffers_[i].buffer, 0, VK_WHOLE_SIZE};
        writes[i] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        writes[i].dstSet = set;
        writes[i].dstBinding = buffers_[i].binding;
        writes[i].descriptorCount = 1;
        writes[i].descriptorType = layoutBindings[i].descriptorType;
        writes[i].pBufferInfo = &infos[i];
    }
    vkUpdateDescriptorSets(device_, static_cast<uint32_t>(writes.size()), writes.data(), 0, nullptr);

    VkQueryPool queries = VK_NULL_HANDLE;
    if (timestamps) {
        VkQueryPoolCreateInfo qpci{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
        qpci.queryType = VK_QUERY_TYPE_TIMESTAMP;
        qpci.queryCount = 2 * repeat;
        Check(vkCreateQueryPool(device_, &qpci, nullptr, &queries), "vkCreateQueryPool");
    }

    VkCommandPoolCreateInfo cpoolci{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    cpoolci.queueFamilyIndex = queueFamily_;
    VkCommandPool cmdPool;
    Check(vkCreateCommandPool(device_, &cpoolci, nullptr, &cmdPool), "vkCreateCommandPool");
    VkCommandBufferAllocateInfo cbai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    cbai.commandPool = cmdPool;
    cbai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    cbai.commandBufferCount = 1;
    VkCommandBuffer cmd;
    Check(vkAllocateCommandBuffers(device_, &cbai, &cmd), "vkAllocateCommandBuffers");

    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    Check(vkBeginCommandBuffer(cmd, &begin), "vkBeginCommandBuffer");
    if (timestamps) vkCmdResetQueryPool(cmd, queries, 0, 2 * repeat);
    for (const GpuBuffer& b : buffers_) {
        VkBufferCopy region{0, 0, b.size};
        vkCmdCopyBuffer(cmd, b.staging, b.buffer, 1, &region);
    }
    VkMemoryBarrier barrier = FullBarrier();
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1, &barrier, 0,
                         nullptr, 0, nullptr);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipelineLayout, 0, 1, &set, 0, nullptr);
    for (uint32_t k = 0; k < repeat; ++k) {
        if (timestamps) vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, queries, 2 * k);
        vkCmdDispatch(cmd, groups[0], groups[1], groups[2]);
        if (timestamps) vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, queries, 2 * k + 1);
        // Each dispatch sees the previous one's writes (a time step reads the depth the last one wrote).
        vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                             VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 1, &barrier, 0,
                             nullptr, 0, nullptr);
    }
    for (const GpuBuffer& b : buffers_) {
        if (b.uniform) continue;
        VkBufferCopy region{0, 0, b.size};
        vkCmdCopyBuffer(cmd, b.buffer, b.staging, 1, &region);
    }
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &barrier, 0, nullptr, 0,
                         nullptr);
    Check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer");

    VkFenceCreateInfo fci{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VkFence fence;
    Check(vkCreateFence(device_, &fci, nullptr, &fence), "vkCreateFence");
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &cmd;
    Check(vkQueueSubmit(queue_, 1, &submit, fence), "vkQueueSubmit");
    Check(vkWaitForFences(device_, 1, &fence, VK_TRUE, UINT64_MAX), "vkWaitForFences");

    RunResult result;
    if (timestamps) {
        std::vector<uint64_t> ticks(2 * repeat);
        Check(vkGetQueryPoolResults(device_, queries, 0, 2 * repeat, ticks.size() * sizeof(uint64_t), ticks.data(),
                                    sizeof(uint64_t), VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
              "vkGetQueryPoolResults");
        uint64_t mask = timestampBits_ >= 64 ? ~0ull : ((1ull << timestampBits_) - 1);
        for (uint32_t k = 0; k < repeat; ++k) {
            uint64_t d = (ticks[2 * k + 1] - ticks[2 * k]) & mask;  // wraps correctly within the valid bits
            result.dispatchMs.push_back(static_cast<double>(d) * timestampPeriodNs_ * 1e-6);
        }
    }
    if (!stagingCoherent_) {
        for (const GpuBuffer& b : buffers_) {
            VkMappedMemoryRange range{VK_STRUCTURE_TYPE_MAPPED_MEMORY_RANGE};
            range.memory = b.stagingMemory;
            range.size = VK_WHOLE_SIZE;
            Check(vkInvalidateMappedMemoryRanges(device_, 1, &range), "vkInvalidateMappedMemoryRanges");
        }
    }

    vkDestroyFence(device_, fence, nullptr);
    vkDestroyCommandPool(device_, cmdPool, nullptr);
    if (queries != VK_NULL_HANDLE) vkDestroyQueryPool(device_, queries, nullptr);
    vkDestroyDescriptorPool(device_, pool, nullptr);
    vkDestroyPipeline(device_, pipeline, nullptr);
    vkDestroyShaderModule(device_, module, nullptr);
    vkDestroyPipelineLayout(device_, pipelineLayout, nullptr);
    vkDestroyDescriptorSetLayout(device_, setLayout, nullptr);
    return result;
}

std::vector<char> Gpu::Read(uint32_t binding) const
{
    for (const GpuBuffer& b : buffers_)
        if (b.binding == binding) {
            const char* p = static_cast<const char*>(b.mapped);
            return std::vector<char>(p, p + b.size);
        }
    throw std::runtime_error("no buffer at binding " + std::to_string(binding));
}
