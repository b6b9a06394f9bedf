// emission_mean.h — what an emitting triangle sends out on average: its emissive factor times
// its emissive texture averaged over it. One definition for the power light sampling weighs an
// emitter by (emitters.h) and for whether a scene lights itself (scene_lighting.h).
#pragma once

#include <cstddef>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace vkpt {

// Scene triangle `triangle`'s emitted radiance averaged over its surface: the emissive factor,
// times the texture's mean over the triangle when it has one (the centroids of the k² equal
// sub-triangles that cutting each edge into k makes, k from 1 to 8 as the texels the triangle
// covers grow, each read at the nearest texel with the material's transform and wrap modes).
// A triangle whose every point reads black gets 0 however bright its factor.
glm::vec3 meanTriangleEmission(const Scene& scene, std::size_t triangle);

} // namespace vkpt
