// Command line of gt-harness (documented in ../README.md).
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "images.hpp"
#include "render_state.hpp"

namespace gt {

// --uniform-blocks: how the rig's uniform blocks (TerrainParams b0, the camera b1) are bound.
enum class UniformBlocks {
    Auto,     // storage on lavapipe, uniform elsewhere
    Uniform,  // as compiled: uniform-buffer descriptors
    Storage,  // rewritten as storage blocks (spirv.hpp, uniformBlocksAsStorage)
};

enum class Mode {
    Tessellated,  // --vert --tesc --tese --frag: patch-list draw, SV_VertexID only
    Fallback,     // --vert --frag without tesc/tese: indexed (F+1)^2 grid, one instance per tile
    StaticMesh,   // --static-mesh --mesh P I: a plain indexed triangle mesh (benchmark baseline)
};

// --storage BINDING:BYTES: a zero-filled device-local storage buffer at BINDING of set 0.
struct StorageOption {
    uint32_t binding = 0;
    uint64_t bytes = 0;
    std::string dataPath;  // --storage-data: the buffer holds this file's bytes instead of zeros
};

// --compute SPV:GX[,GY[,GZ]]: a compute kernel dispatched over GX x GY x GZ work groups each frame.
struct ComputeOption {
    std::string spec;  // the option's value as given, for error messages
    std::string path;
    std::array<uint32_t, 3> groups{1, 1, 1};
};

// --dump-storage BINDING:FILE: the storage buffer's bytes after the last frame.
struct StorageDump {
    uint32_t binding = 0;
    std::string path;
    uint64_t bytes = 0;   // --dump-storage-prefix: the first `bytes` only; 0: the whole buffer
};

struct Options {
    bool listDevices = false;
    std::string deviceSubstring;  // "" = first device that has what the run needs
    UniformBlocks uniformBlocks = UniformBlocks::Auto;

    std::string vertPath, tescPath, tesePath, fragPath;
    std::string vertEntry, tescEntry, teseEntry, fragEntry;  // "" = the module's only entry point, else the default name

    std::string buffersDir;
    std::optional<std::array<float, 4>> range;  // --range c,d,g,h patches params.f32's first float4
    std::string snowDepthPath, snowParamsPath;  // --snow-depth / --snow-params (GT_SNOW): binding 6, params + 16 bytes
    std::string paramsTailPath;                 // --params-tail (GT_LOD): bytes appended to TerrainParams

    Mode mode = Mode::Tessellated;
    uint32_t patches = 0;
    uint32_t controlPoints = 4;
    uint32_t gridFactor = 0;  // fallback
    uint32_t instances = 1;   // fallback
    std::string gridIndicesPath;  // --grid-indices: the fallback grid's triangles in another order
    std::string meshPositions, meshIndices;

    uint32_t width = 256, height = 256;
    std::string pngPath;
    std::string depthOutPath;  // --depth-out FILE: the depth attachment's D32 floats after the last frame
    std::string depthInPath;   // --depth-in FILE: the depth attachment's D32 floats before the frame
    std::string stencilOutPath;  // --stencil-out FILE: the stencil's bytes after the last frame (needs --stencil)
    std::string stencilInPath;   // --stencil-in FILE: the stencil's bytes before the frame (needs --stencil)
    VkFormat colorFormat = VK_FORMAT_R8G8B8A8_UNORM;  // --color-format: the colour attachment (4 bytes a texel)
    VkFormat target1Format = VK_FORMAT_UNDEFINED;     // --target1 FORMAT:FILE: a second colour attachment (SV_Target1)
    std::string target1Path;
    bool wireframe = false;
    RenderState state;  // --cull --ztest --zwrite --zclip --color-mask --depth --stencil (render_state.hpp)

    std::vector<StorageOption> storage;  // in command-line order
    std::vector<ComputeOption> computes; // dispatched in command-line order before the render pass
    std::vector<StorageDump> dumps;
    std::vector<ImageOption> images;     // --image, in command-line order (images.hpp)
    std::vector<SamplerOption> samplers; // --sampler

    std::string readbackPath;
    uint64_t readbackFloats = 0;
    bool readbackFillNan = true;

    bool stats = false;
    uint32_t frames = 1, warmup = 0;
    bool timestamps = false;
    bool updateRangePerFrame = false;
    float rangePan = 0.0f;      // --range-pan FRACTION (with --update-range-per-frame)
    std::string cameraPath;      // --camera-path FILE: N RigCamera blocks, frame f draws with block f mod N
    std::string paramsPath;      // --params-path FILE: N (TerrainParams, dispatch flag) records, frame f draws record f mod N
    std::string movingTailPath; // --params-tail-path FILE: N --params-tail records, frame f draws record f mod N
    bool computeOnce = false;
    bool computeTimestamp = true;  // --no-compute-timestamp: frame timestamps only
    uint64_t resendBytes = 0;
    uint64_t placementPad = 0;   // --placement-pad BYTES: a buffer allocated before the job's own
    uint32_t inFlight = 1;       // --in-flight N: frames submitted back to back (inflight.hpp)
    bool asyncCompute = false;   // --async-compute: the pre-pass on a compute-only queue

    std::optional<uint64_t> maxVerticesPerDraw;  // unset: 65,536 on lavapipe, no limit elsewhere
    std::optional<uint32_t> maxFactor;            // unset: the device's maxTessellationGenerationLevel
};

// One numeric field of a compound value in [minValue, maxValue]; the error names the option, the
// field and the whole value.
uint64_t parseField(const std::string& option, const std::string& value, const std::string& field,
                    const std::string& text, uint64_t minValue, uint64_t maxValue);

// The BINDING field of a compound value (--storage, --image, --sampler, ...): at most 1023 and not
// one of the rig's own bindings.
uint32_t parseStorageBinding(const std::string& option, const std::string& value, const std::string& bindingText);

// Parses argv; throws gt::Error with the offending flag/value on bad input.
Options parseOptions(int argc, char** argv);

// The usage text printed by --help.
const char* usageText();

}  // namespace gt
