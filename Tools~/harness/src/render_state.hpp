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
#pragma once
#include <cstdint>
#include <string>
#include <vulkan/vulkan.h>

namespace gt {

enum class CullMode { Off, Front, Back };
enum class ZTest { Never, Less, Equal, LEqual, Greater, NotEqual, GEqual, Always };
enum class DepthConvention { Reversed, Forward };

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
// Vulkan's depthBiasConstantFactor / depthBiasSlopeFactor for the state (its convention's sign).
float vulkanDepthBias(float unityBias, DepthConvention depth);

VkCullModeFlags vulkanCullMode(CullMode cull);
// ZTest in the run's depth convention (reversed: Less <-> Greater, LEqual <-> GEqual).
VkCompareOp vulkanCompareOp(ZTest test, DepthConvention depth);
float depthClearValue(DepthConvention depth);

// "state cull back front_face clockwise ztest lequal compare greater_or_equal zwrite on zclip on
// color_mask rgba depth reversed": the state the run draws with, one line.
std::string describeRenderState(const RenderState& s);

}  // namespace gt
