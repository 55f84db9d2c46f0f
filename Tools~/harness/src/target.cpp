#include "target.hpp"

#include <cstring>
#include <string>

#include "buffers.hpp"
#include "check.hpp"

namespace gt {

namespace {

Image createImage(const Gpu& gpu, uint32_t w, uint32_t h, VkFormat format, VkImageUsageFlags usage,
                  VkImageAspectFlags aspect) {
    VkFormatProperties fp{};
    vkGetPhysicalDeviceFormatProperties(gpu.physical, format, &fp);
    VkFormatFeatureFlags need = (aspect & (VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT)) ? VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT
                                                                     : VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT;
    if ((fp.optimalTilingFeatures & need) != need) fail("the device cannot render to format " + std::to_string(format));

    Image img;
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = format;
    info.extent = {w, h, 1};
    info.mipLevels = 1;
    info.arrayLayers = 1;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = usage;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    GT_VK(vkCreateImage(gpu.device, &info, nullptr, &img.image));
    VkMemoryRequirements req{};
    vkGetImageMemoryRequirements(gpu.device, img.image, &req);
    int type = -1;
    for (uint32_t i = 0; i < gpu.memory.memoryTypeCount && type < 0; ++i)
        if ((req.memoryTypeBits & (1u << i)) &&
            (gpu.memory.memoryTypes[i].propertyFlags & VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT))
            type = static_cast<int>(i);
    for (uint32_t i = 0; i < gpu.memory.memoryTypeCount && type < 0; ++i)
        if (req.memoryTypeBits & (1u << i)) type = static_cast<int>(i);
    if (type < 0) fail("no memory type for a render target image");
    VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    alloc.allocationSize = req.size;
    alloc.memoryTypeIndex = static_cast<uint32_t>(type);
    GT_VK(vkAllocateMemory(gpu.device, &alloc, nullptr, &img.memory));
    GT_VK(vkBindImageMemory(gpu.device, img.image, img.memory, 0));
    VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    view.image = img.image;
    view.viewType = VK_IMAGE_VIEW_TYPE_2D;
    view.format = format;
    view.subresourceRange = {aspect, 0, 1, 0, 1};
    GT_VK(vkCreateImageView(gpu.device, &view, nullptr, &img.view));
    return img;
}

void destroyImage(const Gpu& gpu, Image& img) {
    if (img.view) vkDestroyImageView(gpu.device, img.view, nullptr);
    if (img.image) vkDestroyImage(gpu.device, img.image, nullptr);
    if (img.memory) vkFreeMemory(gpu.device, img.memory, nullptr);
    img = Image{};
}

}  // namespace

RenderTarget createRenderTarget(const Gpu& gpu, uint32_t width, uint32_t height, float depthClear, bool depthReadable,
                                bool depthLoaded, VkFormat colorFormat, VkFormat color1Format, StencilTarget stencil) {
    RenderTarget t;
    t.stencil = stencil.on;
    t.stencilReadable = stencil.on && stencil.readable;
    t.stencilLoaded = stencil.on && stencil.loaded;
    if (stencil.on) {
        VkFormatProperties fp{};
        vkGetPhysicalDeviceFormatProperties(gpu.physical, kDepthStencilFormat, &fp);
        if (!(fp.optimalTilingFeatures & VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT))
            fail("--stencil: the device cannot render to D32_SFLOAT_S8_UINT (the only depth-stencil format the harness draws)");
    }
    const bool loaded = depthLoaded || t.stencilLoaded;   // either aspect uploaded: the attachment starts in its layout
    t.colorFormat = colorFormat;
    t.color1Format = color1Format;
    const bool second = color1Format != VK_FORMAT_UNDEFINED;
    t.depthReadable = depthReadable;
    t.depthLoaded = depthLoaded;
    t.width = width;
    t.height = height;
    t.depthClear = depthClear;
    t.color = createImage(gpu, width, height, colorFormat,
                          VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT, VK_IMAGE_ASPECT_COLOR_BIT);
    t.depth = createImage(gpu, width, height, t.stencil ? kDepthStencilFormat : kDepthFormat,
                          VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT |
                              (depthReadable || t.stencilReadable ? VK_IMAGE_USAGE_TRANSFER_SRC_BIT : 0) |
                              (loaded ? VK_IMAGE_USAGE_TRANSFER_DST_BIT : 0),
                          depthAspects(t));

    if (second)
        t.color1 = createImage(gpu, width, height, color1Format,
                               VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT, VK_IMAGE_ASPECT_COLOR_BIT);

    VkAttachmentDescription att[3]{};
    att[0].format = colorFormat;
    att[0].samples = VK_SAMPLE_COUNT_1_BIT;
    att[0].loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    att[0].storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    att[0].stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    att[0].stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    att[0].initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    att[0].finalLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    att[1] = att[0];
    att[1].format = t.stencil ? kDepthStencilFormat : kDepthFormat;
    att[1].storeOp = depthReadable ? VK_ATTACHMENT_STORE_OP_STORE : VK_ATTACHMENT_STORE_OP_DONT_CARE;
    if (depthLoaded) att[1].loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
    if (t.stencil) {
        att[1].stencilLoadOp = t.stencilLoaded ? VK_ATTACHMENT_LOAD_OP_LOAD : VK_ATTACHMENT_LOAD_OP_CLEAR;
        att[1].stencilStoreOp = t.stencilReadable ? VK_ATTACHMENT_STORE_OP_STORE : VK_ATTACHMENT_STORE_OP_DONT_CARE;
    }
    if (loaded) att[1].initialLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;   // uploadDepthStencil leaves it so
    att[1].finalLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
    att[2] = att[0];
    att[2].format = color1Format;
    VkAttachmentReference colorRef[2] = {{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL}, {2, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL}};
    VkAttachmentReference depthRef{1, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
    VkSubpassDescription sub{};
    sub.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    sub.colorAttachmentCount = second ? 2 : 1;
    sub.pColorAttachments = colorRef;
    sub.pDepthStencilAttachment = &depthRef;
    // The pass may run many times from one command buffer: order against the previous frame's
    // copy-out (colour) and depth writes, and make this frame's colour visible to the copy.
    VkSubpassDependency deps[2]{};
    deps[0].srcSubpass = VK_SUBPASS_EXTERNAL;
    deps[0].dstSubpass = 0;
    deps[0].srcStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT |
                           VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    deps[0].dstStageMask = VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    deps[0].srcAccessMask = VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT |
                            VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    deps[0].dstAccessMask = VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
                            VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    deps[1].srcSubpass = 0;
    deps[1].dstSubpass = VK_SUBPASS_EXTERNAL;
    deps[1].srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    deps[1].dstStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT;
    deps[1].srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    deps[1].dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
    VkRenderPassCreateInfo rp{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
    rp.attachmentCount = second ? 3 : 2;
    rp.pAttachments = att;
    rp.subpassCount = 1;
    rp.pSubpasses = &sub;
    rp.dependencyCount = 2;
    rp.pDependencies = deps;
    GT_VK(vkCreateRenderPass(gpu.device, &rp, nullptr, &t.renderPass));

    VkImageView views[3] = {t.color.view, t.depth.view, t.color1.view};
    VkFramebufferCreateInfo fb{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    fb.renderPass = t.renderPass;
    fb.attachmentCount = rp.attachmentCount;
    fb.pAttachments = views;
    fb.width = width;
    fb.height = height;
    fb.layers = 1;
    GT_VK(vkCreateFramebuffer(gpu.device, &fb, nullptr, &t.framebuffer));
    return t;
}

void depthBarrier(VkCommandBuffer cmd, const RenderTarget& t, VkImageLayout from, VkImageLayout to, VkAccessFlags srcAccess,
                  VkAccessFlags dstAccess, VkPipelineStageFlags srcStage, VkPipelineStageFlags dstStage) {
    VkImageMemoryBarrier b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
    b.srcAccessMask = srcAccess;
    b.dstAccessMask = dstAccess;
    b.oldLayout = from;
    b.newLayout = to;
    b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = t.depth.image;
    b.subresourceRange = {depthAspects(t), 0, 1, 0, 1};
    vkCmdPipelineBarrier(cmd, srcStage, dstStage, 0, 0, nullptr, 0, nullptr, 1, &b);
}

VkImageAspectFlags depthAspects(const RenderTarget& t) {
    return VK_IMAGE_ASPECT_DEPTH_BIT | (t.stencil ? VK_IMAGE_ASPECT_STENCIL_BIT : 0);
}

void uploadDepthStencil(const Gpu& gpu, const RenderTarget& t, const std::vector<float>* depth, const std::vector<uint8_t>* stencil) {
    if (depth && !t.depthLoaded) fail("uploadDepthStencil: the render target was created to clear its depth");
    if (stencil && !t.stencilLoaded) fail("uploadDepthStencil: the render target was created to clear its stencil");
    const VkDeviceSize texels = static_cast<VkDeviceSize>(t.width) * t.height;
    const std::string target = " for a " + std::to_string(t.width) + "x" + std::to_string(t.height) + " target";
    if (depth && depth->size() != texels) fail("uploadDepthStencil: " + std::to_string(depth->size()) + " floats" + target);
    if (stencil && stencil->size() != texels) fail("uploadDepthStencil: " + std::to_string(stencil->size()) + " bytes" + target);
    // Depth's floats first, then the stencil bytes (offset 4*W*H: a multiple of 4, as a copy's offset must be).
    Buffer host = createHostBuffer(gpu, texels * 5, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
    std::vector<VkBufferImageCopy> regions;
    VkBufferImageCopy region{};
    region.imageExtent = {t.width, t.height, 1};
    if (depth) {
        std::memcpy(host.mapped, depth->data(), texels * 4);
        region.imageSubresource = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 0, 1};
        regions.push_back(region);
    }
    if (stencil) {
        std::memcpy(static_cast<uint8_t*>(host.mapped) + texels * 4, stencil->data(), texels);
        region.bufferOffset = texels * 4;
        region.imageSubresource = {VK_IMAGE_ASPECT_STENCIL_BIT, 0, 0, 1};
        regions.push_back(region);
    }
    submitOnce(gpu, [&](VkCommandBuffer cmd) {
        depthBarrier(cmd, t, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_ACCESS_HOST_WRITE_BIT,
                     VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_HOST_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
        vkCmdCopyBufferToImage(cmd, host.buffer, t.depth.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                               static_cast<uint32_t>(regions.size()), regions.data());
        depthBarrier(cmd, t, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
                     VK_ACCESS_TRANSFER_WRITE_BIT,
                     VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                     VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT);
    });
    destroyBuffer(gpu, host);
}

void destroyRenderTarget(const Gpu& gpu, RenderTarget& t) {
    if (t.framebuffer) vkDestroyFramebuffer(gpu.device, t.framebuffer, nullptr);
    if (t.renderPass) vkDestroyRenderPass(gpu.device, t.renderPass, nullptr);
    destroyImage(gpu, t.color);
    destroyImage(gpu, t.depth);
    destroyImage(gpu, t.color1);
    t = RenderTarget{};
}

void beginRenderPass(VkCommandBuffer cmd, const RenderTarget& t) {
    VkClearValue clears[3]{};   // the second colour target: 0
    for (int i = 0; i < 4; ++i) clears[0].color.float32[i] = kSky[i];
    clears[1].depthStencil = {t.depthClear, 0};
    VkRenderPassBeginInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    info.renderPass = t.renderPass;
    info.framebuffer = t.framebuffer;
    info.renderArea = {{0, 0}, {t.width, t.height}};
    info.clearValueCount = t.color1Format != VK_FORMAT_UNDEFINED ? 3 : 2;
    info.pClearValues = clears;
    vkCmdBeginRenderPass(cmd, &info, VK_SUBPASS_CONTENTS_INLINE);
}

}  // namespace gt
