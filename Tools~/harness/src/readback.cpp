#include "readback.hpp"

#include <cmath>
#include <cstdlib>
#include <cstring>

#include "check.hpp"

namespace gt {

namespace {

std::vector<uint8_t> readImage(const Gpu& gpu, const RenderTarget& t, VkImage image, uint32_t texelBytes) {
    const VkDeviceSize size = static_cast<VkDeviceSize>(t.width) * t.height * texelBytes;
    Buffer host = createHostBuffer(gpu, size, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    submitOnce(gpu, [&](VkCommandBuffer cmd) {
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = {t.width, t.height, 1};
        vkCmdCopyImageToBuffer(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, host.buffer, 1, &region);
        VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
        toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
        vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &toHost, 0, nullptr, 0,
                             nullptr);
    });
    const uint8_t* p = static_cast<const uint8_t*>(host.mapped);
    std::vector<uint8_t> rgba(p, p + size);
    destroyBuffer(gpu, host);
    return rgba;
}

}  // namespace

std::vector<uint8_t> readColor(const Gpu& gpu, const RenderTarget& t) { return readImage(gpu, t, t.color.image, 4); }

std::vector<uint8_t> readTarget1(const Gpu& gpu, const RenderTarget& t) {
    if (t.color1Format == VK_FORMAT_UNDEFINED) fail("readTarget1: the render target has no second colour attachment");
    const uint32_t bytes = t.color1Format == VK_FORMAT_R8_UNORM ? 1 : t.color1Format == VK_FORMAT_R16_UNORM ? 2 : 4;
    return readImage(gpu, t, t.color1.image, bytes);
}

namespace {

// One aspect of the depth attachment, bytes per texel each, after the last frame; left back in the
// attachment layout so the other aspect can be read the same way.
std::vector<uint8_t> readDepthAspect(const Gpu& gpu, const RenderTarget& t, VkImageAspectFlagBits aspect, uint32_t bytes) {
    const VkDeviceSize size = static_cast<VkDeviceSize>(t.width) * t.height * bytes;
    Buffer host = createHostBuffer(gpu, size, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    submitOnce(gpu, [&](VkCommandBuffer cmd) {
        // The render pass leaves depth in DEPTH_STENCIL_ATTACHMENT_OPTIMAL, stored.
        depthBarrier(cmd, t, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                     VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, VK_ACCESS_TRANSFER_READ_BIT,
                     VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
        VkBufferImageCopy region{};
        region.imageSubresource = {static_cast<VkImageAspectFlags>(aspect), 0, 0, 1};
        region.imageExtent = {t.width, t.height, 1};
        vkCmdCopyImageToBuffer(cmd, t.depth.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, host.buffer, 1, &region);
        depthBarrier(cmd, t, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
                     VK_ACCESS_TRANSFER_READ_BIT, 0, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT);
        VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
        toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
        vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &toHost, 0, nullptr, 0,
                             nullptr);
    });
    const uint8_t* p = static_cast<const uint8_t*>(host.mapped);
    std::vector<uint8_t> texels(p, p + size);
    destroyBuffer(gpu, host);
    return texels;
}

}  // namespace

std::vector<float> readDepth(const Gpu& gpu, const RenderTarget& t) {
    if (!t.depthReadable) fail("readDepth: the render target was created without a readable depth attachment");
    const std::vector<uint8_t> bytes = readDepthAspect(gpu, t, VK_IMAGE_ASPECT_DEPTH_BIT, 4);
    std::vector<float> depth(bytes.size() / 4);
    std::memcpy(depth.data(), bytes.data(), bytes.size());
    return depth;
}

std::vector<uint8_t> readStencil(const Gpu& gpu, const RenderTarget& t) {
    if (!t.stencilReadable) fail("readStencil: the render target was created without a readable stencil");
    return readDepthAspect(gpu, t, VK_IMAGE_ASPECT_STENCIL_BIT, 1);
}

uint64_t countNonSkyPixels(const std::vector<uint8_t>& rgba) {
    uint64_t n = 0;
    for (size_t i = 0; i + 3 < rgba.size(); i += 4) {
        bool differs = false;
        for (int c = 0; c < 3; ++c) differs |= std::abs(rgba[i + c] - static_cast<int>(std::lround(kSky[c] * 255.0f))) > 2;
        n += differs;
    }
    return n;
}

uint64_t dumpReadback(const Buffer& readback, uint64_t floats, const std::string& path) {
    const float* f = static_cast<const float*>(readback.mapped);
    uint64_t nan = 0;
    for (uint64_t i = 0; i < floats; ++i) nan += std::isnan(f[i]) ? 1 : 0;
    writeFile(path, f, floats * 4);
    return nan;
}

}  // namespace gt
