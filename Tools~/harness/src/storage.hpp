// --storage buffers: device-local storage buffers at bindings of set 0 chosen on the command line
// (the vertex cache's _TileFactors and _VertexCache, written by --compute kernels and read by the
// graphics stages), zero-filled once before the first frame; --dump-storage copies one out.
#pragma once
#include <cstdint>
#include <vector>

#include "buffers.hpp"
#include "cli.hpp"

namespace gt {

struct StorageBuffer {
    uint32_t binding = 0;
    uint64_t bytes = 0;  // as asked; buffer.size may be larger (never below 16 bytes)
    Buffer buffer;
};

// One buffer per --storage option, in order, zero-filled. Throws gt::Error naming the option and
// value when BYTES exceeds the device's maxStorageBufferRange (the descriptor could not cover it).
std::vector<StorageBuffer> createStorageBuffers(const Gpu& gpu, const std::vector<StorageOption>& options);

// Copies the buffer at dump.binding (which must exist) into host memory after all submitted work
// and writes its `bytes` bytes to dump.path; returns the byte count written.
uint64_t dumpStorage(const Gpu& gpu, const std::vector<StorageBuffer>& storage, const StorageDump& dump);

void destroyStorageBuffers(const Gpu& gpu, std::vector<StorageBuffer>& storage);

}  // namespace gt
