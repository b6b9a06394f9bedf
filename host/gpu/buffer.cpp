// buffer.cpp — buffer creation with limit checks, memory choice, naming and accounting.
#include "gpu/buffer.h"

#include "common/errors.h"
#include "gpu/context.h"
#include "gpu/vk_check.h"

#include <algorithm>
#include <bit>
#include <utility>

namespace vkpt {

namespace {

[[noreturn]] void throwTooLarge(const std::string& name, VkDeviceSize size, const char* limitName,
                                VkDeviceSize limit) {
    throw VulkanError("buffer '" + name + "' is " + formatBytes(size) + ", above this device's " +
                          limitName + " of " + formatBytes(limit),
                      VK_ERROR_OUT_OF_DEVICE_MEMORY);
}

// What the heap of memory type `typeIndex` has left: its size less what this context holds (all
// vkpt allocates; other processes' use is not visible without VK_EXT_memory_budget).
VkDeviceSize heapAvailable(const GpuContext& context, std::uint32_t typeIndex) {
    const VkPhysicalDeviceMemoryProperties& memory = context.memoryProperties();
    const VkDeviceSize heap = memory.memoryHeaps[memory.memoryTypes[typeIndex].heapIndex].size;
    const std::uint64_t inUse = context.memoryStats().bytesInUse;
    return heap - std::min<VkDeviceSize>(heap, inUse);
}

[[noreturn]] void throwOutOfMemory(const GpuContext& context, const std::string& name,
                                   VkDeviceSize size, std::uint32_t typeIndex, VkResult result) {
    throw VulkanError("cannot allocate " + formatBytes(size) + " for buffer '" + name +
                          "': this device has " + formatBytes(heapAvailable(context, typeIndex)) +
                          " available (" + vkResultName(result) + ")",
                      result);
}

} // namespace

VkDeviceSize keyStableTexelBytes(VkDeviceSize bytes) {
    VkDeviceSize size = (bytes + kTexelBytes - 1) / kTexelBytes * kTexelBytes;
    while (std::has_single_bit(size) || ((size >> 8) & 0xff) == 0)
        size += kTexelBytes;
    return size;
}

Buffer::Buffer(GpuContext& context, BufferDesc desc) : context_(&context), desc_(std::move(desc)) {
    VKPT_ASSERT(desc_.size > 0, "buffer '" + desc_.name + "' has size 0");
    checkLimits();
    VkBufferCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
    info.size = std::max(desc_.size, texelRange());
    info.usage = desc_.usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    VKPT_VK_CHECK(vkCreateBuffer(context.device(), &info, nullptr, &buffer_));
    try {
        allocateAndBind();
        createTexelView();
        context.setDebugName(buffer_, desc_.name);
        context.setDebugName(memory_, desc_.name + ".memory");
    } catch (...) {
        release();
        throw;
    }
}

// maxStorageBufferRange bounds a descriptor's range, not a VkBuffer; vkpt binds whole buffers,
// so it is the largest storage buffer a kernel can see. Checked before anything is allocated.
void Buffer::checkLimits() const {
    const DeviceLimits& limits = context_->limits();
    if ((desc_.usage & VK_BUFFER_USAGE_STORAGE_BUFFER_BIT) != 0 &&
        desc_.size > limits.maxStorageBufferRange) {
        throwTooLarge(desc_.name, desc_.size, "maxStorageBufferRange",
                      limits.maxStorageBufferRange);
    }
    if ((desc_.usage & VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT) != 0 &&
        desc_.size > limits.maxUniformBufferRange) {
        throwTooLarge(desc_.name, desc_.size, "maxUniformBufferRange",
                      limits.maxUniformBufferRange);
    }
    if ((desc_.usage & VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT) != 0 &&
        desc_.size / kTexelBytes > limits.maxTexelBufferElements) {
        throwTooLarge(desc_.name, desc_.size, "maxTexelBufferElements",
                      VkDeviceSize(limits.maxTexelBufferElements) * kTexelBytes);
    }
    if (desc_.size > limits.maxMemoryAllocationSize) {
        throwTooLarge(desc_.name, desc_.size, "maxMemoryAllocationSize",
                      limits.maxMemoryAllocationSize);
    }
}

void Buffer::allocateAndBind() {
    const VkDevice device = context_->device();
    VkMemoryRequirements requirements{};
    vkGetBufferMemoryRequirements(device, buffer_, &requirements);
    if (requirements.size > context_->limits().maxMemoryAllocationSize) {
        throwTooLarge(desc_.name, requirements.size, "maxMemoryAllocationSize",
                      context_->limits().maxMemoryAllocationSize);
    }
    VkMemoryAllocateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
    info.allocationSize = requirements.size;
    info.memoryTypeIndex =
        chooseMemoryType(context_->memoryProperties(), requirements.memoryTypeBits, desc_.location);
    // A size above what the heap has left is refused here, with both sizes, rather than left
    // to a driver that may overcommit (lavapipe) or fail without saying how much was free.
    if (requirements.size > heapAvailable(*context_, info.memoryTypeIndex)) {
        throwOutOfMemory(*context_, desc_.name, requirements.size, info.memoryTypeIndex,
                         VK_ERROR_OUT_OF_DEVICE_MEMORY);
    }
    const VkResult result = vkAllocateMemory(device, &info, nullptr, &memory_);
    if (result != VK_SUCCESS) {
        throwOutOfMemory(*context_, desc_.name, requirements.size, info.memoryTypeIndex, result);
    }
    allocationSize_ = requirements.size;
    context_->memoryAccounting().recordAllocation(allocationSize_);
    VKPT_VK_CHECK(vkBindBufferMemory(device, buffer_, memory_, 0));
    if (desc_.location != MemoryLocation::DeviceLocal) {
        void* mapped = nullptr;
        VKPT_VK_CHECK(vkMapMemory(device, memory_, 0, VK_WHOLE_SIZE, 0, &mapped));
        mapped_ = static_cast<std::byte*>(mapped);
    }
}

// A view of the whole buffer in whole texels; a partial texel at the end is not visible, and
// a buffer smaller than one texel gets no view (nothing could be fetched from it).
void Buffer::createTexelView() {
    if ((desc_.usage & VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT) == 0) return;
    if (desc_.size < kTexelBytes) return;
    VKPT_ASSERT(desc_.texelFormat == VK_FORMAT_R32G32B32A32_UINT ||
                    desc_.texelFormat == VK_FORMAT_R32G32B32A32_SFLOAT,
                "buffer '" + desc_.name + "': texel format not 16 bytes");
    VkBufferViewCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_BUFFER_VIEW_CREATE_INFO;
    info.buffer = buffer_;
    info.format = desc_.texelFormat;
    info.offset = 0;
    info.range = texelRange();
    VKPT_VK_CHECK(vkCreateBufferView(context_->device(), &info, nullptr, &texelView_));
    context_->setDebugName(texelView_, desc_.name + ".texels");
}

// The texel view's range (0 without one): keyStableTexelBytes, less the padding where that
// would cross a limit desc_.size keeps within (that buffer then costs a compile per size, not
// a refusal). The buffer is created at least this large.
VkDeviceSize Buffer::texelRange() const {
    const bool texels = (desc_.usage & VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT) != 0;
    if (!texels || desc_.size < kTexelBytes) return 0;
    const DeviceLimits& limits = context_->limits();
    const VkDeviceSize padded = keyStableTexelBytes(desc_.size);
    const bool storage = (desc_.usage & VK_BUFFER_USAGE_STORAGE_BUFFER_BIT) != 0;
    const bool fits = padded / kTexelBytes <= limits.maxTexelBufferElements &&
                      padded <= limits.maxMemoryAllocationSize &&
                      (!storage || padded <= limits.maxStorageBufferRange);
    return fits ? padded : desc_.size / kTexelBytes * kTexelBytes;
}

void Buffer::release() noexcept {
    if (context_ == nullptr) return;
    const VkDevice device = context_->device();
    if (texelView_ != VK_NULL_HANDLE) vkDestroyBufferView(device, texelView_, nullptr);
    texelView_ = VK_NULL_HANDLE;
    if (buffer_ != VK_NULL_HANDLE) vkDestroyBuffer(device, buffer_, nullptr);
    if (memory_ != VK_NULL_HANDLE) {
        // vkFreeMemory unmaps implicitly.
        vkFreeMemory(device, memory_, nullptr);
        context_->memoryAccounting().recordFree(allocationSize_);
    }
    buffer_ = VK_NULL_HANDLE;
    memory_ = VK_NULL_HANDLE;
    mapped_ = nullptr;
    allocationSize_ = 0;
}

Buffer::~Buffer() {
    release();
}

Buffer::Buffer(Buffer&& other) noexcept
    : context_(std::exchange(other.context_, nullptr)), desc_(std::move(other.desc_)),
      buffer_(std::exchange(other.buffer_, VK_NULL_HANDLE)),
      memory_(std::exchange(other.memory_, VK_NULL_HANDLE)),
      allocationSize_(std::exchange(other.allocationSize_, 0)),
      mapped_(std::exchange(other.mapped_, nullptr)),
      texelView_(std::exchange(other.texelView_, VK_NULL_HANDLE)) {}

Buffer& Buffer::operator=(Buffer&& other) noexcept {
    if (this != &other) {
        release();
        context_ = std::exchange(other.context_, nullptr);
        desc_ = std::move(other.desc_);
        buffer_ = std::exchange(other.buffer_, VK_NULL_HANDLE);
        memory_ = std::exchange(other.memory_, VK_NULL_HANDLE);
        allocationSize_ = std::exchange(other.allocationSize_, 0);
        mapped_ = std::exchange(other.mapped_, nullptr);
        texelView_ = std::exchange(other.texelView_, VK_NULL_HANDLE);
    }
    return *this;
}

} // namespace vkpt
