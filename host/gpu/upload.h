// upload.h — moving plain data between host memory and buffers: uploads through a staging
// buffer into device-local memory, downloads back (readback, tests). Each call waits.
#pragma once

#include "gpu/buffer.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

namespace vkpt {

class GpuContext;

// Copies `bytes` to `destination` at `offset` and makes them visible to later kernels and
// indirect dispatches. A device-local destination needs VK_BUFFER_USAGE_TRANSFER_DST_BIT.
void uploadBytes(GpuContext& context, const Buffer& destination, std::span<const std::byte> bytes,
                 VkDeviceSize offset = 0);

// Copies bytes.size() bytes from `source` at `offset` once all earlier work has finished.
// A device-local source needs VK_BUFFER_USAGE_TRANSFER_SRC_BIT.
void downloadBytes(GpuContext& context, const Buffer& source, std::span<std::byte> bytes,
                   VkDeviceSize offset = 0);

// Sets every 32-bit word of `buffer` to `value` (vkCmdFillBuffer; needs TRANSFER_DST).
void fillBuffer(GpuContext& context, const Buffer& buffer, std::uint32_t value);

template <typename T>
void upload(GpuContext& context, const Buffer& destination, std::span<const T> values,
            VkDeviceSize offset = 0) {
    static_assert(std::is_trivially_copyable_v<T>, "only plain data goes to the device");
    uploadBytes(context, destination, std::as_bytes(values), offset);
}

template <typename T>
std::vector<T> download(GpuContext& context, const Buffer& source, std::size_t count,
                        VkDeviceSize offset = 0) {
    static_assert(std::is_trivially_copyable_v<T>, "only plain data comes from the device");
    std::vector<T> values(count);
    downloadBytes(context, source, std::as_writable_bytes(std::span<T>(values)), offset);
    return values;
}

// A device-local buffer named `name` holding `values` (TRANSFER_DST is added to `usage`).
template <typename T>
Buffer createBufferWithData(GpuContext& context, std::string name, VkBufferUsageFlags usage,
                            std::span<const T> values) {
    Buffer buffer(context, {std::move(name), values.size_bytes(),
                            usage | VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryLocation::DeviceLocal});
    upload(context, buffer, values);
    return buffer;
}

} // namespace vkpt
