// buffer.h — Buffer: one VkBuffer with its own memory, named like the data it holds
// ("bvhNodes"), counted in the context's memory statistics, and refused with a clear message
// when the device cannot hold it. A buffer with VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT also
// owns the view through which kernels fetch it as texels ("<name>.texels").
#pragma once

#include "gpu/memory.h"

#include <volk.h>

#include <cstddef>
#include <string>

namespace vkpt {

class GpuContext;

struct BufferDesc {
    std::string name;      // debug name, same word as in C++ and GLSL: "bvhNodes"
    VkDeviceSize size = 0; // bytes, > 0 (Vulkan has no empty buffers)
    VkBufferUsageFlags usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    MemoryLocation location = MemoryLocation::DeviceLocal;
    // With VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT: the view's format, one of the 16-byte
    // four-channel 32-bit formats (kernels read it as a `usamplerBuffer` or `samplerBuffer`).
    VkFormat texelFormat = VK_FORMAT_R32G32B32A32_UINT;
};

// Bytes per texel of the texel views buffers make.
inline constexpr VkDeviceSize kTexelBytes = 16;

// The size a texel buffer of `bytes` is created with, and its view's range: whole texels, never
// a power of two, and never with bits 8-15 zero. Lavapipe (Mesa 22.3) compiles a kernel once
// per "variant key", and the key records, for each texel view bound, whether its buffer's size
// is a power of two and whether bits 8-15 of the view's range are zero (it reads the range
// through the mip-level field of a union). Sizes that keep both false give every frame size
// and every scene the same key, so LLVM compiles each kernel once, not once per size.
VkDeviceSize keyStableTexelBytes(VkDeviceSize bytes);

class Buffer {
public:
    // Throws VulkanError naming the buffer, its size and the limit when a storage buffer is
    // larger than maxStorageBufferRange, a uniform buffer than maxUniformBufferRange, a texel
    // buffer holds more than maxTexelBufferElements texels or the memory is larger than
    // maxMemoryAllocationSize (splitting big buffers is the caller's decision, not this layer's).
    Buffer(GpuContext& context, BufferDesc desc);
    ~Buffer();
    Buffer(Buffer&& other) noexcept;
    Buffer& operator=(Buffer&& other) noexcept;
    Buffer(const Buffer&) = delete;
    Buffer& operator=(const Buffer&) = delete;

    GpuContext& context() const { return *context_; }
    VkBuffer handle() const { return buffer_; }
    VkDeviceSize size() const { return desc_.size; }
    const std::string& name() const { return desc_.name; }
    VkBufferUsageFlags usage() const { return desc_.usage; }
    MemoryLocation location() const { return desc_.location; }
    // Bytes of device memory held (the allocation may exceed size() for alignment).
    VkDeviceSize allocationSize() const { return allocationSize_; }
    // Upload and Readback buffers stay mapped for their lifetime; null for DeviceLocal.
    std::byte* mapped() const { return mapped_; }
    // The texel view of a uniform texel buffer of at least one texel, else VK_NULL_HANDLE.
    VkBufferView texelView() const { return texelView_; }

private:
    VkDeviceSize texelRange() const;
    void checkLimits() const;
    void allocateAndBind();
    void createTexelView();
    void release() noexcept;

    GpuContext* context_ = nullptr;
    BufferDesc desc_;
    VkBuffer buffer_ = VK_NULL_HANDLE;
    VkDeviceMemory memory_ = VK_NULL_HANDLE;
    VkDeviceSize allocationSize_ = 0;
    std::byte* mapped_ = nullptr;
    VkBufferView texelView_ = VK_NULL_HANDLE;
};

} // namespace vkpt
