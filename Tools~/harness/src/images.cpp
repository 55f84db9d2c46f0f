#include "images.hpp"

#include <cstring>
#include <sstream>

#include "buffers.hpp"
#include "check.hpp"
#include "cli.hpp"
#include "device.hpp"

namespace gt {

namespace {

constexpr uint64_t kMaxExtent = 16384;      // maxImageDimension2D every Vulkan device has at least 4096 of
constexpr uint64_t kMaxLayers = 2048;       // maxImageArrayLayers' required minimum is 256

std::vector<std::string> fields(const std::string& value) {
    std::vector<std::string> out;
    std::stringstream ss(value);
    std::string item;
    while (std::getline(ss, item, ':')) out.push_back(item);
    if (!value.empty() && value.back() == ':') out.push_back("");
    return out;
}

struct FormatInfo {
    const char* name;
    VkFormat format;
    uint32_t bytes;
};
// Upper case as Vulkan spells them (without VK_FORMAT_); D32 is D32_SFLOAT: a depth map as data,
// for a comparison sampler (SampleCmp reads depth formats only).
const FormatInfo kFormats[] = {
    {"R32_SFLOAT", VK_FORMAT_R32_SFLOAT, 4},
    {"R32G32_SFLOAT", VK_FORMAT_R32G32_SFLOAT, 8},
    {"R32G32B32A32_SFLOAT", VK_FORMAT_R32G32B32A32_SFLOAT, 16},
    {"R16G16B16A16_SFLOAT", VK_FORMAT_R16G16B16A16_SFLOAT, 8},
    {"R8G8B8A8_UNORM", VK_FORMAT_R8G8B8A8_UNORM, 4},
    {"R8G8B8A8_SRGB", VK_FORMAT_R8G8B8A8_SRGB, 4},
    {"D32", VK_FORMAT_D32_SFLOAT, 4},
    {"D32_SFLOAT", VK_FORMAT_D32_SFLOAT, 4},
};

bool isDepth(VkFormat f) { return f == VK_FORMAT_D32_SFLOAT; }

struct CompareInfo {
    const char* name;
    VkCompareOp op;
};
const CompareInfo kCompares[] = {
    {"compare-never", VK_COMPARE_OP_NEVER},   {"compare-less", VK_COMPARE_OP_LESS},
    {"compare-equal", VK_COMPARE_OP_EQUAL},   {"compare-lequal", VK_COMPARE_OP_LESS_OR_EQUAL},
    {"compare-greater", VK_COMPARE_OP_GREATER}, {"compare-notequal", VK_COMPARE_OP_NOT_EQUAL},
    {"compare-gequal", VK_COMPARE_OP_GREATER_OR_EQUAL}, {"compare-always", VK_COMPARE_OP_ALWAYS},
};

std::string formatList() {
    std::string s;
    for (const FormatInfo& f : kFormats) s += (s.empty() ? "" : ", ") + std::string(f.name);
    return s;
}

}  // namespace

ImageOption parseImageOption(const std::string& value) {
    const std::string option = "--image";
    const std::vector<std::string> f = fields(value);
    if (f.size() != 5 && f.size() != 6) fail(option + ": expected BINDING:FILE:FORMAT:W:H[:LAYERS], got '" + value + "'");
    ImageOption o;
    o.spec = value;
    o.binding = parseStorageBinding(option, value, f[0]);
    if (f[1].empty()) fail(option + ": FILE is empty in '" + value + "'");
    o.path = f[1];
    for (const FormatInfo& info : kFormats)
        if (f[2] == info.name) {
            o.formatName = info.name;
            o.format = info.format;
            o.texelBytes = info.bytes;
        }
    if (o.format == VK_FORMAT_UNDEFINED)
        fail(option + ": FORMAT '" + f[2] + "' in '" + value + "' is not one of " + formatList());
    o.width = static_cast<uint32_t>(parseField(option, value, "W", f[3], 1, kMaxExtent));
    o.height = static_cast<uint32_t>(parseField(option, value, "H", f[4], 1, kMaxExtent));
    if (f.size() == 6) {
        o.layers = static_cast<uint32_t>(parseField(option, value, "LAYERS", f[5], 1, kMaxLayers));
        o.arrayed = true;
    }
    return o;
}

SamplerOption parseSamplerOption(const std::string& value) {
    const std::string option = "--sampler";
    const std::vector<std::string> f = fields(value);
    const std::string form = "BINDING:linear|point[:clamp|repeat][:compare-OP]";
    if (f.size() < 2 || f.size() > 4) fail(option + ": expected " + form + ", got '" + value + "'");
    SamplerOption s;
    s.spec = value;
    s.binding = parseStorageBinding(option, value, f[0]);
    if (f[1] == "linear") s.filter = VK_FILTER_LINEAR;
    else if (f[1] == "point") s.filter = VK_FILTER_NEAREST;
    else fail(option + ": filter '" + f[1] + "' in '" + value + "' is not linear or point");
    bool addressGiven = false;
    for (size_t i = 2; i < f.size(); ++i) {
        const std::string& t = f[i];
        if ((t == "clamp" || t == "repeat") && !addressGiven && !s.compare) {
            s.address = t == "clamp" ? VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE : VK_SAMPLER_ADDRESS_MODE_REPEAT;
            addressGiven = true;
            continue;
        }
        bool found = false;
        for (const CompareInfo& c : kCompares)
            if (t == c.name && !s.compare) {
                s.compare = true;
                s.compareOp = c.op;
                found = true;
            }
        if (!found)
            fail(option + ": '" + t + "' in '" + value + "' is not clamp or repeat (before) or compare-" +
                 "never|less|equal|lequal|greater|notequal|gequal|always (once, last): expected " + form);
    }
    return s;
}

void checkImageBindings(const std::vector<ImageOption>& images, const std::vector<SamplerOption>& samplers,
                        const std::vector<uint32_t>& storageBindings) {
    struct Use {
        uint32_t binding;
        std::string what;
    };
    std::vector<Use> uses;
    for (uint32_t b : storageBindings) uses.push_back({b, "--storage " + std::to_string(b)});
    auto add = [&](uint32_t binding, const std::string& what) {
        for (const Use& u : uses)
            if (u.binding == binding)
                fail(what + ": binding " + std::to_string(binding) + " is already given (" + u.what + ")");
        uses.push_back({binding, what});
    };
    for (const ImageOption& i : images) add(i.binding, "--image '" + i.spec + "'");
    for (const SamplerOption& s : samplers) add(s.binding, "--sampler '" + s.spec + "'");
}

namespace {

// Which sampler reads which image is the shader's choice, so linear filtering is not checked here:
// lavapipe, for one, does not list SAMPLED_IMAGE_FILTER_LINEAR for D32 (use a point comparison sampler).
void checkFormat(const Gpu& gpu, const ImageOption& o) {
    VkFormatProperties props{};
    vkGetPhysicalDeviceFormatProperties(gpu.physical, o.format, &props);
    const VkFormatFeatureFlags have = props.optimalTilingFeatures;
    const VkFormatFeatureFlags need = VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT | VK_FORMAT_FEATURE_TRANSFER_DST_BIT;
    if ((have & need) != need)
        fail("--image '" + o.spec + "': " + gpu.properties.deviceName + " cannot sample " + o.formatName +
             " images uploaded by a copy");
}

SampledImages::Held uploadImage(const Gpu& gpu, const ImageOption& o) {
    const std::vector<uint8_t> bytes = readFile(o.path);
    const uint64_t expected = uint64_t(o.width) * o.height * o.layers * o.texelBytes;
    if (bytes.size() != expected)
        fail("--image '" + o.spec + "': '" + o.path + "' has " + std::to_string(bytes.size()) + " bytes; expected " +
             std::to_string(expected) + " (W*H*LAYERS texels of " + std::to_string(o.texelBytes) + " bytes, " +
             o.formatName + ")");
    if (isDepth(o.format)) {
        // Without VK_EXT_depth_range_unrestricted a D32 image holds [0, 1]: a value outside would be clamped.
        for (size_t i = 0; i < bytes.size(); i += 4) {
            float d;
            std::memcpy(&d, bytes.data() + i, 4);
            if (!(d >= 0.0f && d <= 1.0f))
                fail("--image '" + o.spec + "': texel " + std::to_string(i / 4) + " of '" + o.path + "' is " +
                     std::to_string(d) + ", outside a depth image's [0, 1]");
        }
    }
    const uint32_t families[2] = {gpu.queueFamily, gpu.computeFamily};
    SampledImages::Held h;
    VkImageCreateInfo ci{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    ci.imageType = VK_IMAGE_TYPE_2D;
    ci.format = o.format;
    ci.extent = {o.width, o.height, 1};
    ci.mipLevels = 1;
    ci.arrayLayers = o.layers;
    ci.samples = VK_SAMPLE_COUNT_1_BIT;
    ci.tiling = VK_IMAGE_TILING_OPTIMAL;
    ci.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    ci.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    if (gpu.asyncCompute && gpu.computeFamily != gpu.queueFamily) {  // as the buffers: no ownership transfers
        ci.sharingMode = VK_SHARING_MODE_CONCURRENT;
        ci.queueFamilyIndexCount = 2;
        ci.pQueueFamilyIndices = families;
    }
    GT_VK(vkCreateImage(gpu.device, &ci, nullptr, &h.image));
    VkMemoryRequirements req{};
    vkGetImageMemoryRequirements(gpu.device, h.image, &req);
    VkMemoryAllocateInfo ai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    ai.allocationSize = req.size;
    const int type = findMemoryType(gpu.memory, req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    if (type < 0) fail("--image '" + o.spec + "': no device-local memory type for the image");
    ai.memoryTypeIndex = static_cast<uint32_t>(type);
    GT_VK(vkAllocateMemory(gpu.device, &ai, nullptr, &h.memory));
    GT_VK(vkBindImageMemory(gpu.device, h.image, h.memory, 0));

    const VkImageAspectFlags aspect = isDepth(o.format) ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT;
    Buffer staging = createHostBuffer(gpu, bytes.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
    std::memcpy(staging.mapped, bytes.data(), bytes.size());
    submitOnce(gpu, [&](VkCommandBuffer cmd) {
        VkImageMemoryBarrier toDst{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
        toDst.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        toDst.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
        toDst.newLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
        toDst.srcQueueFamilyIndex = toDst.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        toDst.image = h.image;
        toDst.subresourceRange = {aspect, 0, 1, 0, o.layers};
        vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0,
                             nullptr, 1, &toDst);
        VkBufferImageCopy region{};
        region.imageSubresource = {aspect, 0, 0, o.layers};
        region.imageExtent = {o.width, o.height, 1};
        vkCmdCopyBufferToImage(cmd, staging.buffer, h.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
        // The texels -> every later shader read, in any stage (compute pre-pass included).
        VkImageMemoryBarrier toRead = toDst;
        toRead.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        toRead.dstAccessMask = VK_ACCESS_SHADER_READ_BIT;
        toRead.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
        toRead.newLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
        vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0, 0, nullptr, 0,
                             nullptr, 1, &toRead);
    });
    destroyBuffer(gpu, staging);

    VkImageViewCreateInfo vi{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    vi.image = h.image;
    vi.viewType = o.arrayed ? VK_IMAGE_VIEW_TYPE_2D_ARRAY : VK_IMAGE_VIEW_TYPE_2D;
    vi.format = o.format;
    vi.subresourceRange = {aspect, 0, 1, 0, o.layers};
    GT_VK(vkCreateImageView(gpu.device, &vi, nullptr, &h.view));
    return h;
}

VkSampler createSampler(const Gpu& gpu, const SamplerOption& s) {
    VkSamplerCreateInfo ci{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    ci.magFilter = ci.minFilter = s.filter;
    ci.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    ci.addressModeU = ci.addressModeV = ci.addressModeW = s.address;
    ci.compareEnable = s.compare ? VK_TRUE : VK_FALSE;
    ci.compareOp = s.compareOp;
    ci.maxLod = 0.0f;  // the images have one mip level
    VkSampler sampler = VK_NULL_HANDLE;
    GT_VK(vkCreateSampler(gpu.device, &ci, nullptr, &sampler));
    return sampler;
}

}  // namespace

SampledImages createSampledImages(const Gpu& gpu, const std::vector<ImageOption>& images,
                                  const std::vector<SamplerOption>& samplers) {
    SampledImages out;
    try {
        for (const ImageOption& o : images) {
            checkFormat(gpu, o);
            out.images.push_back(uploadImage(gpu, o));
            out.descriptors.push_back({o.binding, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, out.images.back().view, VK_NULL_HANDLE});
        }
        for (const SamplerOption& s : samplers) {
            out.samplers.push_back(createSampler(gpu, s));
            out.descriptors.push_back({s.binding, VK_DESCRIPTOR_TYPE_SAMPLER, VK_NULL_HANDLE, out.samplers.back()});
        }
    } catch (...) {
        destroySampledImages(gpu, out);
        throw;
    }
    return out;
}

void destroySampledImages(const Gpu& gpu, SampledImages& sampled) {
    for (SampledImages::Held& h : sampled.images) {
        if (h.view) vkDestroyImageView(gpu.device, h.view, nullptr);
        if (h.image) vkDestroyImage(gpu.device, h.image, nullptr);
        if (h.memory) vkFreeMemory(gpu.device, h.memory, nullptr);
    }
    for (VkSampler s : sampled.samplers) vkDestroySampler(gpu.device, s, nullptr);
    sampled = SampledImages{};
}

void writeImageDescriptors(VkDevice device, VkDescriptorSet set, const std::vector<ImageDescriptor>& descriptors) {
    std::vector<VkDescriptorImageInfo> infos(descriptors.size());
    std::vector<VkWriteDescriptorSet> writes(descriptors.size());
    for (size_t i = 0; i < descriptors.size(); ++i) {
        const ImageDescriptor& d = descriptors[i];
        infos[i].sampler = d.sampler;
        infos[i].imageView = d.view;
        infos[i].imageLayout = d.view ? VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL : VK_IMAGE_LAYOUT_UNDEFINED;
        writes[i] = VkWriteDescriptorSet{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        writes[i].dstSet = set;
        writes[i].dstBinding = d.binding;
        writes[i].descriptorCount = 1;
        writes[i].descriptorType = d.type;
        writes[i].pImageInfo = &infos[i];
    }
    if (!writes.empty()) vkUpdateDescriptorSets(device, static_cast<uint32_t>(writes.size()), writes.data(), 0, nullptr);
}

}  // namespace gt
