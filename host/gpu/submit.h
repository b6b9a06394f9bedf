// submit.h — one-shot command buffers: record, submit to the compute queue, wait on a fence.
// Uploads, downloads and tests use it; the renderer will keep its own per-frame buffers.
#pragma once

#include <volk.h>

#include <functional>
#include <string_view>

namespace vkpt {

class GpuContext;

// Records `record` into a fresh primary command buffer named `label`, submits it and blocks
// until the device has finished it. Throws VulkanError on failure (e.g. VK_ERROR_DEVICE_LOST).
void submitAndWait(const GpuContext& context, std::string_view label,
                   const std::function<void(VkCommandBuffer)>& record);

} // namespace vkpt
