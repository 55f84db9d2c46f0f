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
    VkQueryPool pool = VK_NULL_HANDLE;  // query 0 before the frame's work, the last after it,
    uint32_t count = 2;                 // any between them at points inside the frame (compute end)
    double nsPerTick = 0.0;
    uint64_t mask = 0;
};

// count >= 2 timestamps per frame. Throws gt::Error when the queue family has no timestamps.
TimestampQuery createTimestampQuery(const Gpu& gpu, uint32_t count = 2);
// Milliseconds from timestamp 0 to each of timestamps 1..count-1 of the last submitted frame
// (waits for them): the last value is the frame time.
std::vector<double> readMsSinceFirst(const Gpu& gpu, const TimestampQuery& q);

// The raw ticks of all count timestamps of the last submitted use (waits for them), masked to the
// valid bits; ticksToMs turns a wrap-safe difference of two into milliseconds.
std::vector<uint64_t> readTicks(const Gpu& gpu, const TimestampQuery& q);
double ticksToMs(const TimestampQuery& q, uint64_t from, uint64_t to);

void destroyQuery(const Gpu& gpu, VkQueryPool& pool);

}  // namespace gt
