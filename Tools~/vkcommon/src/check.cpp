#include "check.hpp"

namespace gt {

void fail(const std::string& message) { throw Error(message); }

std::string resultName(VkResult result) {
    switch (result) {
#define GT_CASE(x) case x: return #x;
        GT_CASE(VK_SUCCESS)
        GT_CASE(VK_NOT_READY)
        GT_CASE(VK_TIMEOUT)
        GT_CASE(VK_INCOMPLETE)
        GT_CASE(VK_ERROR_OUT_OF_HOST_MEMORY)
        GT_CASE(VK_ERROR_OUT_OF_DEVICE_MEMORY)
        GT_CASE(VK_ERROR_INITIALIZATION_FAILED)
        GT_CASE(VK_ERROR_DEVICE_LOST)
        GT_CASE(VK_ERROR_MEMORY_MAP_FAILED)
        GT_CASE(VK_ERROR_LAYER_NOT_PRESENT)
        GT_CASE(VK_ERROR_EXTENSION_NOT_PRESENT)
        GT_CASE(VK_ERROR_FEATURE_NOT_PRESENT)
        GT_CASE(VK_ERROR_INCOMPATIBLE_DRIVER)
        GT_CASE(VK_ERROR_TOO_MANY_OBJECTS)
        GT_CASE(VK_ERROR_FORMAT_NOT_SUPPORTED)
        GT_CASE(VK_ERROR_FRAGMENTED_POOL)
        GT_CASE(VK_ERROR_OUT_OF_POOL_MEMORY)
        GT_CASE(VK_ERROR_INVALID_SHADER_NV)
#undef GT_CASE
        default: return "VkResult(" + std::to_string(static_cast<int>(result)) + ")";
    }
}

void checkVk(VkResult result, const char* call) {
    if (result != VK_SUCCESS) fail(std::string("Vulkan call failed: ") + call + " returned " + resultName(result));
}

}  // namespace gt
