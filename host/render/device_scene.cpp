// device_scene.cpp — one named storage buffer per array of the prepared scene.
#include "render/device_scene.h"

#include <string>
#include <vector>

#include "common/errors.h"
#include "gpu/upload.h"

namespace vkpt {

namespace {

template <typename T>
Buffer uploadArray(GpuContext& context, std::string name, const std::vector<T>& values) {
    VKPT_ASSERT(!values.empty(), "scene array '" + name + "' is empty");
    return createBufferWithData(context, std::move(name), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                std::span<const T>(values));
}

std::vector<gpu::Emitter> emittersOrPlaceholder(const std::vector<gpu::Emitter>& emitters) {
    if (!emitters.empty()) return emitters;
    return {gpu::Emitter{0u, 0.0f, 0.0f, 1.0f}}; // never read: frame.emitterCount is 0
}

} // namespace

DeviceScene uploadScene(GpuContext& context, const PreparedScene& scene) {
    return DeviceScene{uploadArray(context, "bvhNodes", scene.nodes),
                       uploadArray(context, "triangles", scene.triangles),
                       uploadArray(context, "triangleNormals", scene.normals),
                       uploadArray(context, "materials", scene.materials),
                       uploadArray(context, "emitters", emittersOrPlaceholder(scene.emitters)),
                       static_cast<std::uint32_t>(scene.nodes.size()),
                       static_cast<std::uint32_t>(scene.emitters.size())};
}

} // namespace vkpt
