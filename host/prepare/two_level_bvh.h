// two_level_bvh.h — the layout of a scene with instances (docs/scene-model.md, "Instancing"): a
// bottom-level BVH per stored mesh and one for the world's own geometry (its flattened
// placements and spheres), a top-level BVH over the instances' world boxes, and the device arrays
// of all of them: one node array (top level first, so the walk starts at node 0) and one
// primitive array (the world's own first, so emitters index it as in a single-level scene).
#pragma once

#include "prepare/prepared_scene.h"

namespace vkpt {

// Fills prepared.meshes, instanceTree, instances, nodes and the primitive arrays (triangles,
// normals, uvs and tangents, as withUvs and withTangents ask), and bvhStats.
void prepareTwoLevel(const Scene& scene, const PrepareOptions& options, bool withUvs,
                     bool withTangents, PreparedScene& prepared);

// The instance record of a placement by objectToWorld of the tree whose root is node `root`
// (its inverse computed in double, both rounded to float once); `material` replaces every
// triangle's (INSTANCE_OWN_MATERIALS: none does).
gpu::Instance makeGpuInstance(const glm::dmat4& objectToWorld, std::uint32_t root,
                              std::uint32_t mesh, std::uint32_t material = INSTANCE_OWN_MATERIALS);

// A float box that holds `own` placed by objectToWorld: the eight corners transformed in double,
// then widened by one float step on each side for the rounding.
Aabb placedBounds(const Aabb& own, const glm::dmat4& objectToWorld);

} // namespace vkpt
