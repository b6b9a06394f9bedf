// device_scene.cpp — one named storage buffer per non-empty array of the prepared scene.
#include "render/device_scene.h"

#include <span>
#include <string>
#include <vector>

#include "common/errors.h"
#include "gpu/upload.h"
#include "lib/wavefront.h"

namespace vkpt {

namespace {

constexpr VkDeviceSize kAbsentDataBytes = 16;

template <typename T>
std::optional<Buffer> uploadArray(GpuContext& context, std::string name,
                                  const std::vector<T>& values,
                                  VkBufferUsageFlags usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT) {
    if (values.empty()) return std::nullopt;
    return createBufferWithData(context, std::move(name), usage, std::span<const T>(values));
}

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

// Each scene binding and the DeviceScene member holding its buffer, in binding order.
struct SceneBinding {
    std::uint32_t binding;
    std::optional<Buffer> DeviceScene::*buffer;
};

constexpr SceneBinding kSceneBindings[] = {
    {BINDING_BVH_NODES, &DeviceScene::bvhNodes},
    {BINDING_TRIANGLES, &DeviceScene::triangles},
    {BINDING_TRIANGLE_NORMALS, &DeviceScene::triangleNormals},
    {BINDING_TRIANGLE_TANGENTS, &DeviceScene::triangleTangents},
    {BINDING_MATERIALS, &DeviceScene::materials},
    {BINDING_EMITTERS, &DeviceScene::emitters},
    {BINDING_TRIANGLE_UVS, &DeviceScene::triangleUvs},
    {BINDING_TEXTURES, &DeviceScene::textures},
    {BINDING_TEXTURE_TEXELS, &DeviceScene::textureTexels},
    {BINDING_EMITTER_CDF, &DeviceScene::emitterCdf},
    {BINDING_ENVIRONMENT_TEXELS, &DeviceScene::environmentTexels},
    {BINDING_ENVIRONMENT_CDF, &DeviceScene::environmentCdf},
};

} // namespace

void DeviceScene::bind(BufferTable& table) const {
    for (const SceneBinding& b : kSceneBindings) {
        const std::optional<Buffer>& buffer = this->*b.buffer;
        table.set(b.binding, buffer ? *buffer : absentData);
    }
}

std::vector<SceneBufferBytes> DeviceScene::bufferBytes() const {
    std::vector<SceneBufferBytes> result{{absentData.name(), absentData.allocationSize()}};
    for (const SceneBinding& b : kSceneBindings) {
        const std::optional<Buffer>& buffer = this->*b.buffer;
        if (buffer) result.push_back({buffer->name(), buffer->allocationSize()});
    }
    return result;
}

std::uint64_t DeviceScene::totalBytes() const {
    std::uint64_t total = 0;
    for (const SceneBufferBytes& buffer : bufferBytes())
        total += buffer.bytes;
    return total;
}

DeviceScene uploadScene(GpuContext& context, const PreparedScene& scene) {
    checkScene(scene);
    DeviceScene d{makeAbsentData(context)};
    // Records of 16-byte multiples are fetched as texels (lib/records.glsl), the rest read as
    // storage buffers (lib/kernel_bindings.h).
    constexpr VkBufferUsageFlags texels = VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT;
    d.bvhNodes = uploadArray(context, "bvhNodes", scene.nodes, texels);
    d.triangles = uploadArray(context, "triangles", scene.triangles, texels);
    d.triangleNormals = uploadArray(context, "triangleNormals", scene.normals, texels);
    d.triangleTangents = uploadArray(context, "triangleTangents", scene.tangents, texels);
    d.triangleUvs = uploadArray(context, "triangleUvs", scene.uvs);
    d.materials = uploadArray(context, "materials", scene.materials, texels);
    d.textures = uploadArray(context, "textures", scene.textures, texels);
    d.textureTexels = uploadArray(context, "textureTexels", scene.texels);
    d.emitters = uploadArray(context, "emitters", scene.emitters, texels);
    d.emitterCdf = uploadArray(context, "emitterCdf", scene.emitterCdf);
    d.environmentTexels = uploadArray(context, "environmentTexels", scene.environmentTexels);
    d.environmentCdf = uploadArray(context, "environmentCdf", scene.environmentCdf);
    d.emitterCount = static_cast<std::uint32_t>(scene.emitters.size());
    d.environment = scene.environment;
    return d;
}

} // namespace vkpt
