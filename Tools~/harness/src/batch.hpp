// --batch FILE: many runs in one process, one line of FILE per run (its options, tab-separated),
// over one device, each distinct graphics pipeline created once. Why: on lavapipe a run's own cost
// is mostly process start, device creation and the pipeline (SPIR-V -> NIR -> LLVM, even with Mesa's
// disk cache about 0.3 CPU s); fixtures that draw hundreds of scenes with one pipeline pay it once.
// A run's output is framed by "batch run INDEX" and "batch exit INDEX CODE"; an error ends that run
// only ("batch error INDEX MESSAGE"), the next line runs on a fresh device. Exit 0 when every run did.
#pragma once
#include <string>

#include "cli.hpp"
#include "device.hpp"
#include "pipeline.hpp"

namespace gt {

using RunFunction = int (*)(const Options&);

int runBatch(const std::string& path, RunFunction run);

// The device of a run: a fresh one outside a batch; inside, the batch's, kept while the next run
// asks for the same device and features. releaseGpu destroys only what acquireGpu did not keep.
Gpu acquireGpu(const std::string& nameSubstring, const FeatureRequest& request);
void releaseGpu(Gpu& gpu);

// Inside a batch: the pipeline an earlier run created from the same stages (file bytes and entry
// points), state, render target size and set 0 layout, else VK_NULL_HANDLE (always outside one).
// keepPipeline hands a run's pipeline and its layouts to the batch (destroyed with its device; a
// later run binds its own identically defined layout, which Vulkan's compatibility rules allow);
// keptByBatch says whether the batch owns an object, so the run must not destroy it.
std::string pipelineKey(const Gpu& gpu, const PipelineDesc& desc, const RenderTarget& target, const Pipeline& pipeline);
VkPipeline keptPipeline(const std::string& key);
void keepPipeline(const std::string& key, const Pipeline& pipeline);
bool keptByBatch(const void* handle);

}  // namespace gt
