// SPIR-V modules: load a file, check it is SPIR-V, find its entry points (OpEntryPoint).
#pragma once
#include <string>
#include <vector>

#include "device.hpp"

namespace gt {

// A descriptor the module's functions use: (set, binding) of a decorated resource variable.
struct DescriptorUse {
    uint32_t set = 0;
    uint32_t binding = 0;
};

struct ShaderModule {
    VkShaderModule module = VK_NULL_HANDLE;
    std::string entry;  // the entry point used
    std::string path;
    std::vector<DescriptorUse> descriptors;  // used by some function of the module
};

// The names of the module's OpEntryPoint instructions that have the given execution model
// (0 vertex, 1 tessellation control, 2 tessellation evaluation, 4 fragment, 5 compute).
std::vector<std::string> entryPoints(const std::vector<uint32_t>& words, uint32_t executionModel);

constexpr uint32_t kExecutionModelGLCompute = 5;

// The resource variables (Binding-decorated) that some function of the module refers to. A
// binding that is only declared needs no descriptor; one that is used must be in the layout, or
// the shader reads garbage (seen on lavapipe) instead of failing. An operand word inside a function
// that equals a resource's id counts as a use: literals can only make the list longer, never shorter.
std::vector<DescriptorUse> usedDescriptors(const std::vector<uint32_t>& words);

// Rewrites each uniform block (a Uniform-class variable of a Block struct) as a storage block
// (BufferBlock, SPIR-V 1.0-1.3): same members, offsets and loads, read through a storage-buffer
// descriptor. Why: lavapipe inlines uniform-block values that steer branches and loops into the
// shader and compiles it again at draw time for each new set of values, a few CPU seconds per
// tessellated pipeline and a miss in Mesa's disk cache for every new scene; storage loads are never
// inlined, so one compile per SPIR-V serves every scene. Returns how many blocks it rewrote; throws
// gt::Error for SPIR-V 1.4+ (BufferBlock is gone there).
uint32_t uniformBlocksAsStorage(std::vector<uint32_t>& words, const std::string& path);

// Loads path. Entry: `requested` when given (must exist in the module); otherwise the module's
// only entry point of that stage, else `fallbackName` (empty: the module must have exactly one).
// Throws gt::Error naming the file. With gpu.uniformBlocksAsStorage, its uniform blocks are
// rewritten as storage blocks first (uniformBlocksAsStorage).
ShaderModule loadShader(const Gpu& gpu, const std::string& path, uint32_t executionModel, const std::string& requested,
                        const std::string& fallbackName);

void destroyShader(const Gpu& gpu, ShaderModule& shader);

}  // namespace gt
