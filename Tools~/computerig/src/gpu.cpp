#include "gpu.h"

#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace {

// The first queue family with compute; UINT32_MAX if none.
uint32_t ComputeFamily(VkPhysicalDevice pd, uint32_t* timestampBits)
{
    int family = gt::queueFamilyWith(pd, VK_QUEUE_COMPUTE_BIT);
    if (family < 0) return UINT32_MAX;
    *timestampBits = gt::queueFamilies(pd)[family].timestampValidBits;
    return static_cast<uint32_t>(family);
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
    VkInstance instance = gt::createInstance("gt-compute");
    for (VkPhysicalDevice pd : gt::physicalDevices(instance)) {
        VkPhysicalDeviceProperties p;
        vkGetPhysicalDeviceProperties(pd, &p);
        std::printf("device %s\n", p.deviceName);
    }
    vkDestroyInstance(instance, nullptr);
}

Gpu::Gpu(const std::string& nameSubstring)
{
    instance_ = gt::createInstance("gt-compute");
    std::string seen;
    for (VkPhysicalDevice pd : gt::physicalDevices(instance_)) {
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
    vkGetPhysicalDeviceMemoryProperties(physical_, &heap_.memory);

    float priority = 1.0f;
    VkDeviceQueueCreateInfo qci{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    qci.queueFamilyIndex = queueFamily_;
    qci.queueCount = 1;
    qci.pQueuePriorities = &priority;
    VkDeviceCreateInfo dci{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    dci.queueCreateInfoCount = 1;
    dci.pQueueCreateInfos = &qci;
    GT_VK(vkCreateDevice(physical_, &dci, nullptr, &device_));
    vkGetDeviceQueue(device_, queueFamily_, 0, &queue_);
    heap_.device = device_;
}

Gpu::~Gpu()
{
    if (device_ != VK_NULL_HANDLE) {
        vkDeviceWaitIdle(device_);
        for (GpuBuffer& b : buffers_) {
            gt::destroyBuffer(device_, b.device);
            gt::destroyBuffer(device_, b.staging);
        }
        vkDestroyDevice(device_, nullptr);
    }
    if (instance_ != VK_NULL_HANDLE) vkDestroyInstance(instance_, nullptr);
}

void Gpu::AddBuffer(const BufferArg& arg, const std::vector<uint8_t>& contents)
{
    GpuBuffer b;
    b.binding = arg.binding;
    b.uniform = arg.uniform;
    b.size = contents.size();
    if (b.size == 0) throw std::runtime_error("binding " + std::to_string(arg.binding) + ": empty buffer");
    VkBufferUsageFlags usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT |
                               (arg.uniform ? VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT : VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    b.device = gt::createBuffer(heap_, b.size, usage, {VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT});
    // Coherent staging when there is some; otherwise flushed here and invalidated after the run.
    b.staging = gt::createBuffer(heap_, b.size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                 {VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT,
                                  VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT});
    const bool coherent = (b.staging.memoryFlags & VK_MEMORY_PROPERTY_HOST_COHERENT_BIT) != 0;
    stagingCoherent_ = stagingCoherent_ && coherent;
    std::memcpy(b.staging.mapped, contents.data(), contents.size());
    if (!coherent) {
        VkMappedMemoryRange range{VK_STRUCTURE_TYPE_MAPPED_MEMORY_RANGE};
        range.memory = b.staging.memory;
        range.size = VK_WHOLE_SIZE;
        GT_VK(vkFlushMappedMemoryRanges(device_, 1, &range));
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
    GT_VK(vkCreateDescriptorSetLayout(device_, &dlci, nullptr, &setLayout));

    VkPipelineLayoutCreateInfo plci{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    plci.setLayoutCount = 1;
    plci.pSetLayouts = &setLayout;
    VkPipelineLayout pipelineLayout;
    GT_VK(vkCreatePipelineLayout(device_, &plci, nullptr, &pipelineLayout));

    VkShaderModule module = gt::createShaderModule(device_, spirv);

    VkComputePipelineCreateInfo cpci{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    cpci.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    cpci.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    cpci.stage.module = module;
    cpci.stage.pName = entry.c_str();
    cpci.layout = pipelineLayout;
    VkPipeline pipeline;
    GT_VK(vkCreateComputePipelines(device_, VK_NULL_HANDLE, 1, &cpci, nullptr, &pipeline));

    std::vector<VkDescriptorPoolSize> sizes;
    if (uniforms) sizes.push_back({VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, uniforms});
    if (storages) sizes.push_back({VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, storages});
    VkDescriptorPoolCreateInfo dpci{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    dpci.maxSets = 1;
    dpci.poolSizeCount = static_cast<uint32_t>(sizes.size());
    dpci.pPoolSizes = sizes.data();
    VkDescriptorPool pool;
    GT_VK(vkCreateDescriptorPool(device_, &dpci, nullptr, &pool));
    VkDescriptorSetAllocateInfo dsai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    dsai.descriptorPool = pool;
    dsai.descriptorSetCount = 1;
    dsai.pSetLayouts = &setLayout;
    VkDescriptorSet set;
    GT_VK(vkAllocateDescriptorSets(device_, &dsai, &set));
    std::vector<gt::DescriptorEntry> entries;
    for (size_t i = 0; i < buffers_.size(); ++i)
        entries.push_back({buffers_[i].binding, layoutBindings[i].descriptorType, buffers_[i].device.buffer});
    gt::writeBufferDescriptors(device_, set, entries);

    VkQueryPool queries = VK_NULL_HANDLE;
    if (timestamps) {
        VkQueryPoolCreateInfo qpci{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
        qpci.queryType = VK_QUERY_TYPE_TIMESTAMP;
        qpci.queryCount = 2 * repeat;
        GT_VK(vkCreateQueryPool(device_, &qpci, nullptr, &queries));
    }

    VkCommandPool cmdPool = gt::createCommandPool(device_, queueFamily_, 0);
    VkCommandBuffer cmd = gt::allocateCommandBuffer(device_, cmdPool);

    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    GT_VK(vkBeginCommandBuffer(cmd, &begin));
    if (timestamps) vkCmdResetQueryPool(cmd, queries, 0, 2 * repeat);
    for (const GpuBuffer& b : buffers_) {
        VkBufferCopy region{0, 0, b.size};
        vkCmdCopyBuffer(cmd, b.staging.buffer, b.device.buffer, 1, &region);
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
        vkCmdCopyBuffer(cmd, b.device.buffer, b.staging.buffer, 1, &region);
    }
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &barrier, 0, nullptr, 0,
                         nullptr);
    GT_VK(vkEndCommandBuffer(cmd));

    VkFenceCreateInfo fci{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VkFence fence;
    GT_VK(vkCreateFence(device_, &fci, nullptr, &fence));
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &cmd;
    GT_VK(vkQueueSubmit(queue_, 1, &submit, fence));
    GT_VK(vkWaitForFences(device_, 1, &fence, VK_TRUE, UINT64_MAX));

    RunResult result;
    if (timestamps) {
        std::vector<uint64_t> ticks(2 * repeat);
        GT_VK(vkGetQueryPoolResults(device_, queries, 0, 2 * repeat, ticks.size() * sizeof(uint64_t), ticks.data(),
                                    sizeof(uint64_t), VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
        uint64_t mask = timestampBits_ >= 64 ? ~0ull : ((1ull << timestampBits_) - 1);
        for (uint32_t k = 0; k < repeat; ++k) {
            uint64_t d = (ticks[2 * k + 1] - ticks[2 * k]) & mask;  // wraps correctly within the valid bits
            result.dispatchMs.push_back(static_cast<double>(d) * timestampPeriodNs_ * 1e-6);
        }
    }
    if (!stagingCoherent_) {
        for (const GpuBuffer& b : buffers_) {
            VkMappedMemoryRange range{VK_STRUCTURE_TYPE_MAPPED_MEMORY_RANGE};
            range.memory = b.staging.memory;
            range.size = VK_WHOLE_SIZE;
            GT_VK(vkInvalidateMappedMemoryRanges(device_, 1, &range));
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

std::vector<uint8_t> Gpu::Read(uint32_t binding) const
{
    for (const GpuBuffer& b : buffers_)
        if (b.binding == binding) {
            const uint8_t* p = static_cast<const uint8_t*>(b.staging.mapped);
            return std::vector<uint8_t>(p, p + b.size);
        }
    throw std::runtime_error("no buffer at binding " + std::to_string(binding));
}
