// scene_arrays.cpp — the scene array list, chunk planning and chunked upload.
#include "render/scene_arrays.h"

#include <algorithm>
#include <bit>
#include <cstdlib>
#include <string>
#include <type_traits>
#include <utility>

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
                                    SceneArrayAccess access, bool splittable = true) {
    using Vector = std::remove_cvref_t<decltype(std::declval<PreparedScene&>().*Member)>;
    const std::uint64_t unit =
        access == SceneArrayAccess::Texels ? kTexelBytes : sizeof(typename Vector::value_type);
    return {name, binding, access, splittable, unit, &arrayBytes<Member>, &releaseArray<Member>};
}

constexpr SceneArrayAccess kTexels = SceneArrayAccess::Texels;
constexpr SceneArrayAccess kStorage = SceneArrayAccess::Storage;

// Every array the kernels read from the scene, one line each. Records of
// 16-byte multiples are fetched as texels (lib/records.glsl), the rest read as storage buffers
// (lib/kernel_bindings.h). A splittable array is declared in GLSL with VKPT_SCENE_TEXELS or a
// SCENE entry; the last is read by shared code as one array (shared/albedo_lookup.h) and has a
// fixed size.
const SceneArrayDesc kSceneArrays[] = {
    sceneArray<&PreparedScene::nodes>("bvhNodes", BINDING_BVH_NODES, kTexels),
    sceneArray<&PreparedScene::triangles>("triangles", BINDING_TRIANGLES, kTexels),
    sceneArray<&PreparedScene::normals>("triangleNormals", BINDING_TRIANGLE_NORMALS, kTexels),
    sceneArray<&PreparedScene::tangents>("triangleTangents", BINDING_TRIANGLE_TANGENTS, kTexels),
    sceneArray<&PreparedScene::materials>("materials", BINDING_MATERIALS, kTexels),
    sceneArray<&PreparedScene::emitters>("emitters", BINDING_EMITTERS, kTexels),
    sceneArray<&PreparedScene::lightTree>("lightTree", BINDING_LIGHT_TREE, kTexels),
    sceneArray<&PreparedScene::instances>("instances", BINDING_INSTANCES, kTexels),
    sceneArray<&PreparedScene::uvs>("triangleUvs", BINDING_TRIANGLE_UVS, kStorage),
    sceneArray<&PreparedScene::textures>("textures", BINDING_TEXTURES, kTexels),
    sceneArray<&PreparedScene::emitterCdf>("emitterCdf", BINDING_EMITTER_CDF, kStorage),
    sceneArray<&PreparedScene::texels>("textureTexels", BINDING_TEXTURE_TEXELS, kStorage),
    sceneArray<&PreparedScene::environmentTexels>("environmentTexels", BINDING_ENVIRONMENT_TEXELS,
                                                  kStorage),
    sceneArray<&PreparedScene::environmentCdf>("environmentCdf", BINDING_ENVIRONMENT_CDF, kStorage),
    sceneArray<&PreparedScene::albedoTables>("albedoTables", BINDING_ALBEDO_TABLES, kStorage,
                                             false),
};

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

bool isSplittableSceneBinding(std::uint32_t binding) {
    return std::any_of(
        std::begin(kSceneArrays), std::end(kSceneArrays),
        [binding](const SceneArrayDesc& d) { return d.binding == binding && d.splittable; });
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
