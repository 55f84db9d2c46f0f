// gt-compute: headless Vulkan compute runner (see ../README.md).
#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "cli.h"
#include "gpu.h"
#include "vkcommon.hpp"

namespace {

double Median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

} // namespace

int main(int argc, char** argv)
{
    Options o = ParseOptions(argc, argv);
    try {
        if (o.listDevices) {
            Gpu::ListDevices();
            return 0;
        }
        std::vector<uint32_t> spirv = gt::readSpirv(o.spv);
        Gpu gpu(o.device);
        std::printf("device %s\n", gpu.DeviceName().c_str());
        for (const BufferArg& b : o.buffers)
            gpu.AddBuffer(b, b.file.empty() ? std::vector<uint8_t>(b.zeroBytes, 0) : gt::readFile(b.file));
        RunResult r = gpu.Run(spirv, o.entry, o.groups, o.repeat, o.timestamps);
        if (o.timestamps) {
            std::printf("time dispatches %zu\n", r.dispatchMs.size());
            std::printf("time dispatch_ms_median %.6f\n", Median(r.dispatchMs));
            std::printf("time dispatch_ms_min %.6f\n", *std::min_element(r.dispatchMs.begin(), r.dispatchMs.end()));
        }
        for (const OutputArg& out : o.outputs) {
            std::vector<uint8_t> bytes = gpu.Read(out.binding);
            gt::writeFile(out.file, bytes.data(), bytes.size());
            std::printf("wrote binding %u -> %s\n", out.binding, out.file.c_str());
        }
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "gt-compute: %s\n", e.what());
        return 1;
    }
}
