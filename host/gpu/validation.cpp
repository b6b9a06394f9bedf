// validation.cpp — prints and counts the validation layer's warnings and errors.
#include "gpu/validation.h"

#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

namespace vkpt {

bool validationRequestedByEnvironment() {
    const char* value = std::getenv("VKPT_VALIDATION");
    return value != nullptr && std::string_view(value) != "" && std::string_view(value) != "0";
}

VkDebugUtilsMessengerCreateInfoEXT ValidationLog::messengerCreateInfo() {
    VkDebugUtilsMessengerCreateInfoEXT info{};
    info.sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT;
    info.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                           VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                       VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                       VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    info.pfnUserCallback = &ValidationLog::onMessage;
    info.pUserData = this;
    return info;
}

namespace {

// Layer messages sometimes span lines; one line per message keeps logs greppable.
std::string oneLine(const char* text) {
    std::string line = text != nullptr ? text : "";
    for (char& c : line) {
        if (c == '\n' || c == '\r') c = ' ';
    }
    return line;
}

} // namespace

VkBool32 ValidationLog::onMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                  VkDebugUtilsMessageTypeFlagsEXT /*type*/,
                                  const VkDebugUtilsMessengerCallbackDataEXT* data,
                                  void* userData) {
    static_cast<ValidationLog*>(userData)->count_.fetch_add(1);
    const bool error = (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) != 0;
    std::fprintf(stderr, "vkpt: validation %s: %s\n", error ? "error" : "warning",
                 oneLine(data->pMessage).c_str());
    // VK_FALSE: the call goes on, as the layer's specification asks of application callbacks.
    return VK_FALSE;
}

} // namespace vkpt
