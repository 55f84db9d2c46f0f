// --image and --sampler: device-local 2D (array) images uploaded once from raw texel files and
// separate samplers (comparison ones included), bound at bindings of set 0 as SAMPLED_IMAGE and
// SAMPLER, the descriptors HLSL's Texture2D / SamplerState / SamplerComparisonState compile to.
// A run that gives neither adds no descriptor, so existing layouts (and pipelines) stay as they are.
#pragma once
#include <cstdint>
#include <string>
#include <vector>
#include <vulkan/vulkan.h>

namespace gt {

struct Gpu;

// --image BINDING:FILE:FORMAT:W:H[:LAYERS]; FILE holds W*H*LAYERS texels, row-major, layer after layer.
struct ImageOption {
    std::string spec;  // the option's value as given, for error messages
    uint32_t binding = 0;
    std::string path;
    std::string formatName;
    VkFormat format = VK_FORMAT_UNDEFINED;
    uint32_t texelBytes = 0;
    uint32_t width = 0, height = 0, layers = 1;
    bool arrayed = false;  // LAYERS given: a 2D_ARRAY view (Texture2DArray), even of one layer
};

// --sampler BINDING:linear|point[:clamp|repeat][:compare-OP]
struct SamplerOption {
    std::string spec;
    uint32_t binding = 0;
    VkFilter filter = VK_FILTER_LINEAR;
    VkSamplerAddressMode address = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    bool compare = false;
    VkCompareOp compareOp = VK_COMPARE_OP_NEVER;  // Vulkan's: passes when (reference OP texel)
};

// Parse one value; throw gt::Error naming the option, the field and the whole value.
ImageOption parseImageOption(const std::string& value);
SamplerOption parseSamplerOption(const std::string& value);

// Every --image and --sampler binding differs from the others and from the --storage ones
// (given as a list of bindings); throws naming both options.
void checkImageBindings(const std::vector<ImageOption>& images, const std::vector<SamplerOption>& samplers,
                        const std::vector<uint32_t>& storageBindings);

struct ImageDescriptor {
    uint32_t binding = 0;
    VkDescriptorType type = VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE;  // or VK_DESCRIPTOR_TYPE_SAMPLER
    VkImageView view = VK_NULL_HANDLE;
    VkSampler sampler = VK_NULL_HANDLE;
};

struct SampledImages {
    struct Held {
        VkImage image = VK_NULL_HANDLE;
        VkDeviceMemory memory = VK_NULL_HANDLE;
        VkImageView view = VK_NULL_HANDLE;
    };
    std::vector<Held> images;
    std::vector<VkSampler> samplers;
    std::vector<ImageDescriptor> descriptors;  // images then samplers, in command-line order
};

// Uploads every image (left in SHADER_READ_ONLY_OPTIMAL) and creates every sampler. Throws naming
// the option and value when a file's size does not match, a D32 texel is outside [0, 1], or the
// device cannot sample the format.
SampledImages createSampledImages(const Gpu& gpu, const std::vector<ImageOption>& images,
                                  const std::vector<SamplerOption>& samplers);
void destroySampledImages(const Gpu& gpu, SampledImages& sampled);

void writeImageDescriptors(VkDevice device, VkDescriptorSet set, const std::vector<ImageDescriptor>& descriptors);

}  // namespace gt
