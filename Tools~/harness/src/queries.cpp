#include "queries.hpp"

#include "check.hpp"

namespace gt {

StatsQuery createStatsQuery(const Gpu& gpu) {
    struct Bit { VkQueryPipelineStatisticFlagBits bit; const char* name; bool tess; };
    // Ascending bit order = the order of the results.
    static const Bit bits[] = {
        {VK_QUERY_PIPELINE_STATISTIC_INPUT_ASSEMBLY_VERTICES_BIT, "input_assembly_vertices", false},
        {VK_QUERY_PIPELINE_STATISTIC_INPUT_ASSEMBLY_PRIMITIVES_BIT, "input_assembly_primitives", false},
        {VK_QUERY_PIPELINE_STATISTIC_VERTEX_SHADER_INVOCATIONS_BIT, "vertex_shader_invocations", false},
        {VK_QUERY_PIPELINE_STATISTIC_CLIPPING_INVOCATIONS_BIT, "clipping_invocations", false},
        {VK_QUERY_PIPELINE_STATISTIC_CLIPPING_PRIMITIVES_BIT, "clipping_primitives", false},
        {VK_QUERY_PIPELINE_STATISTIC_FRAGMENT_SHADER_INVOCATIONS_BIT, "fragment_shader_invocations", false},
        {VK_QUERY_PIPELINE_STATISTIC_TESSELLATION_CONTROL_SHADER_PATCHES_BIT, "tessellation_control_shader_patches", true},
        {VK_QUERY_PIPELINE_STATISTIC_TESSELLATION_EVALUATION_SHADER_INVOCATIONS_BIT,
         "tessellation_evaluation_shader_invocations", true},
    };
    StatsQuery q;
    VkQueryPipelineStatisticFlags flags = 0;
    for (const Bit& b : bits) {
        if (b.tess && !gpu.enabled.tessellationShader) continue;
        flags |= b.bit;
        q.names.push_back(b.name);
    }
    VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    info.queryType = VK_QUERY_TYPE_PIPELINE_STATISTICS;
    info.queryCount = 1;
    info.pipelineStatistics = flags;
    GT_VK(vkCreateQueryPool(gpu.device, &info, nullptr, &q.pool));
    return q;
}

std::vector<std::pair<std::string, uint64_t>> readStats(const Gpu& gpu, const StatsQuery& q) {
    std::vector<uint64_t> values(q.names.size());
    GT_VK(vkGetQueryPoolResults(gpu.device, q.pool, 0, 1, values.size() * 8, values.data(), values.size() * 8,
                                VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
    std::vector<std::pair<std::string, uint64_t>> out;
    for (size_t i = 0; i < values.size(); ++i) out.emplace_back(q.names[i], values[i]);
    return out;
}

TimestampQuery createTimestampQuery(const Gpu& gpu, uint32_t count) {
    if (gpu.timestampValidBits == 0) fail(std::string(gpu.properties.deviceName) + "'s graphics queue has no timestamps");
    TimestampQuery q;
    q.count = count;
    q.nsPerTick = gpu.properties.limits.timestampPeriod;
    q.mask = gpu.timestampValidBits >= 64 ? ~0ull : ((1ull << gpu.timestampValidBits) - 1);
    VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    info.queryType = VK_QUERY_TYPE_TIMESTAMP;
    info.queryCount = count;
    GT_VK(vkCreateQueryPool(gpu.device, &info, nullptr, &q.pool));
    return q;
}

std::vector<uint64_t> readTicks(const Gpu& gpu, const TimestampQuery& q) {
    std::vector<uint64_t> t(q.count);
    GT_VK(vkGetQueryPoolResults(gpu.device, q.pool, 0, q.count, t.size() * 8, t.data(), 8,
                                VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
    for (uint64_t& v : t) v &= q.mask;
    return t;
}

double ticksToMs(const TimestampQuery& q, uint64_t from, uint64_t to) {
    const uint64_t ticks = (to - from) & q.mask;  // wrap-safe within the valid bits
    return static_cast<double>(ticks) * q.nsPerTick * 1e-6;
}

std::vector<double> readMsSinceFirst(const Gpu& gpu, const TimestampQuery& q) {
    const std::vector<uint64_t> t = readTicks(gpu, q);
    std::vector<double> ms;
    for (uint32_t i = 1; i < q.count; ++i) ms.push_back(ticksToMs(q, t[0], t[i]));
    return ms;
}

void destroyQuery(const Gpu& gpu, VkQueryPool& pool) {
    if (pool) vkDestroyQueryPool(gpu.device, pool, nullptr);
    pool = VK_NULL_HANDLE;
}

}  // namespace gt
