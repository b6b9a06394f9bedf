// debug_utils.h — Vulkan object names and command-buffer labels (VK_EXT_debug_utils), so that
// captures and validation messages read like the pipeline: "bvhNodes", "trace_closest".
#pragma once

#include <volk.h>

#include <cstdint>
#include <string_view>

namespace vkpt {

// The VkObjectType of each handle vkpt names. Non-dispatchable handles are distinct pointer
// types on 64-bit platforms, the only ones vkpt targets, so overloading tells them apart.
constexpr VkObjectType objectTypeOf(VkBuffer) {
    return VK_OBJECT_TYPE_BUFFER;
}
constexpr VkObjectType objectTypeOf(VkBufferView) {
    return VK_OBJECT_TYPE_BUFFER_VIEW;
}
constexpr VkObjectType objectTypeOf(VkDeviceMemory) {
    return VK_OBJECT_TYPE_DEVICE_MEMORY;
}
constexpr VkObjectType objectTypeOf(VkPipeline) {
    return VK_OBJECT_TYPE_PIPELINE;
}
constexpr VkObjectType objectTypeOf(VkPipelineLayout) {
    return VK_OBJECT_TYPE_PIPELINE_LAYOUT;
}
constexpr VkObjectType objectTypeOf(VkShaderModule) {
    return VK_OBJECT_TYPE_SHADER_MODULE;
}
constexpr VkObjectType objectTypeOf(VkDescriptorSetLayout) {
    return VK_OBJECT_TYPE_DESCRIPTOR_SET_LAYOUT;
}
constexpr VkObjectType objectTypeOf(VkDescriptorPool) {
    return VK_OBJECT_TYPE_DESCRIPTOR_POOL;
}
constexpr VkObjectType objectTypeOf(VkDescriptorSet) {
    return VK_OBJECT_TYPE_DESCRIPTOR_SET;
}
constexpr VkObjectType objectTypeOf(VkCommandPool) {
    return VK_OBJECT_TYPE_COMMAND_POOL;
}
constexpr VkObjectType objectTypeOf(VkCommandBuffer) {
    return VK_OBJECT_TYPE_COMMAND_BUFFER;
}
constexpr VkObjectType objectTypeOf(VkQueryPool) {
    return VK_OBJECT_TYPE_QUERY_POOL;
}
constexpr VkObjectType objectTypeOf(VkFence) {
    return VK_OBJECT_TYPE_FENCE;
}
constexpr VkObjectType objectTypeOf(VkQueue) {
    return VK_OBJECT_TYPE_QUEUE;
}
constexpr VkObjectType objectTypeOf(VkDevice) {
    return VK_OBJECT_TYPE_DEVICE;
}

// Names one object; does nothing when `enabled` is false (VK_EXT_debug_utils unavailable).
void setObjectName(bool enabled, VkDevice device, VkObjectType type, std::uint64_t handle,
                   std::string_view name);

// Brackets the commands recorded during its lifetime with a label (e.g. the kernel's name).
class ScopedDebugLabel {
public:
    ScopedDebugLabel(bool enabled, VkCommandBuffer commands, std::string_view label);
    ~ScopedDebugLabel();
    ScopedDebugLabel(const ScopedDebugLabel&) = delete;
    ScopedDebugLabel& operator=(const ScopedDebugLabel&) = delete;

private:
    VkCommandBuffer commands_ = VK_NULL_HANDLE; // null when labels are off
};

} // namespace vkpt
