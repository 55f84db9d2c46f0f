// gt-compute: headless Vulkan compute runner (see ../README.md).
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <vector>

#include "cli.h"
#include "gpu.h"

namespace {

std::vector<char> ReadFile(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot read " + path);
    return std::vector<char>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void WriteFile(const std::string& path, const std::vector<char>& bytes)
{
    std::ofstream out(path, std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!out) throw std::runtime_error("cannot write " + path);
}

std::vector<uint32_t> ReadSpirv(const std::string& path)
{
    std::vector<char> bytes = ReadFile(path);
    if (bytes.size() < 20 || bytes.size() % 4 != 0) throw std::runtime_error(path + " is not SPIR-V (size " + std::to_string(bytes.size()) + ")");
    std::vector<uint32_t> words(bytes.size() / 4);
    std::copy(bytes.begin(), bytes.end(), reinterpret_cast<char*>(words.data()));
    if (words[0] != 0x07230203u) throw std::runtime_error(path + " is not SPIR-V (bad magic)");
    return words;
}

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
        std::vector<uint32_t> spirv = ReadSpirv(o.spv);
        Gpu gpu(o.device);
        std::printf("device %s\n", gpu.DeviceName().c_str());
        for (const BufferArg& b : o.buffers)
            gpu.AddBuffer(b, b.file.empty() ? std::vector<char>(b.zeroBytes, 0) : ReadFile(b.file));
        RunResult r = gpu.Run(spirv, o.entry, o.groups, o.repeat, o.timestamps);
        if (o.timestamps) {
            std::printf("time dispatches %zu\n", r.dispatchMs.size());
            std::printf("time dispatch_ms_median %.6f\n", Median(r.dispatchMs));
            std::printf("time dispatch_ms_min %.6f\n", *std::min_element(r.dispatchMs.begin(), r.dispatchMs.end()));
        }
        for (const OutputArg& out : o.outputs) {
            WriteFile(out.file, gpu.Read(out.binding));
            std::printf("wrote binding %u -> %s\n", out.binding, out.file.c_str());
        }
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "gt-compute: %s\n", e.what());
        return 1;
    }
}
