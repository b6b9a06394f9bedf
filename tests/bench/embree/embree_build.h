// embree_build.h — Embree 3's own BVH build over a triangle soup, timed, for bvh_build_bench to
// print beside vkpt's builder on the same triangles and threads. Benchmarks only.
#pragma once

#include <cstdint>
#include <span>

#include <glm/glm.hpp>

namespace vkpt::bench {

enum class EmbreeBuildQuality { Medium, High }; // Embree's default; embree-ref's

// Wall seconds of filling one triangle geometry (three vertices a triangle) and committing the
// scene, the same work embree-ref's EmbreeIntersectors::buildSeconds() times.
double embreeBuildSeconds(std::span<const glm::vec3> positions, EmbreeBuildQuality quality,
                          std::uint32_t threads);

} // namespace vkpt::bench
