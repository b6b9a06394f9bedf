// vk_check.h — VulkanError and VKPT_VK_CHECK: every failed Vulkan call becomes one clear line.
#pragma once

#include <volk.h>

#include <stdexcept>
#include <string>

#include "common/errors.h"

namespace vkpt {

// A Vulkan call failed or no usable device exists. main() prints the message and exits with 2.
class VulkanError : public DeviceError {
public:
    explicit VulkanError(const std::string& message, VkResult result = VK_ERROR_UNKNOWN)
        : DeviceError(message), result_(result) {}
    VkResult result() const { return result_; }

private:
    VkResult result_;
};

// "VK_ERROR_DEVICE_LOST" for VK_ERROR_DEVICE_LOST; "VkResult(<n>)" for codes it does not know.
std::string vkResultName(VkResult result);

// Throws VulkanError("<expression> failed: <result name> (<file>:<line>)").
[[noreturn]] void throwVulkanError(VkResult result, const char* expression, const char* file,
                                   int line);

} // namespace vkpt

// Anything but VK_SUCCESS throws, including the positive codes (VK_TIMEOUT, VK_INCOMPLETE,
// VK_NOT_READY): vkpt waits without timeouts and sizes its queries, so those mean a bug here.
#define VKPT_VK_CHECK(expr)                                                                        \
    do {                                                                                           \
        const VkResult vkptResult_ = (expr);                                                       \
        if (vkptResult_ != VK_SUCCESS)                                                             \
            ::vkpt::throwVulkanError(vkptResult_, #expr, __FILE__, __LINE__);                      \
    } while (false)
