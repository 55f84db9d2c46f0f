#include "cli.h"

#include <cstdio>
#include <cstdlib>
#include <set>

namespace {

[[noreturn]] void Usage(const std::string& why)
{
    std::fprintf(stderr,
                 "gt-compute: %s\n"
                 "usage: gt-compute --spv FILE [--entry main] [--device SUBSTR] --groups X,Y[,Z] [--repeat K]\n"
                 "                  [--uniform B=FILE] [--buffer B=FILE]... [--zeros B=BYTES]... [--out B=FILE]...\n"
                 "                  [--timestamps] [--list-devices]\n",
                 why.c_str());
    std::exit(2);
}

uint64_t ParseUnsigned(const std::string& s, const char* what)
{
    if (s.empty() || s.find_first_not_of("0123456789") != std::string::npos) Usage(std::string(what) + " '" + s + "' is not a non-negative integer");
    return std::strtoull(s.c_str(), nullptr, 10);
}

// "B=REST" -> binding B and REST.
std::pair<uint32_t, std::string> BindingPair(const std::string& arg, const char* option)
{
    size_t eq = arg.find('=');
    if (eq == std::string::npos || eq + 1 >= arg.size()) Usage(std::string(option) + " needs BINDING=VALUE, got '" + arg + "'");
    uint64_t b = ParseUnsigned(arg.substr(0, eq), "binding");
    if (b > 63) Usage("binding " + std::to_string(b) + " is above 63");
    return {static_cast<uint32_t>(b), arg.substr(eq + 1)};
}

} // namespace

Options ParseOptions(int argc, char** argv)
{
    Options o;
    std::set<uint32_t> bound;
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) Usage(a + " needs a value");
            return argv[++i];
        };
        if (a == "--spv") o.spv = value();
        else if (a == "--entry") o.entry = value();
        else if (a == "--device") o.device = value();
        else if (a == "--repeat") {
            uint64_t k = ParseUnsigned(value(), "--repeat");
            if (k < 1 || k > 100000) Usage("--repeat must be from 1 to 100000");
            o.repeat = static_cast<uint32_t>(k);
        } else if (a == "--groups") {
            std::string g = value();
            int n = 0;
            size_t start = 0;
            while (start <= g.size() && n < 3) {
                size_t comma = g.find(',', start);
                std::string part = g.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
                uint64_t v = ParseUnsigned(part, "--groups");
                if (v < 1 || v > 65535) Usage("--groups counts must be from 1 to 65535");
                o.groups[n++] = static_cast<uint32_t>(v);
                if (comma == std::string::npos) break;
                start = comma + 1;
            }
        } else if (a == "--uniform" || a == "--buffer" || a == "--zeros") {
            auto [b, rest] = BindingPair(value(), a.c_str());
            if (!bound.insert(b).second) Usage("binding " + std::to_string(b) + " given twice");
            BufferArg buf;
            buf.binding = b;
            buf.uniform = a == "--uniform";
            if (a == "--zeros") {
                buf.zeroBytes = ParseUnsigned(rest, "--zeros size");
                if (buf.zeroBytes == 0 || buf.zeroBytes % 4 != 0) Usage("--zeros size must be a positive multiple of 4");
            } else {
                buf.file = rest;
            }
            o.buffers.push_back(buf);
        } else if (a == "--out") {
            auto [b, file] = BindingPair(value(), "--out");
            o.outputs.push_back({b, file});
        } else if (a == "--timestamps") o.timestamps = true;
        else if (a == "--list-devices") o.listDevices = true;
        else Usage("unknown argument '" + a + "'");
    }
    if (o.listDevices) return o;
    if (o.spv.empty()) Usage("--spv is required");
    for (const OutputArg& out : o.outputs) {
        bool found = false;
        for (const BufferArg& b : o.buffers) found |= b.binding == out.binding && !b.uniform;
        if (!found) Usage("--out binding " + std::to_string(out.binding) + " is not a storage buffer given with --buffer or --zeros");
    }
    return o;
}
