// dispatch.cpp — labelled direct and indirect dispatches.
#include "gpu/dispatch.h"

#include "common/errors.h"
#include "gpu/buffer.h"
#include "gpu/context.h"
#include "gpu/debug_utils.h"
#include "gpu/descriptor_set.h"
#include "gpu/kernel.h"
#include "gpu/vk_check.h"

#include <string>

namespace vkpt {

namespace {

void bindKernel(VkCommandBuffer commands, const Kernel& kernel, const DescriptorSet& set,
                std::span<const std::byte> pushConstants) {
    VKPT_ASSERT(pushConstants.size() == kernel.pushConstantSize(),
                "kernel '" + kernel.name() + "' takes " +
                    std::to_string(kernel.pushConstantSize()) + " bytes of push constants, " +
                    std::to_string(pushConstants.size()) + " given");
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_COMPUTE, kernel.pipeline());
    const VkDescriptorSet handle = set.handle();
    vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_COMPUTE, kernel.pipelineLayout(), 0, 1,
                            &handle, 0, nullptr);
    if (!pushConstants.empty()) {
        vkCmdPushConstants(commands, kernel.pipelineLayout(), VK_SHADER_STAGE_COMPUTE_BIT, 0,
                           static_cast<std::uint32_t>(pushConstants.size()), pushConstants.data());
    }
}

void checkWorkgroupCount(const Kernel& kernel, WorkgroupCount groups) {
    const std::uint32_t counts[] = {groups.x, groups.y, groups.z};
    const auto& limits = kernel.context().limits().maxComputeWorkGroupCount;
    for (std::size_t axis = 0; axis < 3; ++axis) {
        if (counts[axis] > limits[axis]) {
            throw VulkanError("dispatch of '" + kernel.name() +
                                  "': " + std::to_string(counts[axis]) + " workgroups along axis " +
                                  std::to_string(axis) +
                                  ", above this device's maxComputeWorkGroupCount of " +
                                  std::to_string(limits[axis]),
                              VK_ERROR_FEATURE_NOT_PRESENT);
        }
    }
}

} // namespace

void recordDispatch(VkCommandBuffer commands, const Kernel& kernel, const DescriptorSet& set,
                    WorkgroupCount groups, std::span<const std::byte> pushConstants) {
    checkWorkgroupCount(kernel, groups);
    const ScopedDebugLabel label(kernel.context().debugUtilsEnabled(), commands, kernel.name());
    bindKernel(commands, kernel, set, pushConstants);
    vkCmdDispatch(commands, groups.x, groups.y, groups.z);
}

void recordDispatchIndirect(VkCommandBuffer commands, const Kernel& kernel,
                            const DescriptorSet& set, const Buffer& arguments, VkDeviceSize offset,
                            std::span<const std::byte> pushConstants) {
    VKPT_ASSERT((arguments.usage() & VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT) != 0,
                "buffer '" + arguments.name() + "' lacks INDIRECT_BUFFER usage");
    VKPT_ASSERT(offset % 4 == 0 && offset + sizeof(VkDispatchIndirectCommand) <= arguments.size(),
                "indirect arguments outside buffer '" + arguments.name() + "'");
    const ScopedDebugLabel label(kernel.context().debugUtilsEnabled(), commands, kernel.name());
    bindKernel(commands, kernel, set, pushConstants);
    vkCmdDispatchIndirect(commands, arguments.handle(), offset);
}

} // namespace vkpt
