// The drawn pass's fixed-function state in ShaderLab's terms (Cull, ZTest, ZWrite, ZClip,
// ColorMask) and the depth convention, turned into Vulkan's as Unity does it on Vulkan.
//
// Front faces: Unity's are clockwise as the camera sees them in the final, upright image. Vulkan
// decides facing from the signed area in framebuffer coordinates (y down), after the viewport;
// the harness's viewport has a negative height (clip +y at row 0) and its PNG stores row 0 at the
// top, so the image is upright and "clockwise on screen" is VK_FRONT_FACE_CLOCKWISE.
//
// Depth: Unity on Vulkan (and D3D11/12, Metal) uses reversed depth, UNITY_REVERSED_Z: near = 1,
// far = 0, the buffer cleared to 0, and every ZTest turned around (LEqual is GreaterEqual). The
// options name ZTest as ShaderLab does; the convention turns it around.
//
// Stencil: ShaderLab's Stencil block; its Comp is never turned around (stencil values are not depth).
// Front and back are ShaderLab's faces, the same as the rasterizer's here (front faces clockwise).
#pragma once
#include <cstdint>
#include <string>
#include <vulkan/vulkan.h>

namespace gt {

enum class CullMode { Off, Front, Back };
enum class ZTest { Never, Less, Equal, LEqual, Greater, NotEqual, GEqual, Always };
enum class DepthConvention { Reversed, Forward };
enum class StencilOp { Keep, Zero, Replace, IncrSat, DecrSat, Invert, IncrWrap, DecrWrap };

struct StencilFace {
    ZTest comp = ZTest::Always;   // ShaderLab's Comp words, as ZTest's
    StencilOp pass = StencilOp::Keep, fail = StencilOp::Keep, zFail = StencilOp::Keep;
};

// ShaderLab's defaults for what a Stencil block leaves out: Ref 0, ReadMask 255, WriteMask 255,
// Comp Always, Pass/Fail/ZFail Keep. Off (no block): the stencil test is off, as in Unity.
struct StencilState {
    bool enabled = false;
    uint32_t ref = 0, readMask = 255, writeMask = 255;
    StencilFace front, back;
};

// Defaults: what a ShaderLab pass gets when it names none of these (Cull Back, ZTest LEqual,
// ZWrite On, ZClip True, ColorMask RGBA), with Unity's reversed depth.
struct RenderState {
    CullMode cull = CullMode::Back;
    ZTest zTest = ZTest::LEqual;
    bool zWrite = true;
    bool zClip = true;       // false: depth clamp instead of clipping at near/far (ZClip False)
    uint32_t colorMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
    DepthConvention depth = DepthConvention::Reversed;
    // Unity's depth bias (CommandBuffer.SetGlobalDepthBias(bias, slopeBias), ShaderLab's Offset slope, units):
    // positive moves depth away from the viewer, so it is negated under reversed depth, as Unity does.
    float depthBiasUnits = 0.0f, depthBiasSlope = 0.0f;
    StencilState stencil;
};

// Each parses one option's value (ShaderLab's words, any case); a bad value throws gt::Error
// naming the option, the value and the accepted ones.
CullMode parseCull(const std::string& option, const std::string& value);
ZTest parseZTest(const std::string& option, const std::string& value);
bool parseOnOff(const std::string& option, const std::string& value);
uint32_t parseColorMask(const std::string& option, const std::string& value);
DepthConvention parseDepth(const std::string& option, const std::string& value);
// "UNITS,SLOPE", each finite, |x| <= 1000, into state.depthBiasUnits / depthBiasSlope.
void parseDepthBias(const std::string& option, const std::string& value, RenderState& state);
// The body of a ShaderLab Stencil block, e.g. "Ref 1 WriteMask 9 Comp Always Pass Replace": Ref,
// ReadMask, WriteMask (0..255), Comp, Pass, Fail, ZFail for both faces, CompFront ... ZFailBack for one
// (they win over the two-face ones, in any order). Each command at most once; enables the stencil.
StencilState parseStencil(const std::string& option, const std::string& value);
VkStencilOpState vulkanStencil(const StencilState& s, const StencilFace& face);
// Vulkan's depthBiasConstantFactor / depthBiasSlopeFactor for the state (its convention's sign).
float vulkanDepthBias(float unityBias, DepthConvention depth);

VkCullModeFlags vulkanCullMode(CullMode cull);
// ZTest in the run's depth convention (reversed: Less <-> Greater, LEqual <-> GEqual).
VkCompareOp vulkanCompareOp(ZTest test, DepthConvention depth);
float depthClearValue(DepthConvention depth);

// "state cull back front_face clockwise ztest lequal compare greater_or_equal zwrite on zclip on
// color_mask rgba depth reversed", then " stencil ref 1 read 255 write 9 front always replace keep keep
// back ..." when the stencil is on: the state the run draws with, one line.
std::string describeRenderState(const RenderState& s);

}  // namespace gt
