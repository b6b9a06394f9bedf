// submit.cpp — one-shot command buffer submission with a fence.
#include "gpu/submit.h"

#include "gpu/context.h"
#include "gpu/vk_check.h"

#include <cstdint>
#include <string>

namespace vkpt {

namespace {

// Frees the command buffer and fence on every path out of submitAndWait.
struct OneShot {
    const GpuContext& context;
    VkCommandBuffer commands = VK_NULL_HANDLE;
    VkFence fence = VK_NULL_HANDLE;

    ~OneShot() {
        if (fence != VK_NULL_HANDLE) vkDestroyFence(context.device(), fence, nullptr);
        if (commands != VK_NULL_HANDLE) {
            vkFreeCommandBuffers(context.device(), context.commandPool(), 1, &commands);
        }
    }
};

void allocate(OneShot& shot, std::string_view label) {
    VkCommandBufferAllocateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
    info.commandPool = shot.context.commandPool();
    info.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    info.commandBufferCount = 1;
    VKPT_VK_CHECK(vkAllocateCommandBuffers(shot.context.device(), &info, &shot.commands));
    shot.context.setDebugName(shot.commands, label);
    VkFenceCreateInfo fenceInfo{};
    fenceInfo.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
    VKPT_VK_CHECK(vkCreateFence(shot.context.device(), &fenceInfo, nullptr, &shot.fence));
    shot.context.setDebugName(shot.fence, std::string(label) + ".fence");
}

} // namespace

void submitAndWait(const GpuContext& context, std::string_view label,
                   const std::function<void(VkCommandBuffer)>& record) {
    OneShot shot{context};
    allocate(shot, label);
    VkCommandBufferBeginInfo begin{};
    begin.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    VKPT_VK_CHECK(vkBeginCommandBuffer(shot.commands, &begin));
    record(shot.commands);
    VKPT_VK_CHECK(vkEndCommandBuffer(shot.commands));

    VkSubmitInfo submit{};
    submit.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &shot.commands;
    VKPT_VK_CHECK(vkQueueSubmit(context.queue(), 1, &submit, shot.fence));
    VKPT_VK_CHECK(vkWaitForFences(context.device(), 1, &shot.fence, VK_TRUE, UINT64_MAX));
}

} // namespace vkpt
