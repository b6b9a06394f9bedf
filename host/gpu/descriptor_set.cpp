// descriptor_set.cpp — allocation and updates of a kernel's descriptor set.
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

// One pool size per descriptor kind the kernel uses.
VkDescriptorPool createPool(const GpuContext& context, const std::vector<KernelBinding>& bindings) {
    std::vector<VkDescriptorPoolSize> sizes;
    for (const KernelBinding& binding : bindings) {
        const VkDescriptorType type = descriptorTypeOf(binding.kind);
        auto same = std::find_if(sizes.begin(), sizes.end(),
                                 [type](const VkDescriptorPoolSize& s) { return s.type == type; });
        if (same == sizes.end()) {
            sizes.push_back({type, binding.count});
        } else {
            same->descriptorCount += binding.count;
        }
    }
    if (sizes.empty()) sizes.push_back({VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1});
    VkDescriptorPoolCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
    info.maxSets = 1;
    info.poolSizeCount = static_cast<std::uint32_t>(sizes.size());
    info.pPoolSizes = sizes.data();
    VkDescriptorPool pool = VK_NULL_HANDLE;
    VKPT_VK_CHECK(vkCreateDescriptorPool(context.device(), &info, nullptr, &pool));
    return pool;
}

// The buffer usage a descriptor kind reads through.
VkBufferUsageFlags usageFor(DescriptorKind kind) {
    switch (kind) {
    case DescriptorKind::StorageBuffer:
        return VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    case DescriptorKind::UniformBuffer:
        return VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT;
    case DescriptorKind::UniformTexelBuffer:
        return VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT;
    }
    return 0;
}

// The descriptor written at element `element` of `binding`.
const Buffer* elementBuffer(const BufferBinding& binding, std::uint32_t element) {
    if (binding.elements.empty()) return binding.buffer;
    return binding.elements[std::min<std::size_t>(element, binding.elements.size() - 1)];
}

} // namespace

DescriptorSet::DescriptorSet(const Kernel& kernel, const std::vector<BufferBinding>& bindings)
    : context_(&kernel.context()), kernelName_(kernel.name()), kernelBindings_(kernel.bindings()) {
    checkBindings(bindings);
    pool_ = createPool(*context_, kernelBindings_);
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

const KernelBinding& DescriptorSet::declared(std::uint32_t binding) const {
    for (const KernelBinding& declared : kernelBindings_)
        if (declared.binding == binding) return declared;
    VKPT_ASSERT(false, "kernel '" + kernelName_ + "' has no binding " + std::to_string(binding));
    return kernelBindings_.front();
}

void DescriptorSet::checkBuffer(const KernelBinding& declared, const Buffer* buffer) const {
    VKPT_ASSERT(buffer != nullptr, "kernel '" + kernelName_ + "': binding " +
                                       std::to_string(declared.binding) + " has no buffer");
    VKPT_ASSERT(declared.kind != DescriptorKind::UniformTexelBuffer ||
                    buffer->texelView() != VK_NULL_HANDLE,
                "buffer '" + buffer->name() + "' is smaller than one texel");
    VKPT_ASSERT((buffer->usage() & usageFor(declared.kind)) != 0,
                "buffer '" + buffer->name() + "' lacks the usage of binding " +
                    std::to_string(declared.binding) + " of kernel '" + kernelName_ + "'");
}

void DescriptorSet::checkBindings(const std::vector<BufferBinding>& bindings) const {
    VKPT_ASSERT(bindings.size() == kernelBindings_.size(),
                "kernel '" + kernelName_ + "' has " + std::to_string(kernelBindings_.size()) +
                    " bindings, " + std::to_string(bindings.size()) + " given");
    for (const BufferBinding& binding : bindings) {
        const auto named =
            std::count_if(bindings.begin(), bindings.end(), [&binding](const BufferBinding& other) {
                return other.binding == binding.binding;
            });
        VKPT_ASSERT(named == 1, "kernel '" + kernelName_ + "': binding " +
                                    std::to_string(binding.binding) + " given more than once");
        const KernelBinding& kernelBinding = declared(binding.binding);
        VKPT_ASSERT(binding.elements.size() <= kernelBinding.count,
                    "kernel '" + kernelName_ + "': binding " + std::to_string(binding.binding) +
                        " has " + std::to_string(kernelBinding.count) + " descriptors, " +
                        std::to_string(binding.elements.size()) + " buffers given");
        for (std::uint32_t element = 0; element < kernelBinding.count; ++element)
            checkBuffer(kernelBinding, elementBuffer(binding, element));
    }
}

void DescriptorSet::update(const std::vector<BufferBinding>& bindings) {
    checkBindings(bindings);
    std::size_t descriptors = 0;
    for (const BufferBinding& binding : bindings)
        descriptors += declared(binding.binding).count;
    // Writes point into these, so they must not reallocate.
    std::vector<VkDescriptorBufferInfo> infos;
    infos.reserve(descriptors);
    std::vector<VkBufferView> views;
    views.reserve(descriptors);
    std::vector<VkWriteDescriptorSet> writes;
    for (const BufferBinding& binding : bindings) {
        const KernelBinding& kernelBinding = declared(binding.binding);
        VkWriteDescriptorSet write{};
        write.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
        write.dstSet = set_;
        write.dstBinding = binding.binding;
        write.descriptorCount = kernelBinding.count;
        write.descriptorType = descriptorTypeOf(kernelBinding.kind);
        for (std::uint32_t element = 0; element < kernelBinding.count; ++element) {
            const Buffer* buffer = elementBuffer(binding, element);
            if (kernelBinding.kind == DescriptorKind::UniformTexelBuffer) {
                views.push_back(buffer->texelView());
            } else {
                infos.push_back({buffer->handle(), 0, VK_WHOLE_SIZE});
            }
        }
        if (kernelBinding.kind == DescriptorKind::UniformTexelBuffer) {
            write.pTexelBufferView = &views[views.size() - kernelBinding.count];
        } else {
            write.pBufferInfo = &infos[infos.size() - kernelBinding.count];
        }
        writes.push_back(write);
    }
    vkUpdateDescriptorSets(context_->device(), static_cast<std::uint32_t>(writes.size()),
                           writes.data(), 0, nullptr);
}

} // namespace vkpt
