// gt-harness entry point: parse the command line, set the device up, draw, report.
// Output is line-oriented and machine-readable ("KEY [SUBKEY] VALUE"), see ../README.md.
#include <algorithm>
#include <array>
#include <cstring>
#include <cstdio>
#include <numeric>
#include <utility>
#include <vector>

#include "batch.hpp"
#include "check.hpp"
#include "cli.hpp"
#include "compute.hpp"
#include "device.hpp"
#include "draw_split.hpp"
#include "frames.hpp"
#include "images.hpp"
#include "inflight.hpp"
#include "inputs.hpp"
#include "pipeline.hpp"
#include "png.hpp"
#include "readback.hpp"
#include "spirv.hpp"
#include "storage.hpp"
#include "target.hpp"

namespace gt {
namespace {

// Indices of the two triangles of each cell of a (F+1) x (F+1) vertex grid, row-major vertices:
// the renderer's fallback index buffer (TerrainFrameDriver.EnsureFallbackIndices), cell split
// along its (v + 1, v + row) diagonal, clockwise seen from above (col -> x, row -> z, Unity's front).
std::vector<uint32_t> rowMajorGrid(uint32_t f) {
    std::vector<uint32_t> idx;
    idx.reserve(static_cast<size_t>(f) * f * 6);
    const uint32_t row = f + 1;
    for (uint32_t j = 0; j < f; ++j)
        for (uint32_t i = 0; i < f; ++i) {
            const uint32_t v = j * row + i;
            idx.insert(idx.end(), {v, v + row, v + 1, v + 1, v + row, v + row + 1});
        }
    return idx;
}

// A grid's triangles as a sorted list, each rotated to start at its smallest index (the winding
// is kept), so two index orders of the same triangles compare equal.
std::vector<std::array<uint32_t, 3>> canonicalTriangles(const std::vector<uint32_t>& idx) {
    std::vector<std::array<uint32_t, 3>> t(idx.size() / 3);
    for (size_t i = 0; i < t.size(); ++i) {
        const uint32_t a = idx[3 * i], b = idx[3 * i + 1], c = idx[3 * i + 2];
        t[i] = a <= b && a <= c ? std::array<uint32_t, 3>{a, b, c}
             : b <= c           ? std::array<uint32_t, 3>{b, c, a}
                                : std::array<uint32_t, 3>{c, a, b};
    }
    std::sort(t.begin(), t.end());
    return t;
}

// The fallback grid's index buffer: row by row, or --grid-indices' order of the same triangles
// (a cache-optimised order: gt bench's fair static mesh). A file holding other triangles fails.
std::vector<uint8_t> gridIndices(uint32_t f, const std::string& orderPath, uint32_t* count) {
    std::vector<uint32_t> idx = rowMajorGrid(f);
    if (!orderPath.empty()) {
        const std::vector<uint8_t> bytes = readFile(orderPath);
        if (bytes.size() != idx.size() * 4)
            fail("--grid-indices '" + orderPath + "' has " + std::to_string(bytes.size()) + " bytes; expected " +
                 std::to_string(idx.size() * 4) + " (6 F^2 uint32 for --grid-factor " + std::to_string(f) + ")");
        std::vector<uint32_t> order(idx.size());
        std::memcpy(order.data(), bytes.data(), bytes.size());
        if (canonicalTriangles(order) != canonicalTriangles(idx))
            fail("--grid-indices '" + orderPath + "' does not hold the " + std::to_string(2ull * f * f) +
                 " triangles of the --grid-factor " + std::to_string(f) + " grid (each once, same winding)");
        idx = std::move(order);
    }
    *count = static_cast<uint32_t>(idx.size());
    std::vector<uint8_t> bytes(idx.size() * 4);
    std::memcpy(bytes.data(), idx.data(), bytes.size());
    return bytes;
}

DrawWork prepareWork(const Options& o, const Gpu& gpu) {
    DrawWork w;
    w.mode = o.mode;
    w.controlPoints = o.controlPoints;
    w.instances = o.instances;
    if (o.mode == Mode::Tessellated) {
        const uint64_t limit = o.maxVerticesPerDraw ? *o.maxVerticesPerDraw : (gpu.isLavapipe ? kLavapipeMaxVerticesPerDraw : 0);
        const uint32_t factor = o.maxFactor ? *o.maxFactor : gpu.properties.limits.maxTessellationGenerationLevel;
        const uint64_t perPatch = quadVerticesBound(factor);
        w.draws = splitPatches(o.patches, perPatch, limit);
        std::printf("split max_vertices_per_draw %llu\n", static_cast<unsigned long long>(limit));
        std::printf("split max_factor %u\n", factor);
        std::printf("split vertices_per_patch_bound %llu\n", static_cast<unsigned long long>(perPatch));
        std::printf("draws %zu\n", w.draws.size());
        for (size_t i = 0; i < w.draws.size(); ++i)
            std::printf("draw %zu first_patch %u patches %u\n", i, w.draws[i].firstPatch, w.draws[i].patchCount);
    } else if (o.mode == Mode::Fallback) {
        w.indices = createDeviceBuffer(gpu, gridIndices(o.gridFactor, o.gridIndicesPath, &w.indexCount), VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
        std::printf("draws 1\n");
        std::printf("fallback grid_vertices %u indices %u instances %u order %s\n", (o.gridFactor + 1) * (o.gridFactor + 1),
                    w.indexCount, o.instances, o.gridIndicesPath.empty() ? "rows" : "file");
    } else {
        std::vector<uint8_t> pos = readFile(o.meshPositions), idx = readFile(o.meshIndices);
        if (pos.empty() || pos.size() % 12 != 0)
            fail("'" + o.meshPositions + "' has " + std::to_string(pos.size()) + " bytes; expected a non-zero multiple of 12 (float3)");
        if (idx.empty() || idx.size() % 12 != 0)
            fail("'" + o.meshIndices + "' has " + std::to_string(idx.size()) + " bytes; expected a non-zero multiple of 12 (3 uint32 per triangle)");
        const uint32_t vertexCount = static_cast<uint32_t>(pos.size() / 12);
        const uint32_t* ip = reinterpret_cast<const uint32_t*>(idx.data());
        for (size_t i = 0; i < idx.size() / 4; ++i)
            if (ip[i] >= vertexCount)
                fail("'" + o.meshIndices + "': index " + std::to_string(ip[i]) + " at " + std::to_string(i) +
                     " >= vertex count " + std::to_string(vertexCount));
        w.positions = createDeviceBuffer(gpu, pos, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
        w.indices = createDeviceBuffer(gpu, idx, VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
        w.indexCount = static_cast<uint32_t>(idx.size() / 4);
        w.instances = 1;
        std::printf("draws 1\n");
        std::printf("mesh vertices %u triangles %u\n", vertexCount, w.indexCount / 3);
    }
    return w;
}

void printTimes(const char* key, std::vector<double> ms) {
    if (ms.empty()) return;
    std::sort(ms.begin(), ms.end());
    const size_t n = ms.size();
    const double median = n % 2 ? ms[n / 2] : 0.5 * (ms[n / 2 - 1] + ms[n / 2]);
    const double mean = std::accumulate(ms.begin(), ms.end(), 0.0) / static_cast<double>(n);
    std::printf("time %s_median %.6f\n", key, median);
    std::printf("time %s_min %.6f\n", key, ms.front());
    std::printf("time %s_mean %.6f\n", key, mean);
}

// --depth-out: the depth attachment's floats, raw, in the PNG's row order; prints where and how
// many of them differ from the clear value (the pixels some draw wrote).
void writeDepthOut(const Gpu& gpu, const RenderTarget& target, const std::string& path) {
    const std::vector<float> depth = readDepth(gpu, target);
    writeFile(path, depth.data(), depth.size() * 4);
    const auto written = std::count_if(depth.begin(), depth.end(), [&](float d) { return d != target.depthClear; });
    std::printf("depth_out %s %u %u written %lld\n", path.c_str(), target.width, target.height, static_cast<long long>(written));
}

// --depth-in: the depth a previous pass wrote (--depth-out's file), checked; prints how many of its
// pixels differ from the clear.
std::vector<float> readDepthIn(const RenderTarget& target, const std::string& path) {
    const std::vector<uint8_t> bytes = readFile(path);
    const size_t count = static_cast<size_t>(target.width) * target.height;
    if (bytes.size() != count * 4)
        fail("--depth-in '" + path + "' has " + std::to_string(bytes.size()) + " bytes; expected " + std::to_string(count * 4) +
             " (W*H float32 for " + std::to_string(target.width) + "x" + std::to_string(target.height) + ")");
    std::vector<float> depth(count);
    std::memcpy(depth.data(), bytes.data(), bytes.size());
    for (size_t i = 0; i < count; ++i)
        if (!(depth[i] >= 0.0f && depth[i] <= 1.0f))
            fail("--depth-in '" + path + "': pixel " + std::to_string(i) + " is " + std::to_string(depth[i]) +
                 ", outside a depth attachment's [0, 1]");
    const auto written = std::count_if(depth.begin(), depth.end(), [&](float d) { return d != target.depthClear; });
    std::printf("depth_in %s %u %u written %lld\n", path.c_str(), target.width, target.height, static_cast<long long>(written));
    return depth;
}

// --stencil-in: a previous pass's stencil (--stencil-out's file), its size checked; prints how many are not 0.
std::vector<uint8_t> readStencilIn(const RenderTarget& target, const std::string& path) {
    std::vector<uint8_t> bytes = readFile(path);
    const size_t count = static_cast<size_t>(target.width) * target.height;
    if (bytes.size() != count)
        fail("--stencil-in '" + path + "' has " + std::to_string(bytes.size()) + " bytes; expected " + std::to_string(count) +
             " (W*H bytes for " + std::to_string(target.width) + "x" + std::to_string(target.height) + ")");
    const auto set = std::count_if(bytes.begin(), bytes.end(), [](uint8_t s) { return s != 0; });
    std::printf("stencil_in %s %u %u nonzero %lld\n", path.c_str(), target.width, target.height, static_cast<long long>(set));
    return bytes;
}

// Both uploaded in one copy: uploading one aspect starts from an undefined layout, which would lose the other.
void loadDepthStencilIn(const Gpu& gpu, const RenderTarget& target, const Options& o) {
    if (o.depthInPath.empty() && o.stencilInPath.empty()) return;
    std::vector<float> depth;
    std::vector<uint8_t> stencil;
    if (!o.depthInPath.empty()) depth = readDepthIn(target, o.depthInPath);
    if (!o.stencilInPath.empty()) stencil = readStencilIn(target, o.stencilInPath);
    uploadDepthStencil(gpu, target, o.depthInPath.empty() ? nullptr : &depth, o.stencilInPath.empty() ? nullptr : &stencil);
}

// --stencil-out: the stencil's bytes in the PNG's row order; prints how many are not 0.
void writeStencilOut(const Gpu& gpu, const RenderTarget& target, const std::string& path) {
    const std::vector<uint8_t> stencil = readStencil(gpu, target);
    writeFile(path, stencil.data(), stencil.size());
    const auto set = std::count_if(stencil.begin(), stencil.end(), [](uint8_t s) { return s != 0; });
    std::printf("stencil_out %s %u %u nonzero %lld\n", path.c_str(), target.width, target.height, static_cast<long long>(set));
}

int run(const Options& o) {
    if (o.listDevices) {
        listDevices();
        return 0;
    }
    FeatureRequest request;
    request.tessellation = o.mode == Mode::Tessellated;
    request.wireframe = o.wireframe;
    request.depthClamp = !o.state.zClip;
    request.vertexStores = !o.readbackPath.empty();
    request.statistics = o.stats;
    request.compute = !o.computes.empty();
    request.timeline = o.inFlight > 1;
    request.asyncCompute = o.asyncCompute;
    Gpu gpu = acquireGpu(o.deviceSubstring, request);
    gpu.uniformBlocksAsStorage = o.uniformBlocks == UniformBlocks::Storage ||
                                 (o.uniformBlocks == UniformBlocks::Auto && gpu.isLavapipe);
    printDevice(gpu);
    std::printf("inputs uniform_blocks %s\n", gpu.uniformBlocksAsStorage ? "storage" : "uniform");
    // Held until the end, so every buffer of the job is placed after it (performance.md: where the
    // vertex cache lands moved a 0.6M frame by up to 1%; a sweep of pads averages that out).
    Buffer placementPad;
    if (o.placementPad) {
        placementPad = createDeviceBuffer(gpu, o.placementPad, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
        std::printf("inputs placement_pad %llu\n", static_cast<unsigned long long>(o.placementPad));
    }

    Inputs inputs = loadInputs(gpu, o.buffersDir, o.range, o.readbackFloats, o.readbackFillNan, o.snowDepthPath,
                               o.snowParamsPath, o.paramsTailPath);
    // Before the pipeline: its descriptor set points at the camera buffer this replaces.
    std::vector<uint8_t> cameraPath;
    if (!o.cameraPath.empty()) {
        cameraPath = loadCameraPath(gpu, inputs, o.cameraPath);
        std::printf("inputs camera_path %zu\n", cameraPath.size() / kCameraBytes);
    }
    std::vector<uint8_t> paramsPath;
    if (!o.paramsPath.empty()) {
        paramsPath = loadParamsPath(inputs, o.paramsPath);
        std::printf("inputs params_path %zu\n", paramsPath.size() / paramsRecordBytes(inputs));
    }
    std::vector<uint8_t> paramsTailPath;
    if (!o.movingTailPath.empty()) {
        paramsTailPath = loadParamsTailPath(inputs, o.movingTailPath);
        std::printf("inputs params_tail_path %zu\n", paramsTailPath.size() / inputs.tailBytes);
    }
    std::printf("inputs gregory_patches %u\n", inputs.gregoryPatches);
    if (inputs.snow) std::printf("inputs snow_resolution %u\n", inputs.snowResolution);
    std::printf("inputs range %.9g %.9g %.9g %.9g\n", inputs.params[0], inputs.params[1], inputs.params[2], inputs.params[3]);
    std::vector<StorageBuffer> storage = createStorageBuffers(gpu, o.storage);
    SampledImages sampled = createSampledImages(gpu, o.images, o.samplers);
    for (const ImageOption& i : o.images)
        std::printf("inputs image %u %s %ux%u layers %u\n", i.binding, i.formatName.c_str(), i.width, i.height, i.layers);
    for (const SamplerOption& s : o.samplers)
        std::printf("inputs sampler %u %s\n", s.binding, s.compare ? "compare" : "plain");

    PipelineDesc desc;
    desc.mode = o.mode;
    desc.controlPoints = o.controlPoints;
    desc.wireframe = o.wireframe;
    desc.state = o.state;
    std::printf("%s\n", describeRenderState(o.state).c_str());
    desc.descriptorSets = o.inFlight;
    const std::string vertDefault = o.mode == Mode::Fallback ? "vert_fallback" : "vert";
    desc.vert = loadShader(gpu, o.vertPath, 0, o.vertEntry, vertDefault);
    if (o.mode == Mode::Tessellated) {
        desc.tesc = loadShader(gpu, o.tescPath, 1, o.tescEntry, "hull_shader");
        desc.tese = loadShader(gpu, o.tesePath, 2, o.teseEntry, "domain_shader");
    }
    desc.frag = loadShader(gpu, o.fragPath, 4, o.fragEntry, "frag");

    RenderTarget target = createRenderTarget(gpu, o.width, o.height, depthClearValue(o.state.depth), !o.depthOutPath.empty(),
                                             !o.depthInPath.empty(), o.colorFormat, o.target1Format,
                                             {o.state.stencil.enabled, !o.stencilOutPath.empty(), !o.stencilInPath.empty()});
    loadDepthStencilIn(gpu, target, o);
    Pipeline pipeline = createPipeline(gpu, desc, target, inputs, storage, sampled.descriptors);
    std::vector<ComputePass> compute = createComputePasses(gpu, o.computes, pipeline);
    DrawWork work = prepareWork(o, gpu);

    FrameSettings fs;
    fs.frames = o.frames;
    fs.warmup = o.warmup;
    fs.timestamps = o.timestamps;
    fs.stats = o.stats;
    fs.updateRange = o.updateRangePerFrame;
    fs.cameraPath = std::move(cameraPath);
    fs.paramsPath = std::move(paramsPath);
    fs.paramsTailPath = std::move(paramsTailPath);
    fs.computeOnce = o.computeOnce;
    fs.computeTimestamp = o.computeTimestamp;
    fs.rangePan = o.rangePan;
    fs.resendBytes = o.resendBytes;
    FrameResults results = o.inFlight > 1 ? runFramesInFlight(gpu, target, pipeline, inputs, storage, o.storage, o.dumps,
                                                              work, compute, fs, o.inFlight)
                                          : runFrames(gpu, target, pipeline, inputs, work, compute, fs);

    for (const auto& s : results.stats) std::printf("stat %s %llu\n", s.first.c_str(), static_cast<unsigned long long>(s.second));
    if (o.frames > 1 || o.timestamps) {
        std::printf("time frames %u warmup %u\n", o.frames, o.warmup);
        if (o.inFlight > 1) std::printf("time in_flight %u async_compute %d\n", o.inFlight, o.asyncCompute ? 1 : 0);
        for (size_t i = 0; i < results.gpuMs.size(); ++i) std::printf("time frame_ms %zu %.6f\n", i, results.gpuMs[i]);
        printTimes("frame_ms", results.gpuMs);
        for (size_t i = 0; i < results.computeMs.size(); ++i)
            std::printf("time compute_ms %zu %.6f\n", i, results.computeMs[i]);
        printTimes("compute_ms", results.computeMs);
        if (!compute.empty() && o.inFlight == 1) std::printf("time dispatched_frames %u\n", results.dispatchedFrames);
        printTimes("cpu_frame_ms", results.cpuMs);
        if (gpu.isLavapipe) std::printf("note lavapipe timings are functional figures, not performance\n");
    }

    std::vector<uint8_t> rgba = readColor(gpu, target);
    std::printf("image nonsky_pixels %llu of %llu\n", static_cast<unsigned long long>(countNonSkyPixels(rgba)),
                static_cast<unsigned long long>(rgba.size() / 4));
    if (!o.pngPath.empty()) {
        writePng(o.pngPath, rgba.data(), o.width, o.height);
        std::printf("png %s %u %u\n", o.pngPath.c_str(), o.width, o.height);
    }
    if (!o.depthOutPath.empty()) writeDepthOut(gpu, target, o.depthOutPath);
    if (!o.stencilOutPath.empty()) writeStencilOut(gpu, target, o.stencilOutPath);
    if (!o.target1Path.empty()) {
        const std::vector<uint8_t> texels = readTarget1(gpu, target);
        writeFile(o.target1Path, texels.data(), texels.size());
        std::printf("target1 %s %u %u bytes %zu\n", o.target1Path.c_str(), o.width, o.height, texels.size());
    }
    if (!o.readbackPath.empty()) {
        const uint64_t nan = dumpReadback(inputs.bindings[kBindingReadback], o.readbackFloats, o.readbackPath);
        std::printf("readback %s floats %llu nan %llu\n", o.readbackPath.c_str(),
                    static_cast<unsigned long long>(o.readbackFloats), static_cast<unsigned long long>(nan));
    }

    if (o.inFlight == 1)  // (frames in flight dumped their last frame's buffers themselves)
        for (const StorageDump& d : o.dumps) {
            const uint64_t bytes = dumpStorage(gpu, storage, d);
            std::printf("storage %u %s bytes %llu\n", d.binding, d.path.c_str(), static_cast<unsigned long long>(bytes));
        }

    destroyComputePasses(gpu, compute);
    destroyBuffer(gpu, work.indices);
    destroyBuffer(gpu, work.positions);
    destroyPipeline(gpu, pipeline);
    destroyRenderTarget(gpu, target);
    destroyShader(gpu, desc.vert);
    destroyShader(gpu, desc.tesc);
    destroyShader(gpu, desc.tese);
    destroyShader(gpu, desc.frag);
    destroyStorageBuffers(gpu, storage);
    destroySampledImages(gpu, sampled);
    destroyInputs(gpu, inputs);
    destroyBuffer(gpu, placementPad);
    releaseGpu(gpu);
    return 0;
}

}  // namespace
}  // namespace gt

int main(int argc, char** argv) {
    std::setvbuf(stdout, nullptr, _IOLBF, 0);
    try {
        if (argc == 3 && std::strcmp(argv[1], "--batch") == 0) return gt::runBatch(argv[2], gt::run);
        return gt::run(gt::parseOptions(argc, argv));
    } catch (const gt::Error& e) {
        std::fflush(stdout);
        std::fprintf(stderr, "gt-harness: error: %s\n", e.what());
        return 1;
    } catch (const std::exception& e) {
        std::fflush(stdout);
        std::fprintf(stderr, "gt-harness: error: %s\n", e.what());
        return 1;
    }
}
