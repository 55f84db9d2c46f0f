// Errors: every failure ends the run with one clear line and a non-zero exit code.
#pragma once
#include <stdexcept>
#include <string>
#include <vulkan/vulkan.h>

namespace gt {

// Thrown for anything a rig tool cannot go on with; its main() prints it and exits 1.
struct Error : std::runtime_error {
    using std::runtime_error::runtime_error;
};

[[noreturn]] void fail(const std::string& message);

// The enum name of a VkResult ("VK_ERROR_DEVICE_LOST"), or its number when unknown.
std::string resultName(VkResult result);

// Throws gt::Error naming the call when result is not VK_SUCCESS.
void checkVk(VkResult result, const char* call);

}  // namespace gt

#define GT_VK(call) ::gt::checkVk((call), #call)
