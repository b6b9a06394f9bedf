// device_scene.h — the prepared scene in device-local buffers, uploaded through staging
// buffers: the arrays of render/scene_arrays.h (BVH nodes, primitives, normals, tangents,
// texture coordinates, materials, textures and their texels, emitters and their CDF, the
// environment map and its CDF), each one buffer or, when larger than a binding, several. An empty
// array is not uploaded; its bindings get one shared 16-byte placeholder, which the kernels
// specialised for the scene never read (docs/wavefront.md).
#pragma once

#include <cstdint>
#include <vector>

#include "common/device_stats.h"
#include "gpu/buffer.h"
#include "prepare/prepared_scene.h"
#include "render/scene_arrays.h"
#include "render/wavefront_kernels.h"

namespace vkpt {

class GpuContext;

struct DeviceScene {
    // Bound wherever a kernel's binding has no data: Vulkan needs a valid descriptor for every
    // binding of a layout, and has no empty buffers.
    Buffer absentData;
    std::vector<SceneArray> arrays; // one per entry of sceneArrayList(), in its order
    std::uint32_t emitterCount = 0;
    gpu::EnvironmentParams environment{}; // for FrameParams::environment

    // Points every scene binding of `table` at its chunks, or at absentData.
    void bind(BufferTable& table) const;
    // The arrays uploaded, absentData first, each with the bytes of all its chunks.
    std::vector<SceneBufferBytes> bufferBytes() const;
    std::uint64_t totalBytes() const;
};

// Throws VulkanError naming the buffer and the device limit when one does not fit, and, before
// allocating anything, when the arrays together need more than the device-local heap has left.
// The arrays must be consistent with each other (texture coordinates for every primitive when a
// material has a texture, a CDF entry per emitter when there are several, a whole map when the
// environment has one): the kernels index them without bounds checks, so a mismatch is an
// internal error here rather than a hang there.
DeviceScene uploadScene(GpuContext& context, const PreparedScene& scene);

// uploadScene's checks and an empty DeviceScene (its placeholder made) for a caller that uploads
// the arrays itself (kept_scene.h); `onDevice` bytes of the scene's arrays are already on the
// device, kept from a frame before, and the memory check does not count them twice.
DeviceScene beginSceneUpload(GpuContext& context, const PreparedScene& scene,
                             std::uint64_t onDevice = 0);

// The same, freeing each array's host copy once it is on the device (vkpt's own path, where
// nothing on the host reads them again), so that the host holds the scene only once.
DeviceScene uploadSceneAndRelease(GpuContext& context, PreparedScene& scene);

} // namespace vkpt
