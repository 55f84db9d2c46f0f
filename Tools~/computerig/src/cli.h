// Command line of gt-compute (see ../README.md).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

struct BufferArg {
    uint32_t binding = 0;
    std::string file;      // input file, or empty for a zero-filled buffer
    uint64_t zeroBytes = 0; // size of a zero-filled buffer
    bool uniform = false;
};

struct OutputArg {
    uint32_t binding = 0;
    std::string file;
};

struct Options {
    std::string spv;
    std::string entry = "main";
    std::string device;
    uint32_t groups[3] = {1, 1, 1};
    uint32_t repeat = 1;
    bool timestamps = false;
    bool listDevices = false;
    std::vector<BufferArg> buffers;
    std::vector<OutputArg> outputs;
};

// Parses argv; on a bad argument prints why and exits with status 2.
Options ParseOptions(int argc, char** argv);
