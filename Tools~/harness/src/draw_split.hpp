// Splitting a patch-list draw into several draws over whole patches.
//
// Why: Mesa's lavapipe (22.3.6 .. 25.0.7) mis-renders any tessellated draw that generates more
// than 65,536 vertices (Tools~/rig/README.md, "The rig's drivers"). Each draw here covers
// whole patches and starts at firstVertex = firstPatch * controlPoints, so SV_VertexID (which
// includes firstVertex) keeps counting across draws, while SV_PrimitiveID restarts at 0 in each
// draw: shaders must derive the tile from SV_VertexID / 4, never from SV_PrimitiveID.
#pragma once
#include <cstdint>
#include <vector>

namespace gt {

constexpr uint64_t kLavapipeMaxVerticesPerDraw = 65536;

struct PatchRange {
    uint32_t firstPatch = 0;
    uint32_t patchCount = 0;
};

// Upper bound of the vertices the tessellator generates for one quad patch at factor F: (F+1)^2.
uint64_t quadVerticesBound(uint32_t maxFactor);

// Whole-patch ranges covering [0, patches) with patchCount * verticesPerPatch <= maxVertices each.
// maxVertices == 0: one draw. Throws gt::Error if a single patch exceeds maxVertices.
std::vector<PatchRange> splitPatches(uint32_t patches, uint64_t verticesPerPatch, uint64_t maxVertices);

}  // namespace gt
