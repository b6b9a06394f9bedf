// camera.cpp — picks the camera to render from (or frames the bounds) and builds the GPU record.
#include "scene/camera.h"

#include <cmath>
#include <iostream>
#include <numbers>

#include "common/errors.h"

namespace vkpt {
namespace {

constexpr float kFramingYfov = std::numbers::pi_v<float> / 4.0f; // 45 degrees

SceneCamera requestedCamera(const Scene& scene, int index) {
    if (index < 0 || static_cast<std::size_t>(index) >= scene.cameras.size()) {
        throw InputError(scene.sourcePath + ": camera " + std::to_string(index) +
                         " requested but the scene has " + std::to_string(scene.cameras.size()) +
                         " cameras");
    }
    return scene.cameras[static_cast<std::size_t>(index)];
}

} // namespace

SceneCamera selectCamera(const Scene& scene, std::optional<int> index, float aspect) {
    if (index) return requestedCamera(scene, *index);
    if (!scene.cameras.empty()) return scene.cameras.front();
    std::cerr << scene.sourcePath << ": no camera in the scene; framing its bounds from +Z\n";
    // Not value_or: its argument, a walk over every vertex, would be computed either way.
    return makeFramingCamera(scene.framingBounds ? *scene.framingBounds : computeBounds(scene),
                             aspect);
}

SceneCamera makeFramingCamera(const Bounds& bounds, float aspect) {
    VKPT_ASSERT(glm::all(glm::lessThanEqual(bounds.min, bounds.max)), "framing empty bounds");
    VKPT_ASSERT(aspect > 0.0f, "the aspect ratio must be positive");
    const glm::vec3 center = 0.5f * (bounds.min + bounds.max);
    float radius = 0.5f * glm::length(bounds.max - bounds.min);
    if (!(radius > 0.0f)) radius = 1.0f; // a single point: any distance shows it
    // A sphere of radius r seen from distance d fills a cone of half-angle asin(r / d).
    const float tanHalfY = std::tan(0.5f * kFramingYfov);
    const float halfFovMin = std::atan(std::min(tanHalfY, tanHalfY * aspect));
    SceneCamera camera;
    camera.name = "framing camera";
    camera.position = center + glm::vec3(0.0f, 0.0f, radius / std::sin(halfFovMin));
    camera.forward = glm::vec3(0.0f, 0.0f, -1.0f);
    camera.up = glm::vec3(0.0f, 1.0f, 0.0f);
    camera.yfov = kFramingYfov;
    return camera;
}

gpu::Camera makeGpuCamera(const SceneCamera& camera, std::uint32_t width, std::uint32_t height) {
    VKPT_ASSERT(width > 0 && height > 0, "the image must not be empty");
    const glm::vec3 forward = glm::normalize(camera.forward);
    const glm::vec3 right = glm::normalize(glm::cross(forward, camera.up));
    gpu::Camera gpuCamera{};
    gpuCamera.position = camera.position;
    gpuCamera.tanHalfFovY = std::tan(0.5f * camera.yfov); // unused by an orthographic camera
    gpuCamera.right = right;
    gpuCamera.aspect = static_cast<float>(width) / static_cast<float>(height);
    gpuCamera.up = glm::cross(right, forward); // unit, and exactly orthogonal to both
    gpuCamera.width = width;
    gpuCamera.forward = forward;
    gpuCamera.height = height;
    const bool orthographic = camera.projection == CameraProjection::Orthographic;
    gpuCamera.projection = orthographic ? CAMERA_ORTHOGRAPHIC : CAMERA_PERSPECTIVE;
    gpuCamera.orthoHalfHeight = orthographic ? camera.ymag : 0.0f;
    return gpuCamera;
}

} // namespace vkpt
