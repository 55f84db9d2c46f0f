#include "draw_split.hpp"

#include <algorithm>
#include <string>

#include "check.hpp"

namespace gt {

uint64_t quadVerticesBound(uint32_t maxFactor) {
    const uint64_t n = static_cast<uint64_t>(maxFactor) + 1;
    return n * n;
}

std::vector<PatchRange> splitPatches(uint32_t patches, uint64_t verticesPerPatch, uint64_t maxVertices) {
    if (maxVertices == 0) return {PatchRange{0, patches}};
    if (verticesPerPatch > maxVertices)
        fail("one patch may generate " + std::to_string(verticesPerPatch) + " vertices, more than the per-draw limit " +
             std::to_string(maxVertices) + "; lower --max-factor");
    const uint64_t perDraw = std::max<uint64_t>(1, maxVertices / std::max<uint64_t>(1, verticesPerPatch));
    std::vector<PatchRange> ranges;
    for (uint64_t first = 0; first < patches; first += perDraw) {
        const uint64_t count = std::min<uint64_t>(perDraw, patches - first);
        ranges.push_back({static_cast<uint32_t>(first), static_cast<uint32_t>(count)});
    }
    return ranges;
}

}  // namespace gt
