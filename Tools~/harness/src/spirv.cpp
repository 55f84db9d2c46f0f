#include "spirv.hpp"

#include <cstring>
#include <map>
#include <set>

#include "vkcommon.hpp"

namespace gt {

namespace {
constexpr uint32_t kOpEntryPoint = 15;
constexpr uint32_t kOpDecorate = 71;
constexpr uint32_t kOpFunction = 54;
constexpr uint32_t kOpTypePointer = 32;
constexpr uint32_t kOpVariable = 59;
constexpr uint32_t kStorageClassUniform = 2;
constexpr uint32_t kDecorationBlock = 2;
constexpr uint32_t kDecorationBufferBlock = 3;
constexpr uint32_t kDecorationBinding = 33;
constexpr uint32_t kDecorationDescriptorSet = 34;
}  // namespace

std::vector<DescriptorUse> usedDescriptors(const std::vector<uint32_t>& words) {
    std::map<uint32_t, uint32_t> bindings, sets;  // by variable id
    std::set<uint32_t> used;
    bool inFunctions = false;  // decorations come before the first OpFunction, code after
    for (size_t i = 5; i < words.size();) {
        const uint32_t count = words[i] >> 16, op = words[i] & 0xffff;
        if (count == 0 || i + count > words.size()) break;
        if (op == kOpFunction) inFunctions = true;
        if (!inFunctions && op == kOpDecorate && count >= 4) {
            if (words[i + 2] == kDecorationBinding) bindings[words[i + 1]] = words[i + 3];
            if (words[i + 2] == kDecorationDescriptorSet) sets[words[i + 1]] = words[i + 3];
        }
        if (inFunctions)
            for (uint32_t k = 1; k < count; ++k) used.insert(words[i + k]);
        i += count;
    }
    std::vector<DescriptorUse> out;
    for (const auto& [id, binding] : bindings)
        if (used.count(id)) out.push_back({sets.count(id) ? sets[id] : 0, binding});
    return out;
}

uint32_t uniformBlocksAsStorage(std::vector<uint32_t>& words, const std::string& path) {
    if (words.size() < 5) fail("'" + path + "' is too short for SPIR-V");
    if (words[1] >= 0x00010400u)
        fail("'" + path + "' is SPIR-V " + std::to_string((words[1] >> 16) & 0xff) + "." +
             std::to_string((words[1] >> 8) & 0xff) + ": --uniform-blocks storage rewrites SPIR-V 1.0-1.3 only " +
             "(BufferBlock); use --uniform-blocks uniform");
    std::map<uint32_t, uint32_t> uniformPointee;  // OpTypePointer Uniform: pointer id -> pointee type
    std::set<uint32_t> uniformTypes;              // pointee types of Uniform-class variables
    std::vector<size_t> blockDecorations;         // word index of each OpDecorate ... Block
    for (size_t i = 5; i < words.size();) {
        const uint32_t count = words[i] >> 16, op = words[i] & 0xffff;
        if (count == 0 || i + count > words.size()) break;
        if (op == kOpDecorate && count == 3 && words[i + 2] == kDecorationBlock) blockDecorations.push_back(i);
        if (op == kOpTypePointer && count == 4 && words[i + 2] == kStorageClassUniform) uniformPointee[words[i + 1]] = words[i + 3];
        if (op == kOpVariable && count >= 4 && words[i + 3] == kStorageClassUniform && uniformPointee.count(words[i + 1]))
            uniformTypes.insert(uniformPointee[words[i + 1]]);
        i += count;
    }
    uint32_t rewritten = 0;
    for (size_t i : blockDecorations)
        if (uniformTypes.count(words[i + 1])) {
            words[i + 2] = kDecorationBufferBlock;
            ++rewritten;
        }
    return rewritten;
}

std::vector<std::string> entryPoints(const std::vector<uint32_t>& words, uint32_t executionModel) {
    std::vector<std::string> names;
    // Header is 5 words; each instruction starts with (word count << 16) | opcode.
    for (size_t i = 5; i < words.size();) {
        uint32_t count = words[i] >> 16, op = words[i] & 0xffff;
        if (count == 0 || i + count > words.size()) break;
        if (op == kOpEntryPoint && count >= 4 && words[i + 1] == executionModel) {
            const char* s = reinterpret_cast<const char*>(&words[i + 3]);
            names.emplace_back(s, strnlen(s, (count - 3) * 4));
        }
        i += count;
    }
    return names;
}

ShaderModule loadShader(const Gpu& gpu, const std::string& path, uint32_t executionModel, const std::string& requested,
                        const std::string& fallbackName) {
    std::vector<uint32_t> words = readSpirv(path);

    std::vector<std::string> names = entryPoints(words, executionModel);
    static const char* stageNames[] = {"vertex", "tessellation control", "tessellation evaluation", "geometry", "fragment",
                                       "compute"};
    const std::string stage = executionModel < 6 ? stageNames[executionModel] : "matching";
    if (names.empty())
        fail("'" + path + "' has no " + stage + " entry point: is it the right stage's SPIR-V?");
    ShaderModule s;
    s.path = path;
    auto has = [&](const std::string& n) { for (auto& x : names) if (x == n) return true; return false; };
    if (!requested.empty()) {
        if (!has(requested)) fail("'" + path + "' has no entry point '" + requested + "' (it has '" + names[0] + "')");
        s.entry = requested;
    } else if (names.size() > 1 && fallbackName.empty()) {
        std::string list;
        for (const std::string& n : names) list += (list.empty() ? "'" : ", '") + n + "'";
        fail("'" + path + "' has " + std::to_string(names.size()) + " " + stage +
             " entry points (" + list + "); it needs exactly one (compile one entry point per module, glslangValidator -e NAME)");
    } else {
        s.entry = names.size() == 1 ? names[0] : fallbackName;
        if (!has(s.entry)) fail("'" + path + "' has several entry points and none named '" + fallbackName + "'");
    }
    if (gpu.uniformBlocksAsStorage) uniformBlocksAsStorage(words, path);
    s.descriptors = usedDescriptors(words);
    s.module = createShaderModule(gpu.device, words);
    return s;
}

void destroyShader(const Gpu& gpu, ShaderModule& shader) {
    if (shader.module) vkDestroyShaderModule(gpu.device, shader.module, nullptr);
    shader = ShaderModule{};
}

}  // namespace gt
