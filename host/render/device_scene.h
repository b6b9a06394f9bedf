// device_scene.h — the prepared scene in device-local storage buffers, uploaded through
// staging buffers: BVH nodes, triangles, normals, materials and emitters (with their CDF).
#pragma once

#include <cstdint>

#include "gpu/buffer.h"
#include "prepare/prepared_scene.h"

namespace vkpt {

class GpuContext;

struct DeviceScene {
    Buffer bvhNodes;
    Buffer triangles;
    Buffer triangleNormals;
    Buffer materials;
    Buffer emitters; // one unused record when the scene has none (Vulkan has no empty buffers)
    std::uint32_t nodeCount = 0;
    std::uint32_t emitterCount = 0;
};

// Throws VulkanError naming the buffer and the device limit when one does not fit.
DeviceScene uploadScene(GpuContext& context, const PreparedScene& scene);

} // namespace vkpt
