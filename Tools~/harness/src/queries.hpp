// Query pools: pipeline statistics ("stat NAME VALUE") and timestamps around a frame.
#pragma once
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "device.hpp"

namespace gt {

struct StatsQuery {
    VkQueryPool pool = VK_NULL_HANDLE;
    std::vector<const char*> names;  // in result order (ascending flag bits)
};

// Counts input assembly, vertex, tessellation (when enabled), clipping and fragment work.
StatsQuery createStatsQuery(const Gpu& gpu);
std::vector<std::pair<std::string, uint64_t>> readStats(const Gpu& gpu, const StatsQuery& q);

struct TimestampQuery {
    VkQueryPool pool = VK_NULL_HANDLE;  // two queries: 0 before the frame's work, 1 after
    double nsPerTick = 0.0;
    uint64_t mask = 0;
};

// Throws gt::Error when the queue family has no timestamps.
TimestampQuery createTimestampQuery(const Gpu& gpu);
// Milliseconds between the two timestamps of the last submitted frame (waits for them).
double readFrameMs(const Gpu& gpu, const TimestampQuery& q);

void destroyQuery(const Gpu& gpu, VkQueryPool& pool);

}  // namespace gt
