// gltf_origin.h — where the loaded scene's coordinates are measured from: the file's origin, or
// the centre of a scene that lies far from it relative to its size, found in double before any
// position is rounded to float (docs/numerical-stability.md, "Distance from the origin").
#pragma once

#include <optional>
#include <vector>

#include <glm/glm.hpp>
#include <tiny_gltf.h>

#include "scene/gltf_animation.h"
#include "scene/gltf_instancing_plan.h"
#include "scene/gltf_nodes.h"

namespace vkpt::gltf {

// A scene is recentred when a coordinate of its centre exceeds this many times its largest side:
// from there on, floats at the scene's place are at least 16 times coarser than the scene needs.
inline constexpr double kRecentreRatio = 16.0;

struct WorldExtent {
    glm::dvec3 min{0.0};
    glm::dvec3 max{0.0};

    glm::dvec3 centre() const { return 0.5 * (min + max); }
    double size() const; // the largest side
};

// Bounds of the default scene's vertex positions (for a mesh `plan` instances, the corners of
// its own box at each placement), spheres and point and spot lights in world space, in double.
// Tolerant by design: nullopt when the scene has no readable finite geometry or the file has a
// problem, which the loading pass that follows reports in its own words.
// Always at rest (the nodes as the file stores them), whatever the time a scene is posed at: the
// origin it chooses is then the same for every frame of an animation and for a still at any
// --time, so that nothing jumps from one frame to the next when the origin would have moved.
// A skinned mesh counts where its skin places it at rest: its own box placed by each joint's
// matrix (a box that holds every skinned vertex). A morphed mesh counts with every shape its
// weights can give it (an animation of its weights can move vertices out of the rest extent):
// each target's weight ranges over its weight at rest and every value `animations` give it
// (gltf_morph.h, morphWeightRanges), and each vertex adds the box of p + Σ wₜ·dₜ over those
// ranges.
std::optional<WorldExtent> worldExtent(const tinygltf::Model& model, int sceneIndex,
                                       const InstancingPlan& plan,
                                       const std::vector<Animation>& animations = {});

// The centre of `extent` when it lies beyond kRecentreRatio times the scene's size from the
// origin, else the origin.
glm::dvec3 chooseWorldOrigin(const WorldExtent& extent);

} // namespace vkpt::gltf
