// Reading results back: the colour image (RGBA8, top row first) and the readback buffer.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "buffers.hpp"
#include "target.hpp"

namespace gt {

// Copies the colour attachment (in TRANSFER_SRC layout after the render pass) to host memory.
std::vector<uint8_t> readColor(const Gpu& gpu, const RenderTarget& target);

// The second colour attachment's texels (--target1), raw, top row first.
std::vector<uint8_t> readTarget1(const Gpu& gpu, const RenderTarget& target);

// The depth attachment's D32 values after the last frame (target created depthReadable), rows in
// framebuffer order: row 0 is the picture's top row, as in the colour image and the PNG.
std::vector<float> readDepth(const Gpu& gpu, const RenderTarget& target);
// The stencil's bytes after the last frame (target created stencilReadable), rows as readDepth's.
std::vector<uint8_t> readStencil(const Gpu& gpu, const RenderTarget& target);

// Pixels whose colour differs from the sky clear colour by more than 2/255 in some channel.
uint64_t countNonSkyPixels(const std::vector<uint8_t>& rgba);

// Writes the first floats of the host-visible readback buffer to path; returns how many
// of them are NaN (never written when the buffer was NaN-filled).
uint64_t dumpReadback(const Buffer& readback, uint64_t floats, const std::string& path);

}  // namespace gt
