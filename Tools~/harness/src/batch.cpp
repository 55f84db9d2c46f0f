#include "batch.hpp"

#include <cstdio>
#include <fstream>
#include <map>
#include <set>
#include <vector>

#include "check.hpp"
#include "render_state.hpp"
#include "vkcommon.hpp"

namespace gt {

namespace {

struct BatchState {
    bool active = false;
    bool haveGpu = false;
    Gpu gpu;
    std::string gpuKey;
    std::map<std::string, Pipeline> pipelines;
    std::set<const void*> kept;
    uint64_t created = 0, reused = 0;
};

BatchState batch;

std::string requestKey(const std::string& name, const FeatureRequest& r) {
    const bool flags[] = {r.tessellation, r.wireframe, r.depthClamp, r.vertexStores, r.statistics, r.compute, r.timeline, r.asyncCompute};
    std::string key = name + '\n';
    for (bool f : flags) key += f ? '1' : '0';
    return key;
}

// After a failed run the device is left as it is (what the run created is not known here); the
// next run gets a fresh one.
void forgetGpu() {
    batch.pipelines.clear();
    batch.kept.clear();
    batch.haveGpu = false;
}

void dropGpu() {
    if (!batch.haveGpu) return;
    vkDeviceWaitIdle(batch.gpu.device);
    for (auto& p : batch.pipelines) {
        vkDestroyPipeline(batch.gpu.device, p.second.pipeline, nullptr);
        vkDestroyPipelineLayout(batch.gpu.device, p.second.layout, nullptr);
        vkDestroyDescriptorSetLayout(batch.gpu.device, p.second.setLayout, nullptr);
    }
    destroyGpu(batch.gpu);
    forgetGpu();
}

// A line's options: tab-separated words (paths may hold spaces); empty lines and lines starting
// with '#' are not runs.
std::vector<std::string> words(const std::string& line) {
    std::vector<std::string> w;
    size_t start = 0;
    for (;;) {
        const size_t tab = line.find('\t', start);
        const std::string word = line.substr(start, tab == std::string::npos ? std::string::npos : tab - start);
        if (!word.empty()) w.push_back(word);
        if (tab == std::string::npos) return w;
        start = tab + 1;
    }
}

std::string fileBytes(const std::string& path) {
    const std::vector<uint8_t> b = readFile(path);
    return std::string(b.begin(), b.end());
}

}  // namespace

Gpu acquireGpu(const std::string& nameSubstring, const FeatureRequest& request) {
    if (!batch.active) return createGpu(nameSubstring, request);
    const std::string key = requestKey(nameSubstring, request);
    if (batch.haveGpu && batch.gpuKey != key) dropGpu();
    if (!batch.haveGpu) {
        batch.gpu = createGpu(nameSubstring, request);
        batch.gpuKey = key;
        batch.haveGpu = true;
    }
    return batch.gpu;
}

void releaseGpu(Gpu& gpu) {
    if (!batch.active) destroyGpu(gpu);
    else vkDeviceWaitIdle(gpu.device);
    gpu = Gpu{};
}

std::string pipelineKey(const Gpu& gpu, const PipelineDesc& d, const RenderTarget& target, const Pipeline& p) {
    if (!batch.active) return "";
    std::string key = std::to_string(static_cast<int>(d.mode)) + ' ' + std::to_string(d.controlPoints) + ' ' +
                      std::to_string(d.wireframe) + ' ' + describeRenderState(d.state) + ' ' +
                      std::to_string(target.width) + 'x' + std::to_string(target.height) + " colour " +
                      std::to_string(target.colorFormat) + ' ' + std::to_string(target.color1Format) + " blocks " +
                      std::to_string(gpu.uniformBlocksAsStorage) + " set0";
    for (uint32_t b : p.bindings) key += ' ' + std::to_string(b);
    for (const ImageDescriptor& i : p.images) key += " image " + std::to_string(i.binding) + ':' + std::to_string(i.type);
    for (const ShaderModule* s : {&d.vert, &d.tesc, &d.tese, &d.frag})
        if (s->module) key += '\n' + s->entry + '\n' + fileBytes(s->path);
    return key;
}

VkPipeline keptPipeline(const std::string& key) {
    if (!batch.active) return VK_NULL_HANDLE;
    const auto it = batch.pipelines.find(key);
    if (it == batch.pipelines.end()) return VK_NULL_HANDLE;
    ++batch.reused;
    return it->second.pipeline;
}

void keepPipeline(const std::string& key, const Pipeline& p) {
    if (!batch.active) return;
    Pipeline& kept = batch.pipelines[key];
    kept.pipeline = p.pipeline;
    kept.layout = p.layout;
    kept.setLayout = p.setLayout;
    batch.kept.insert(p.pipeline);
    batch.kept.insert(p.layout);
    batch.kept.insert(p.setLayout);
    ++batch.created;
}

bool keptByBatch(const void* handle) { return batch.active && batch.kept.count(handle) != 0; }

int runBatch(const std::string& path, RunFunction run) {
    std::ifstream in(path);
    if (!in) fail("--batch '" + path + "': cannot read the file");
    batch.active = true;
    std::string line;
    uint32_t index = 0, failed = 0, lineNumber = 0;
    while (std::getline(in, line)) {
        ++lineNumber;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        std::vector<std::string> w = words(line);
        if (w.empty() || w[0][0] == '#') continue;
        std::vector<char*> argv = {const_cast<char*>("gt-harness")};
        for (std::string& s : w) argv.push_back(&s[0]);
        std::printf("batch run %u line %u\n", index, lineNumber);
        int code = 1;
        try {
            const Options o = parseOptions(static_cast<int>(argv.size()), argv.data());
            if (o.listDevices) fail("--list-devices is not a batch run");
            code = run(o);
        } catch (const std::exception& e) {
            std::fflush(stdout);
            std::printf("batch error %u %s\n", index, e.what());
            std::fprintf(stderr, "gt-harness: --batch '%s' line %u: error: %s\n", path.c_str(), lineNumber, e.what());
            forgetGpu();
        }
        std::printf("batch exit %u %d\n", index, code);
        failed += code != 0;
        ++index;
    }
    std::printf("batch runs %u failed %u pipelines_created %llu reused %llu\n", index, failed,
                static_cast<unsigned long long>(batch.created), static_cast<unsigned long long>(batch.reused));
    dropGpu();
    batch.active = false;
    if (index == 0) fail("--batch '" + path + "' holds no run");
    return failed ? 1 : 0;
}

}  // namespace gt
