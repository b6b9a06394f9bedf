// descriptor_set.h — DescriptorSet: which buffer each binding of a kernel reads and writes.
// One small pool per set: vkpt has a handful of kernels, each with a set or two (e.g.
// ping-pong ray queues), so pooling across kernels would buy nothing.
#pragma once

#include <volk.h>

#include <cstdint>
#include <string>
#include <vector>

#include "gpu/kernel.h"

namespace vkpt {

class Buffer;
class GpuContext;

// A buffer bound whole (offset 0, VK_WHOLE_SIZE), or through its texel view where the
// kernel's binding is a uniform texel buffer. A binding of several descriptors (an array,
// KernelBinding::count) takes element i from elements[i], the last of them past its end, or
// from `buffer` when elements is empty.
struct BufferBinding {
    std::uint32_t binding = 0;
    const Buffer* buffer = nullptr;
    std::vector<const Buffer*> elements{};
};

class DescriptorSet {
public:
    // `bindings` must name each of the kernel's bindings exactly once, each with a buffer that
    // has the usage its kind needs. The set copies what it needs from `kernel`; the buffers
    // must outlive every use of the set.
    DescriptorSet(const Kernel& kernel, const std::vector<BufferBinding>& bindings);
    ~DescriptorSet();
    DescriptorSet(DescriptorSet&& other) noexcept;
    DescriptorSet& operator=(DescriptorSet&&) = delete;
    DescriptorSet(const DescriptorSet&) = delete;
    DescriptorSet& operator=(const DescriptorSet&) = delete;

    VkDescriptorSet handle() const { return set_; }

    // Points the bindings at other buffers. Only while no submitted work uses the set.
    void update(const std::vector<BufferBinding>& bindings);

private:
    void checkBindings(const std::vector<BufferBinding>& bindings) const;
    const KernelBinding& declared(std::uint32_t binding) const;
    void checkBuffer(const KernelBinding& declared, const Buffer* buffer) const;

    const GpuContext* context_;
    std::string kernelName_;                    // for messages
    std::vector<KernelBinding> kernelBindings_; // what update() must be given
    VkDescriptorPool pool_ = VK_NULL_HANDLE;
    VkDescriptorSet set_ = VK_NULL_HANDLE;
};

} // namespace vkpt
