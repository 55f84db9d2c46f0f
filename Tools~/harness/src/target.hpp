// The offscreen render target: RGBA8 colour + D32 depth (D32 + S8 when the pass has a stencil state), one render pass that clears both to
// the sky colour / far plane and leaves the colour image ready to be copied out.
#pragma once
#include <vector>

#include "device.hpp"

namespace gt {

constexpr VkFormat kColorFormat = VK_FORMAT_R8G8B8A8_UNORM;  // the default; --color-format picks another of 4 bytes
constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;
constexpr VkFormat kDepthStencilFormat = VK_FORMAT_D32_SFLOAT_S8_UINT;   // only with a stencil state: the rest stays D32
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
    bool depthLoaded = false;    // --depth-in: the pass loads depth (uploadDepth) instead of clearing it
    bool stencil = false;          // the depth attachment has a stencil aspect (kDepthStencilFormat), cleared to 0
    bool stencilReadable = false;  // --stencil-out: stored after the pass (readStencil)
    bool stencilLoaded = false;    // --stencil-in: the pass loads stencil (uploadDepthStencil) instead of clearing it
    VkRenderPass renderPass = VK_NULL_HANDLE;
    VkFramebuffer framebuffer = VK_NULL_HANDLE;
};

// depthReadable: the depth attachment is stored and can be copied out after the pass (--depth-out).
// depthLoaded: the render pass loads depth instead of clearing it; fill it first with uploadDepth.
// stencil: a stencil aspect (fails clearly where the device cannot render D32_SFLOAT_S8_UINT), readable
// after the pass (--stencil-out) and/or loaded before it (--stencil-in) as depth is.
struct StencilTarget {
    bool on = false, readable = false, loaded = false;
};
RenderTarget createRenderTarget(const Gpu& gpu, uint32_t width, uint32_t height, float depthClear,
                                bool depthReadable = false, bool depthLoaded = false,
                                VkFormat colorFormat = kColorFormat, VkFormat color1Format = VK_FORMAT_UNDEFINED,
                                StencilTarget stencil = {});
// The depth attachment's aspects: depth, and stencil where it has one.
VkImageAspectFlags depthAspects(const RenderTarget& target);
// The depth attachment's layout change from -> to, ordered by the access and stage masks.
void depthBarrier(VkCommandBuffer cmd, const RenderTarget& target, VkImageLayout from, VkImageLayout to,
                  VkAccessFlags srcAccess, VkAccessFlags dstAccess, VkPipelineStageFlags srcStage, VkPipelineStageFlags dstStage);
// --depth-in / --stencil-in: copies W*H depth floats and/or W*H stencil bytes (rows as readDepth and
// readStencil return them; null: that aspect is cleared by the pass) into the depth attachment, in one go.
void uploadDepthStencil(const Gpu& gpu, const RenderTarget& target, const std::vector<float>* depth,
                        const std::vector<uint8_t>* stencil);
void destroyRenderTarget(const Gpu& gpu, RenderTarget& target);

// Begins the render pass with the clears (sky colour, depth 1, or 0 when reversed, stencil 0).
void beginRenderPass(VkCommandBuffer cmd, const RenderTarget& target);

}  // namespace gt
