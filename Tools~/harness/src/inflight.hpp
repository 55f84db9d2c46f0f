// Frames in flight (--in-flight N, N >= 2): the frame loop of an application rather than of a
// profiler. Frames are submitted back to back, at most N queued; each frame slot has its own
// TerrainParams and --storage buffers (so the pre-pass of frame f may run while frame f-1 still
// draws from the other slot's vertex cache), and the GPU time reported is the period between
// consecutive frames' ends, which overlap between frames makes shorter than one frame's latency.
//
// Ordering, by two timeline semaphores instead of barriers and host waits:
//   pre-pass f  waits  drawn  >= f-N+1   (frame f-N, which read this slot's buffers, has drawn)
//               signals cached = f+1
//   draw f      waits  cached >= f+1     (at the graphics shader stages, only when a pre-pass ran)
//               signals drawn  = f+1
// With --async-compute the pre-pass goes to a queue of a compute-only family and can run
// alongside the graphics queue's draw; without it, both go to the graphics queue.
#pragma once
#include "frames.hpp"

namespace gt {

// settings.computeOnce: each slot's pre-pass runs once (its first frame). Re-send and readback
// are not supported here (the command line rejects them with --in-flight). dumps: written from the
// storage buffers of the last frame's slot (printed as main prints them).
FrameResults runFramesInFlight(const Gpu& gpu, const RenderTarget& target, const Pipeline& pipeline, Inputs& inputs,
                               const std::vector<StorageBuffer>& storage, const std::vector<StorageOption>& storageOptions,
                               const std::vector<StorageDump>& dumps, const DrawWork& work,
                               const std::vector<ComputePass>& compute, const FrameSettings& settings, uint32_t inFlight);

}  // namespace gt
