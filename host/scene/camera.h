// camera.h — picks the scene's camera (or frames the bounds) and turns it into the GPU layout.
#pragma once

#include <optional>

#include "scene/scene.h"
#include "shared/host_device.h"

namespace vkpt {

// The camera to render from: scene.cameras[index] when given (InputError if out of range),
// else the first camera, else a default one that frames the scene bounds from the +Z side
// (and says so in one line on stderr). aspect (image width / height) only matters for that default
// one: it must fit the bounds into the narrower field of view, which is the vertical one
// for aspect >= 1.
SceneCamera selectCamera(const Scene& scene, std::optional<int> index, float aspect = 1.0f);

// A camera with yfov 45 degrees on the +Z side of the bounds, looking down -Z with +Y up, at the
// distance where the bounding sphere just fits the narrower field of view.
SceneCamera makeFramingCamera(const Bounds& bounds, float aspect);

// Image width/height sets the horizontal field of view (perspective) or extent
// (orthographic); yfov or ymag is kept.
gpu::Camera makeGpuCamera(const SceneCamera& camera, std::uint32_t width, std::uint32_t height);

} // namespace vkpt
