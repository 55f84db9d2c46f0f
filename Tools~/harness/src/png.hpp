// A minimal PNG writer (8-bit RGBA, no compression) so the harness needs no libpng/zlib.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace gt {

// CRC-32 (ISO 3309, as PNG chunks use it) of data, continuing from crc (start with 0).
uint32_t crc32(const uint8_t* data, size_t size, uint32_t crc = 0);

// Adler-32 (RFC 1950, the zlib stream checksum) of data.
uint32_t adler32(const uint8_t* data, size_t size);

// The PNG file bytes of a width x height RGBA8 image, rows top to bottom.
std::vector<uint8_t> encodePng(const uint8_t* rgba, uint32_t width, uint32_t height);

void writePng(const std::string& path, const uint8_t* rgba, uint32_t width, uint32_t height);

}  // namespace gt
