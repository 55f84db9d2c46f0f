// The offscreen render target: RGBA8 colour + D32 depth, one render pass that clears both to
// the sky colour / far plane and leaves the colour image ready to be copied out.
#pragma once
#include "device.hpp"

namespace gt {

constexpr VkFormat kColorFormat = VK_FORMAT_R8G8B8A8_UNORM;  // the default; --color-format picks another of 4 bytes
constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;
// Sky colour of the clear, also used to tell drawn pixels from background (0..255 per channel).
constexpr float kSky[4] = {0.55f, 0.70f, 0.90f, 1.0f};

struct Image {
    VkImage image = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;
};

struct RenderTarget {
    uint32_t width = 0, height = 0;
    Image color, depth;
    VkFormat colorFormat = kColorFormat;
    Image color1;                                   // a second colour attachment, when color1Format is set
    VkFormat color1Format = VK_FORMAT_UNDEFINED;
    float depthClear = 1.0f;  // 0 with reversed depth (near 1, far 0)
    bool depthReadable = false;  // --depth-out: depth stored after the pass and copyable (readDepth)
    VkRenderPass renderPass = VK_NULL_HANDLE;
    VkFramebuffer framebuffer = VK_NULL_HANDLE;
};

// depthReadable: the depth attachment is stored and can be copied out after the pass (--depth-out).
RenderTarget createRenderTarget(const Gpu& gpu, uint32_t width, uint32_t height, float depthClear,
                                bool depthReadable = false, VkFormat colorFormat = kColorFormat,
                                VkFormat color1Format = VK_FORMAT_UNDEFINED);
void destroyRenderTarget(const Gpu& gpu, RenderTarget& target);

// Begins the render pass with the clears (sky colour, depth 1, or 0 when reversed).
void beginRenderPass(VkCommandBuffer cmd, const RenderTarget& target);

}  // namespace gt
