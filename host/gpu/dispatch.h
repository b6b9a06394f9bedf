// dispatch.h — recording a kernel's dispatch: pipeline, descriptor set, push constants, the
// workgroup count (direct, or read from a buffer), all inside a debug label named after it.
#pragma once

#include <volk.h>

#include <cstddef>
#include <cstdint>
#include <span>

namespace vkpt {

class Buffer;
class DescriptorSet;
class Kernel;

struct WorkgroupCount {
    std::uint32_t x = 1;
    std::uint32_t y = 1;
    std::uint32_t z = 1;
};

// Enough workgroups of `workgroupSize` for `invocations` threads (kernels bounds-check).
constexpr std::uint32_t workgroupsFor(std::uint32_t invocations, std::uint32_t workgroupSize) {
    return invocations / workgroupSize + (invocations % workgroupSize != 0 ? 1u : 0u);
}

// Push constants as bytes: recordDispatch(..., pushConstantBytes(params)).
template <typename T> std::span<const std::byte> pushConstantBytes(const T& value) {
    return std::as_bytes(std::span<const T, 1>(&value, 1));
}

// `pushConstants` must be exactly the kernel's push-constant size. Throws VulkanError when a
// count exceeds the device's maxComputeWorkGroupCount.
void recordDispatch(VkCommandBuffer commands, const Kernel& kernel, const DescriptorSet& set,
                    WorkgroupCount groups, std::span<const std::byte> pushConstants = {});

// The workgroup count is the VkDispatchIndirectCommand (three uints) at `offset` in `arguments`,
// which needs VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT; a previous stage usually wrote it.
void recordDispatchIndirect(VkCommandBuffer commands, const Kernel& kernel,
                            const DescriptorSet& set, const Buffer& arguments, VkDeviceSize offset,
                            std::span<const std::byte> pushConstants = {});

} // namespace vkpt
