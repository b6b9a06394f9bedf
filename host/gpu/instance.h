// instance.h — the Vulkan loader and instance (API 1.2), with validation and debug utils when
// asked for and available.
#pragma once

#include "gpu/validation.h"

#include <volk.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

namespace vkpt {

class Instance {
public:
    // Loads Vulkan through volk and creates a 1.2 instance. With `validation`, enables
    // VK_LAYER_KHRONOS_validation (core and synchronization checks) and a messenger that counts
    // messages; throws VulkanError when the loader or the layer is missing.
    explicit Instance(bool validation);
    ~Instance();
    Instance(const Instance&) = delete;
    Instance& operator=(const Instance&) = delete;

    VkInstance handle() const { return instance_; }
    bool validationEnabled() const { return validationLog_ != nullptr; }
    // VK_EXT_debug_utils: object names and command labels (no-ops without it).
    bool debugUtilsEnabled() const { return debugUtils_; }
    // Null without validation.
    std::shared_ptr<const ValidationLog> validationLog() const { return validationLog_; }
    std::size_t validationMessageCount() const {
        return validationLog_ ? validationLog_->messageCount() : 0;
    }

private:
    void createInstance();
    void createMessenger();

    VkInstance instance_ = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
    std::shared_ptr<ValidationLog> validationLog_;
    bool debugUtils_ = false;
};

// "1.3.230" for a packed Vulkan version.
std::string formatVulkanVersion(std::uint32_t version);

} // namespace vkpt
