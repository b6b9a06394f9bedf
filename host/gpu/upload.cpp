// upload.cpp — staging copies in one-shot submissions, each ended by the barrier that makes
// the data visible where it goes next.
#include "gpu/upload.h"

#include "common/errors.h"
#include "gpu/barriers.h"
#include "gpu/context.h"
#include "gpu/submit.h"

#include <cstring>

namespace vkpt {

namespace {

void checkRange(const Buffer& buffer, std::size_t bytes, VkDeviceSize offset) {
    VKPT_ASSERT(offset <= buffer.size() && bytes <= buffer.size() - offset,
                "range [" + std::to_string(offset) + ", +" + std::to_string(bytes) +
                    ") outside buffer '" + buffer.name() + "' of " + std::to_string(buffer.size()) +
                    " bytes");
}

void checkUsage(const Buffer& buffer, VkBufferUsageFlags usage, const char* usageName) {
    VKPT_ASSERT((buffer.usage() & usage) != 0,
                "buffer '" + buffer.name() + "' lacks " + usageName + " usage");
}

void copyBuffer(VkCommandBuffer commands, const Buffer& source, VkDeviceSize sourceOffset,
                const Buffer& destination, VkDeviceSize destinationOffset, VkDeviceSize size) {
    VkBufferCopy region{};
    region.srcOffset = sourceOffset;
    region.dstOffset = destinationOffset;
    region.size = size;
    vkCmdCopyBuffer(commands, source.handle(), destination.handle(), 1, &region);
}

} // namespace

void uploadBytes(GpuContext& context, const Buffer& destination, std::span<const std::byte> bytes,
                 VkDeviceSize offset) {
    checkRange(destination, bytes.size(), offset);
    if (bytes.empty()) return;
    // Host writes to mapped memory are visible to every later submission (vkQueueSubmit's
    // implicit host-write dependency), so a mapped destination needs no copy.
    if (destination.mapped() != nullptr) {
        std::memcpy(destination.mapped() + offset, bytes.data(), bytes.size());
        return;
    }
    checkUsage(destination, VK_BUFFER_USAGE_TRANSFER_DST_BIT, "TRANSFER_DST");
    const Buffer staging(context, {destination.name() + ".staging", bytes.size(),
                                   VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryLocation::Upload});
    std::memcpy(staging.mapped(), bytes.data(), bytes.size());
    submitAndWait(context, "upload " + destination.name(), [&](VkCommandBuffer commands) {
        copyBuffer(commands, staging, 0, destination, offset, bytes.size());
        recordTransferToComputeBarrier(commands);
    });
}

void downloadBytes(GpuContext& context, const Buffer& source, std::span<std::byte> bytes,
                   VkDeviceSize offset) {
    checkRange(source, bytes.size(), offset);
    if (bytes.empty()) return;
    if (source.mapped() != nullptr) {
        submitAndWait(context, "download " + source.name(), recordDeviceToHostBarrier);
        std::memcpy(bytes.data(), source.mapped() + offset, bytes.size());
        return;
    }
    checkUsage(source, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, "TRANSFER_SRC");
    const Buffer staging(context, {source.name() + ".readback", bytes.size(),
                                   VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryLocation::Readback});
    submitAndWait(context, "download " + source.name(), [&](VkCommandBuffer commands) {
        recordComputeToTransferBarrier(commands);
        copyBuffer(commands, source, offset, staging, 0, bytes.size());
        recordDeviceToHostBarrier(commands);
    });
    std::memcpy(bytes.data(), staging.mapped(), bytes.size());
}

void fillBuffer(GpuContext& context, const Buffer& buffer, std::uint32_t value) {
    checkUsage(buffer, VK_BUFFER_USAGE_TRANSFER_DST_BIT, "TRANSFER_DST");
    submitAndWait(context, "fill " + buffer.name(), [&](VkCommandBuffer commands) {
        recordComputeToTransferBarrier(commands);
        vkCmdFillBuffer(commands, buffer.handle(), 0, VK_WHOLE_SIZE, value);
        recordTransferToComputeBarrier(commands);
    });
}

} // namespace vkpt
