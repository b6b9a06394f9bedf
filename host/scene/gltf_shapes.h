// gltf_shapes.h — analytic spheres: KHR_implicit_shapes sphere shapes that nodes place, rendered
// as spheres (the convention is spelled out in gltf_shapes.cpp and docs/scene-model.md).
#pragma once

#include <optional>

#include <glm/glm.hpp>
#include <tiny_gltf.h>

namespace vkpt::gltf {

// A sphere in world space, in double until the loader rounds it.
struct WorldSphere {
    glm::dvec3 centre{0.0};
    double radius = 0.0;
    int material = -1; // a glTF material index, -1 for the default material
};

// The sphere node `nodeIndex` places through `world`, nullopt when it places none (or its scale
// is zero on every axis, which disables a shape). Throws GltfProblem for a reference to a shape
// that does not exist, a radius that is not positive, a non-uniform scale, or a material that
// does not exist.
std::optional<WorldSphere> placeSphere(const tinygltf::Model& model, int nodeIndex,
                                       const glm::dmat4& world);

} // namespace vkpt::gltf
