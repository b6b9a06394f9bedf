// device_scene.h — the prepared scene in device-local storage buffers, uploaded through
// staging buffers: one buffer per array the scene has (BVH nodes, primitives, normals, tangents,
// texture coordinates, materials, textures and their texels, emitters and their CDF, the
// environment map and its CDF). An empty array is not uploaded; its bindings get one shared 16-byte
// placeholder, which the kernels specialised for the scene never read (docs/wavefront.md).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "common/device_stats.h"
#include "gpu/buffer.h"
#include "prepare/prepared_scene.h"
#include "render/wavefront_kernels.h"

namespace vkpt {

class GpuContext;

struct DeviceScene {
    // Bound wherever a kernel's binding has no data: Vulkan needs a valid descriptor for every
    // binding of a layout, and has no empty buffers.
    Buffer absentData;
    std::optional<Buffer> bvhNodes{};
    std::optional<Buffer> triangles{}; // triangles and spheres
    std::optional<Buffer> triangleNormals{};
    std::optional<Buffer> triangleTangents{}; // normal maps only
    std::optional<Buffer> triangleUvs{};
    std::optional<Buffer> materials{};
    std::optional<Buffer> textures{};
    std::optional<Buffer> textureTexels{};
    std::optional<Buffer> emitters{};
    std::optional<Buffer> emitterCdf{};
    std::optional<Buffer> environmentTexels{};
    std::optional<Buffer> environmentCdf{};
    std::uint32_t emitterCount = 0;
    gpu::EnvironmentParams environment{}; // for FrameParams::environment

    // Points every scene binding of `table` at its buffer, or at absentData.
    void bind(BufferTable& table) const;
    // The buffers uploaded, absentData included, in binding order.
    std::vector<SceneBufferBytes> bufferBytes() const;
    std::uint64_t totalBytes() const;
};

// Throws VulkanError naming the buffer and the device limit when one does not fit.
// The arrays must be consistent with each other (texture coordinates for every primitive when a
// material has a texture, a CDF entry per emitter when there are several, a whole map when the
// environment has one): the kernels index them without bounds checks, so a mismatch is an
// internal error here rather than a hang there.
DeviceScene uploadScene(GpuContext& context, const PreparedScene& scene);

} // namespace vkpt
