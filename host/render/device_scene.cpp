// device_scene.cpp — one named storage buffer per non-empty array of the prepared scene.
#include "render/device_scene.h"

#include <algorithm>
#include <string>
#include <vector>

#include "common/errors.h"
#include "gpu/context.h"
#include "gpu/upload.h"
#include "gpu/vk_check.h"
#include "lib/wavefront.h"

namespace vkpt {

namespace {

constexpr VkDeviceSize kAbsentDataBytes = 16;

Buffer makeAbsentData(GpuContext& context) {
    Buffer buffer(context,
                  {"absentData", kAbsentDataBytes,
                   VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT |
                       VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                   MemoryLocation::DeviceLocal});
    fillBuffer(context, buffer, 0); // defined contents, though nothing reads them
    return buffer;
}

bool hasTexture(const gpu::Material& material) {
    return material.baseColorTexture.texture != NO_TEXTURE ||
           material.metallicRoughnessTexture.texture != NO_TEXTURE ||
           material.emissiveTexture.texture != NO_TEXTURE ||
           material.normalTexture.texture != NO_TEXTURE;
}

void checkTextureSlot(const PreparedScene& scene, const gpu::TextureSlot& slot) {
    VKPT_ASSERT(slot.texture == NO_TEXTURE || slot.texture < scene.textures.size(),
                "texture index " + std::to_string(slot.texture) + " out of range");
}

void checkTextures(const PreparedScene& scene) {
    bool textured = false;
    for (const gpu::Material& material : scene.materials) {
        checkTextureSlot(scene, material.baseColorTexture);
        checkTextureSlot(scene, material.metallicRoughnessTexture);
        checkTextureSlot(scene, material.emissiveTexture);
        checkTextureSlot(scene, material.normalTexture);
        checkTextureSlot(scene, material.transmissionTexture);
        textured = textured || hasTexture(material);
    }
    VKPT_ASSERT(!textured || scene.uvs.size() == 3 * scene.triangles.size(),
                "textured materials need three texture coordinates per primitive");
    bool normalMapped = false;
    for (const gpu::Material& material : scene.materials)
        normalMapped = normalMapped || material.normalTexture.texture != NO_TEXTURE;
    VKPT_ASSERT(!normalMapped || scene.tangents.size() == scene.triangles.size(),
                "normal-mapped materials need a tangent record per primitive");
    for (const gpu::TextureInfo& texture : scene.textures) {
        VKPT_ASSERT(std::uint64_t(texture.texelOffset) +
                            std::uint64_t(texture.width) * texture.height <=
                        scene.texels.size(),
                    "a texture's texels lie outside the texel array");
    }
}

// What the kernels index without a bounds check must be there.
void checkScene(const PreparedScene& scene) {
    VKPT_ASSERT(!scene.nodes.empty() && !scene.triangles.empty(), "the scene has no primitives");
    VKPT_ASSERT(scene.normals.size() == scene.triangles.size(), "one normal record per primitive");
    for (const gpu::Triangle& primitive : scene.triangles)
        VKPT_ASSERT(primitive.materialIndex < scene.materials.size(), "material out of range");
    checkTextures(scene);
    VKPT_ASSERT(scene.emitters.size() <= 1 || scene.emitterCdf.size() == scene.emitters.size(),
                "several emitters need a selection CDF entry each");
    const gpu::EnvironmentParams& environment = scene.environment;
    VKPT_ASSERT(environment.emitterIndex == NO_EMITTER ||
                    environment.emitterIndex < scene.emitters.size(),
                "the environment's emitter is out of range");
    const std::uint64_t mapTexels = std::uint64_t(environment.width) * environment.height;
    VKPT_ASSERT(scene.environmentTexels.size() == mapTexels ||
                    (mapTexels == 0 && environment.emitterIndex == NO_EMITTER),
                "the environment map's texels do not match its size");
    VKPT_ASSERT(mapTexels == 0 || scene.environmentCdf.size() == mapTexels + environment.height,
                "the environment map's CDF does not match its size");
}

// The device memory the arrays take, before anything is allocated: a scene that cannot fit
// fails in one line naming both sizes instead of at whichever buffer comes last.
void checkDeviceMemory(const GpuContext& context, const PreparedScene& scene,
                       std::uint64_t onDevice) {
    std::uint64_t needed = 0;
    for (const SceneArrayDesc& desc : sceneArrayList())
        needed += desc.bytes(scene).size();
    needed -= std::min(needed, onDevice);
    const VkDeviceSize heap = context.limits().deviceLocalHeapSize;
    const std::uint64_t inUse = context.memoryStats().bytesInUse;
    if (heap == 0 || needed <= heap - std::min<std::uint64_t>(heap, inUse)) return;
    throw VulkanError("the scene needs " + formatBytes(needed) +
                          " of device memory; this device has " +
                          formatBytes(heap - std::min<std::uint64_t>(heap, inUse)) +
                          " available (device-local heap " + formatBytes(heap) + ", " +
                          formatBytes(inUse) + " in use)",
                      VK_ERROR_OUT_OF_DEVICE_MEMORY);
}

} // namespace

DeviceScene beginSceneUpload(GpuContext& context, const PreparedScene& scene,
                             std::uint64_t onDevice) {
    checkScene(scene);
    checkDeviceMemory(context, scene, onDevice);
    DeviceScene d{makeAbsentData(context),
                  {},
                  static_cast<std::uint32_t>(scene.emitters.size()),
                  scene.environment};
    d.arrays.reserve(sceneArrayList().size());
    return d;
}

void DeviceScene::bind(BufferTable& table) const {
    for (const SceneArray& array : arrays) {
        if (array.chunks.empty()) {
            table.set(array.desc->binding, absentData);
        } else {
            table.setChunks(array.desc->binding, array.chunks, array.chunkLog2);
        }
    }
}

std::vector<SceneBufferBytes> DeviceScene::bufferBytes() const {
    std::vector<SceneBufferBytes> result{{absentData.name(), absentData.allocationSize(), 1}};
    for (const SceneArray& array : arrays)
        if (!array.chunks.empty())
            result.push_back({array.desc->name, array.allocationBytes(),
                              static_cast<std::uint32_t>(array.chunks.size())});
    return result;
}

std::uint64_t DeviceScene::totalBytes() const {
    std::uint64_t total = 0;
    for (const SceneBufferBytes& buffer : bufferBytes())
        total += buffer.bytes;
    return total;
}

DeviceScene uploadScene(GpuContext& context, const PreparedScene& scene) {
    DeviceScene d = beginSceneUpload(context, scene);
    for (const SceneArrayDesc& desc : sceneArrayList())
        d.arrays.push_back(uploadSceneArray(context, desc, desc.bytes(scene)));
    return d;
}

DeviceScene uploadSceneAndRelease(GpuContext& context, PreparedScene& scene) {
    DeviceScene d = beginSceneUpload(context, scene);
    for (const SceneArrayDesc& desc : sceneArrayList()) {
        d.arrays.push_back(uploadSceneArray(context, desc, desc.bytes(scene)));
        desc.release(scene);
    }
    return d;
}

} // namespace vkpt
