// scene_arrays.cpp — the scene array list, chunk planning and chunked upload.
#include "render/scene_arrays.h"

#include <algorithm>
#include <bit>
#include <cstdlib>
#include <string>
#include <type_traits>
#include <utility>

#include "common/errors.h"
#include "gpu/upload.h"
#include "gpu/vk_check.h"
#include "lib/wavefront.h"

namespace vkpt {

namespace {

template <auto Member> std::span<const std::byte> arrayBytes(const PreparedScene& scene) {
    return std::as_bytes(std::span(scene.*Member));
}

template <auto Member> void releaseArray(PreparedScene& scene) {
    std::exchange(scene.*Member, {}); // frees the capacity too, unlike clear()
}

template <auto Member>
constexpr SceneArrayDesc sceneArray(const char* name, std::uint32_t binding,
                                    SceneArrayAccess access, bool splittable) {
    using Vector = std::remove_cvref_t<decltype(std::declval<PreparedScene&>().*Member)>;
    const std::uint64_t unit =
        access == SceneArrayAccess::Texels ? kTexelBytes : sizeof(typename Vector::value_type);
    return {name, binding, access, splittable, unit, &arrayBytes<Member>, &releaseArray<Member>};
}

constexpr SceneArrayAccess kTexels = SceneArrayAccess::Texels;
constexpr SceneArrayAccess kStorage = SceneArrayAccess::Storage;

// Every array the kernels read from the scene: a row of shared/scene_array_table.h each, in its
// order, with its access and split columns in the host's words.
#define VKPT_ACCESS_TEXELS kTexels
#define VKPT_ACCESS_STORAGE kStorage
#define VKPT_SPLITTABLE_SPLIT true
#define VKPT_SPLITTABLE_WHOLE false
#define VKPT_SCENE_ARRAY_DESC(name, Type, binding, number, access, split, member, reader,          \
                              accessor)                                                            \
    sceneArray<&PreparedScene::member>(#name, binding, VKPT_ACCESS_##access,                       \
                                       VKPT_SPLITTABLE_##split),
const SceneArrayDesc kSceneArrays[] = {VKPT_SCENE_ARRAYS(VKPT_SCENE_ARRAY_DESC)};

constexpr VkDeviceSize kStagingSliceBytes = VkDeviceSize(64) << 20;

VkDeviceSize testBindingBytes() {
    const char* value = std::getenv("VKPT_TEST_BINDING_BYTES");
    if (value == nullptr || *value == '\0') return ~VkDeviceSize(0);
    const VkDeviceSize bytes = std::strtoull(value, nullptr, 10);
    return bytes > 0 ? bytes : ~VkDeviceSize(0);
}

VkBufferUsageFlags usageOf(SceneArrayAccess access) {
    return (access == kTexels ? VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT
                              : VK_BUFFER_USAGE_STORAGE_BUFFER_BIT) |
           VK_BUFFER_USAGE_TRANSFER_DST_BIT;
}

std::string chunkName(const SceneArrayDesc& desc, std::uint32_t chunk, std::uint32_t count) {
    if (count == 1) return desc.name;
    return std::string(desc.name) + "[" + std::to_string(chunk) + "]";
}

[[noreturn]] void throwTooManyChunks(const SceneArrayDesc& desc, std::uint64_t bytes,
                                     VkDeviceSize limit, std::uint32_t allowed) {
    throw VulkanError(
        "scene array '" + std::string(desc.name) + "' is " + formatBytes(bytes) + ", above " +
            std::to_string(allowed) + " × this device's " + formatBytes(limit) + " per binding (" +
            (desc.access == kTexels ? "maxTexelBufferElements" : "maxStorageBufferRange") +
            ", maxMemoryAllocationSize)",
        VK_ERROR_OUT_OF_DEVICE_MEMORY);
}

void uploadInSlices(GpuContext& context, const Buffer& chunk, std::span<const std::byte> bytes) {
    for (VkDeviceSize offset = 0; offset < bytes.size(); offset += kStagingSliceBytes) {
        const VkDeviceSize size = std::min<VkDeviceSize>(kStagingSliceBytes, bytes.size() - offset);
        uploadBytes(context, chunk, bytes.subspan(offset, size), offset);
    }
}

} // namespace

std::span<const SceneArrayDesc> sceneArrayList() {
    return kSceneArrays;
}

const SceneArrayDesc* findSceneArray(std::uint32_t binding) {
    const auto found =
        std::find_if(std::begin(kSceneArrays), std::end(kSceneArrays),
                     [binding](const SceneArrayDesc& d) { return d.binding == binding; });
    return found == std::end(kSceneArrays) ? nullptr : found;
}

bool isSplittableSceneBinding(std::uint32_t binding) {
    const SceneArrayDesc* desc = findSceneArray(binding);
    return desc != nullptr && desc->splittable;
}

KernelBinding sceneKernelBinding(std::uint32_t binding) {
    const SceneArrayDesc* desc = findSceneArray(binding);
    VKPT_ASSERT(desc != nullptr, "binding " + std::to_string(binding) +
                                     " of a SCENE entry (lib/kernel_bindings.h) is no scene array");
    return {binding,
            desc->access == kTexels ? DescriptorKind::UniformTexelBuffer
                                    : DescriptorKind::StorageBuffer,
            desc->splittable ? SCENE_ARRAY_MAX_CHUNKS : 1u};
}

VkDeviceSize sceneChunkByteLimit(const DeviceLimits& limits, SceneArrayAccess access) {
    const VkDeviceSize range = access == kTexels
                                   ? VkDeviceSize(limits.maxTexelBufferElements) * kTexelBytes
                                   : VkDeviceSize(limits.maxStorageBufferRange);
    return std::min(range, limits.maxMemoryAllocationSize);
}

ChunkPlan planChunks(std::uint64_t elementCount, std::uint64_t elementBytes,
                     VkDeviceSize chunkByteLimit) {
    if (elementCount * elementBytes <= chunkByteLimit) return {};
    const std::uint64_t perChunk = std::bit_floor(std::max<std::uint64_t>(
        chunkByteLimit / elementBytes, 1)); // a power of two: a shift and a mask in the kernels
    ChunkPlan plan;
    plan.chunkLog2 = static_cast<std::uint32_t>(std::countr_zero(perChunk));
    plan.chunkCount = static_cast<std::uint32_t>((elementCount + perChunk - 1) / perChunk);
    return plan;
}

std::uint64_t SceneArray::allocationBytes() const {
    std::uint64_t total = 0;
    for (const Buffer& chunk : chunks)
        total += chunk.allocationSize();
    return total;
}

SceneArray uploadSceneArray(GpuContext& context, const SceneArrayDesc& desc,
                            std::span<const std::byte> bytes) {
    SceneArray array{&desc, {}, 31};
    if (bytes.empty()) return array;
    VkDeviceSize limit = sceneChunkByteLimit(context.limits(), desc.access);
    if (desc.splittable) limit = std::min(limit, testBindingBytes());
    const ChunkPlan plan = planChunks(bytes.size() / desc.elementBytes, desc.elementBytes, limit);
    const std::uint32_t allowed = desc.splittable ? SCENE_ARRAY_MAX_CHUNKS : 1;
    if (plan.chunkCount > allowed) throwTooManyChunks(desc, bytes.size(), limit, allowed);
    array.chunkLog2 = plan.chunkLog2;
    const std::uint64_t chunkBytes =
        plan.chunkCount == 1 ? bytes.size() : desc.elementBytes << plan.chunkLog2;
    for (std::uint32_t i = 0; i < plan.chunkCount; ++i) {
        const std::span<const std::byte> part = bytes.subspan(
            i * chunkBytes, std::min<std::uint64_t>(chunkBytes, bytes.size() - i * chunkBytes));
        array.chunks.emplace_back(context,
                                  BufferDesc{chunkName(desc, i, plan.chunkCount), part.size(),
                                             usageOf(desc.access), MemoryLocation::DeviceLocal});
        uploadInSlices(context, array.chunks.back(), part);
    }
    return array;
}

} // namespace vkpt
