// debug_utils.cpp — object names and command labels through VK_EXT_debug_utils.
#include "gpu/debug_utils.h"

#include "gpu/vk_check.h"

#include <string>

namespace vkpt {

void setObjectName(bool enabled, VkDevice device, VkObjectType type, std::uint64_t handle,
                   std::string_view name) {
    if (!enabled || handle == 0) return;
    const std::string terminated(name);
    VkDebugUtilsObjectNameInfoEXT info{};
    info.sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT;
    info.objectType = type;
    info.objectHandle = handle;
    info.pObjectName = terminated.c_str();
    VKPT_VK_CHECK(vkSetDebugUtilsObjectNameEXT(device, &info));
}

ScopedDebugLabel::ScopedDebugLabel(bool enabled, VkCommandBuffer commands, std::string_view label) {
    if (!enabled) return;
    const std::string terminated(label);
    VkDebugUtilsLabelEXT info{};
    info.sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_LABEL_EXT;
    info.pLabelName = terminated.c_str();
    vkCmdBeginDebugUtilsLabelEXT(commands, &info);
    commands_ = commands;
}

ScopedDebugLabel::~ScopedDebugLabel() {
    if (commands_ != VK_NULL_HANDLE) vkCmdEndDebugUtilsLabelEXT(commands_);
}

} // namespace vkpt
