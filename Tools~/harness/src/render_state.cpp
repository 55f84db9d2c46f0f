#include "render_state.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <utility>
#include <vector>

#include "check.hpp"

namespace gt {

namespace {

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

// The value among `names` (compared without case), else an error listing them.
template <typename T>
T pick(const std::string& option, const std::string& value, const std::vector<std::pair<const char*, T>>& names) {
    const std::string v = lower(value);
    std::string accepted;
    for (const auto& n : names) {
        if (v == n.first) return n.second;
        accepted += (accepted.empty() ? "" : ", ") + std::string(n.first);
    }
    fail(option + ": expected one of " + accepted + " (ShaderLab's words, any case), got '" + value + "'");
}

const std::vector<std::pair<const char*, ZTest>> kZTests = {
    {"never", ZTest::Never},     {"less", ZTest::Less},         {"equal", ZTest::Equal},   {"lequal", ZTest::LEqual},
    {"greater", ZTest::Greater}, {"notequal", ZTest::NotEqual}, {"gequal", ZTest::GEqual}, {"always", ZTest::Always},
};

const std::vector<std::pair<const char*, StencilOp>> kStencilOps = {
    {"keep", StencilOp::Keep},       {"zero", StencilOp::Zero},         {"replace", StencilOp::Replace},
    {"incrsat", StencilOp::IncrSat}, {"decrsat", StencilOp::DecrSat},   {"invert", StencilOp::Invert},
    {"incrwrap", StencilOp::IncrWrap}, {"decrwrap", StencilOp::DecrWrap},
};

uint32_t parseByte(const std::string& option, const std::string& command, const std::string& value) {
    char* end = nullptr;
    const long v = std::strtol(value.c_str(), &end, 10);
    if (value.empty() || end != value.c_str() + value.size() || v < 0 || v > 255)
        fail(option + ": " + command + " expects a whole number 0..255, got '" + value + "'");
    return static_cast<uint32_t>(v);
}

// Sets one face's Comp/Pass/Fail/ZFail from its command's stem ("comp", "pass", "fail", "zfail").
void setFace(const std::string& option, const std::string& command, const std::string& stem, const std::string& value,
             StencilFace& face) {
    const std::string what = option + " " + command;
    if (stem == "comp") face.comp = pick<ZTest>(what, value, kZTests);
    else if (stem == "pass") face.pass = pick<StencilOp>(what, value, kStencilOps);
    else if (stem == "fail") face.fail = pick<StencilOp>(what, value, kStencilOps);
    else face.zFail = pick<StencilOp>(what, value, kStencilOps);
}

VkStencilOp vulkanStencilOp(StencilOp op) {
    static const VkStencilOp ops[] = {VK_STENCIL_OP_KEEP, VK_STENCIL_OP_ZERO, VK_STENCIL_OP_REPLACE,
                                      VK_STENCIL_OP_INCREMENT_AND_CLAMP, VK_STENCIL_OP_DECREMENT_AND_CLAMP,
                                      VK_STENCIL_OP_INVERT, VK_STENCIL_OP_INCREMENT_AND_WRAP, VK_STENCIL_OP_DECREMENT_AND_WRAP};
    return ops[static_cast<int>(op)];
}

}  // namespace

CullMode parseCull(const std::string& option, const std::string& value) {
    return pick<CullMode>(option, value, {{"back", CullMode::Back}, {"front", CullMode::Front}, {"off", CullMode::Off}});
}

ZTest parseZTest(const std::string& option, const std::string& value) { return pick<ZTest>(option, value, kZTests); }

// ShaderLab writes ZWrite On/Off and ZClip True/False; both spellings are taken for either.
bool parseOnOff(const std::string& option, const std::string& value) {
    return pick<bool>(option, value, {{"on", true}, {"off", false}, {"true", true}, {"false", false}});
}

// ShaderLab's ColorMask: 0, or any of R, G, B, A, each at most once, in that order.
uint32_t parseColorMask(const std::string& option, const std::string& value) {
    if (value == "0") return 0;
    const std::string order = "rgba";
    const std::string v = lower(value);
    uint32_t mask = 0;
    size_t next = 0;
    for (char c : v) {
        const size_t at = order.find(c, next);
        if (at == std::string::npos)
            fail(option + ": expected 0 or channels from R, G, B, A in that order (e.g. RGBA, RGB, R), got '" + value + "'");
        mask |= 1u << at;   // VK_COLOR_COMPONENT_R_BIT = 1, G = 2, B = 4, A = 8
        next = at + 1;
    }
    if (mask == 0) fail(option + ": expected 0 or channels from R, G, B, A in that order (e.g. RGBA, RGB, R), got '" + value + "'");
    return mask;
}

DepthConvention parseDepth(const std::string& option, const std::string& value) {
    return pick<DepthConvention>(option, value, {{"reversed", DepthConvention::Reversed}, {"forward", DepthConvention::Forward}});
}

VkCullModeFlags vulkanCullMode(CullMode cull) {
    switch (cull) {
        case CullMode::Off: return VK_CULL_MODE_NONE;
        case CullMode::Front: return VK_CULL_MODE_FRONT_BIT;
        case CullMode::Back: break;
    }
    return VK_CULL_MODE_BACK_BIT;
}

VkCompareOp vulkanCompareOp(ZTest test, DepthConvention depth) {
    const bool reversed = depth == DepthConvention::Reversed;
    switch (test) {
        case ZTest::Never: return VK_COMPARE_OP_NEVER;
        case ZTest::Less: return reversed ? VK_COMPARE_OP_GREATER : VK_COMPARE_OP_LESS;
        case ZTest::Equal: return VK_COMPARE_OP_EQUAL;
        case ZTest::LEqual: return reversed ? VK_COMPARE_OP_GREATER_OR_EQUAL : VK_COMPARE_OP_LESS_OR_EQUAL;
        case ZTest::Greater: return reversed ? VK_COMPARE_OP_LESS : VK_COMPARE_OP_GREATER;
        case ZTest::NotEqual: return VK_COMPARE_OP_NOT_EQUAL;
        case ZTest::GEqual: return reversed ? VK_COMPARE_OP_LESS_OR_EQUAL : VK_COMPARE_OP_GREATER_OR_EQUAL;
        case ZTest::Always: break;
    }
    return VK_COMPARE_OP_ALWAYS;
}

float depthClearValue(DepthConvention depth) { return depth == DepthConvention::Reversed ? 0.0f : 1.0f; }

void parseDepthBias(const std::string& option, const std::string& value, RenderState& state) {
    const size_t comma = value.find(',');
    float v[2] = {0.0f, 0.0f};
    bool ok = comma != std::string::npos;
    for (int i = 0; i < 2 && ok; ++i) {
        const std::string part = i == 0 ? value.substr(0, comma) : value.substr(comma + 1);
        char* end = nullptr;
        v[i] = std::strtof(part.c_str(), &end);
        ok = !part.empty() && end == part.c_str() + part.size() && std::isfinite(v[i]) && std::fabs(v[i]) <= 1000.0f;
    }
    if (!ok) fail(option + ": expected UNITS,SLOPE (finite, each within -1000..1000), got '" + value + "'");
    state.depthBiasUnits = v[0];
    state.depthBiasSlope = v[1];
}

StencilState parseStencil(const std::string& option, const std::string& value) {
    std::istringstream in(value);
    std::vector<std::string> words;
    for (std::string w; in >> w;) words.push_back(w);
    if (words.empty() || words.size() % 2 != 0)
        fail(option + ": expected a Stencil block's commands as pairs, e.g. 'Ref 1 WriteMask 9 Comp Always Pass Replace', got '" +
             value + "'");
    StencilState s;
    s.enabled = true;
    std::vector<std::string> seen;
    // Two rounds: the two-face commands, then the one-face ones, which win whatever the order.
    for (int round = 0; round < 2; ++round)
        for (size_t i = 0; i < words.size(); i += 2) {
            const std::string command = words[i], key = lower(command), v = words[i + 1];
            std::string stem = key, face;
            for (const char* f : {"front", "back"})
                if (key.size() > std::strlen(f) && key.compare(key.size() - std::strlen(f), std::string::npos, f) == 0) {
                    stem = key.substr(0, key.size() - std::strlen(f));
                    face = f;
                }
            const bool faced = stem == "comp" || stem == "pass" || stem == "fail" || stem == "zfail";
            const bool whole = key == "ref" || key == "readmask" || key == "writemask";
            if (!faced && !whole)
                fail(option + ": '" + command + "' is not a Stencil command (Ref, ReadMask, WriteMask, Comp, Pass, Fail, ZFail, "
                     "or Comp/Pass/Fail/ZFail with Front or Back)");
            if (round == 0) {
                if (std::find(seen.begin(), seen.end(), key) != seen.end()) fail(option + ": " + command + " is given twice");
                seen.push_back(key);
            }
            if (whole && round == 0) {
                uint32_t& field = key == "ref" ? s.ref : key == "readmask" ? s.readMask : s.writeMask;
                field = parseByte(option, command, v);
            } else if (faced && face.empty() && round == 0) {
                setFace(option, command, stem, v, s.front);
                setFace(option, command, stem, v, s.back);
            } else if (faced && !face.empty() && round == 1) {
                setFace(option, command, stem, v, face == "front" ? s.front : s.back);
            }
        }
    return s;
}

VkStencilOpState vulkanStencil(const StencilState& s, const StencilFace& face) {
    VkStencilOpState v{};
    v.failOp = vulkanStencilOp(face.fail);
    v.passOp = vulkanStencilOp(face.pass);
    v.depthFailOp = vulkanStencilOp(face.zFail);
    v.compareOp = vulkanCompareOp(face.comp, DepthConvention::Forward);   // (Ref & ReadMask) comp (stored & ReadMask), as D3D
    v.compareMask = s.readMask;
    v.writeMask = s.writeMask;
    v.reference = s.ref;
    return v;
}

float vulkanDepthBias(float unityBias, DepthConvention depth) {
    return depth == DepthConvention::Reversed ? -unityBias : unityBias;
}

std::string describeRenderState(const RenderState& s) {
    static const char* culls[] = {"off", "front", "back"};
    static const char* compares[] = {"never", "less", "equal", "less_or_equal", "greater", "not_equal", "greater_or_equal", "always"};
    std::string mask;
    for (int i = 0; i < 4; ++i)
        if (s.colorMask & (1u << i)) mask += "rgba"[i];
    std::string line = "state cull ";
    line += culls[static_cast<int>(s.cull)];
    line += " front_face clockwise ztest ";
    line += kZTests[static_cast<int>(s.zTest)].first;
    line += " compare ";
    line += compares[vulkanCompareOp(s.zTest, s.depth)];
    line += std::string(" zwrite ") + (s.zWrite ? "on" : "off");
    line += std::string(" zclip ") + (s.zClip ? "on" : "off");
    line += " color_mask " + (mask.empty() ? std::string("0") : mask);
    line += std::string(" depth ") + (s.depth == DepthConvention::Reversed ? "reversed" : "forward");
    if (s.depthBiasUnits != 0.0f || s.depthBiasSlope != 0.0f)
        line += " depth_bias " + std::to_string(s.depthBiasUnits) + " " + std::to_string(s.depthBiasSlope);
    if (s.stencil.enabled) {
        line += " stencil ref " + std::to_string(s.stencil.ref) + " read " + std::to_string(s.stencil.readMask) + " write " +
                std::to_string(s.stencil.writeMask);
        for (const StencilFace* f : {&s.stencil.front, &s.stencil.back}) {
            line += f == &s.stencil.front ? " front " : " back ";
            line += kZTests[static_cast<int>(f->comp)].first;
            for (StencilOp op : {f->pass, f->fail, f->zFail}) line += std::string(" ") + kStencilOps[static_cast<int>(op)].first;
        }
    }
    return line;
}

}  // namespace gt
