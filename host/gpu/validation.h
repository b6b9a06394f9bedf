// validation.h — the Khronos validation layer's voice: every warning or error is printed as one
// line on stderr and counted, so that tests can fail on any.
#pragma once

#include <volk.h>

#include <atomic>
#include <cstddef>

namespace vkpt {

inline constexpr const char* kValidationLayerName = "VK_LAYER_KHRONOS_validation";

// True when the environment variable VKPT_VALIDATION is set to anything but "" or "0".
bool validationRequestedByEnvironment();

// Receives VK_EXT_debug_utils messages. Vulkan keeps a pointer to it (pUserData), so it lives
// on the heap, owned by Instance through a shared_ptr that tests may keep past the device's
// destruction (the layer reports leaked objects when the device is destroyed).
class ValidationLog {
public:
    // Warnings and errors seen so far (info and verbose messages are not counted or printed).
    std::size_t messageCount() const { return count_.load(); }

    // Chained into VkInstanceCreateInfo as well, so instance creation is covered too.
    VkDebugUtilsMessengerCreateInfoEXT messengerCreateInfo();

private:
    static VKAPI_ATTR VkBool32 VKAPI_CALL
    onMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity, VkDebugUtilsMessageTypeFlagsEXT type,
              const VkDebugUtilsMessengerCallbackDataEXT* data, void* userData);

    std::atomic<std::size_t> count_{0};
};

} // namespace vkpt
