// descriptor_set.cpp — allocation and updates of a kernel's storage-buffer descriptor set.
#include "gpu/descriptor_set.h"

#include "common/errors.h"
#include "gpu/buffer.h"
#include "gpu/context.h"
#include "gpu/kernel.h"
#include "gpu/vk_check.h"

#include <algorithm>
#include <utility>

namespace vkpt {

namespace {

VkDescriptorPool createPool(const GpuContext& context, std::uint32_t bufferCount) {
    const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, std::max(bufferCount, 1u)};
    VkDescriptorPoolCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
    info.maxSets = 1;
    info.poolSizeCount = 1;
    info.pPoolSizes = &size;
    VkDescriptorPool pool = VK_NULL_HANDLE;
    VKPT_VK_CHECK(vkCreateDescriptorPool(context.device(), &info, nullptr, &pool));
    return pool;
}

} // namespace

DescriptorSet::DescriptorSet(const Kernel& kernel, const std::vector<BufferBinding>& bindings)
    : context_(&kernel.context()), kernelName_(kernel.name()),
      kernelBindings_(kernel.storageBufferBindings()) {
    checkBindings(bindings);
    pool_ = createPool(*context_, static_cast<std::uint32_t>(bindings.size()));
    context_->setDebugName(pool_, kernel.name() + ".pool");
    try {
        const VkDescriptorSetLayout layout = kernel.setLayout();
        VkDescriptorSetAllocateInfo info{};
        info.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
        info.descriptorPool = pool_;
        info.descriptorSetCount = 1;
        info.pSetLayouts = &layout;
        VKPT_VK_CHECK(vkAllocateDescriptorSets(context_->device(), &info, &set_));
        context_->setDebugName(set_, kernel.name() + ".set");
        update(bindings);
    } catch (...) {
        vkDestroyDescriptorPool(context_->device(), pool_, nullptr);
        throw;
    }
}

DescriptorSet::~DescriptorSet() {
    // Destroying the pool frees its set.
    if (context_ != nullptr) vkDestroyDescriptorPool(context_->device(), pool_, nullptr);
}

DescriptorSet::DescriptorSet(DescriptorSet&& other) noexcept
    : context_(std::exchange(other.context_, nullptr)), kernelName_(std::move(other.kernelName_)),
      kernelBindings_(std::move(other.kernelBindings_)),
      pool_(std::exchange(other.pool_, VK_NULL_HANDLE)),
      set_(std::exchange(other.set_, VK_NULL_HANDLE)) {}

void DescriptorSet::checkBindings(const std::vector<BufferBinding>& bindings) const {
    const std::vector<std::uint32_t>& expected = kernelBindings_;
    VKPT_ASSERT(bindings.size() == expected.size(),
                "kernel '" + kernelName_ + "' has " + std::to_string(expected.size()) +
                    " storage buffers, " + std::to_string(bindings.size()) + " given");
    for (const BufferBinding& binding : bindings) {
        VKPT_ASSERT(binding.buffer != nullptr, "kernel '" + kernelName_ + "': null buffer");
        VKPT_ASSERT(std::count(expected.begin(), expected.end(), binding.binding) == 1,
                    "kernel '" + kernelName_ + "' has no binding " +
                        std::to_string(binding.binding));
        VKPT_ASSERT((binding.buffer->usage() & VK_BUFFER_USAGE_STORAGE_BUFFER_BIT) != 0,
                    "buffer '" + binding.buffer->name() + "' is not a storage buffer");
    }
}

void DescriptorSet::update(const std::vector<BufferBinding>& bindings) {
    checkBindings(bindings);
    std::vector<VkDescriptorBufferInfo> infos;
    infos.reserve(bindings.size()); // writes point into it
    std::vector<VkWriteDescriptorSet> writes;
    for (const BufferBinding& binding : bindings) {
        infos.push_back({binding.buffer->handle(), 0, VK_WHOLE_SIZE});
        VkWriteDescriptorSet write{};
        write.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
        write.dstSet = set_;
        write.dstBinding = binding.binding;
        write.descriptorCount = 1;
        write.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        write.pBufferInfo = &infos.back();
        writes.push_back(write);
    }
    vkUpdateDescriptorSets(context_->device(), static_cast<std::uint32_t>(writes.size()),
                           writes.data(), 0, nullptr);
}

} // namespace vkpt
