// prepared_scene.h — the loaded scene in the layouts both executors consume: the BVH tree,
// its flattened nodes, triangles and normals in BVH order, materials and the emitter list.
#pragma once

#include <optional>
#include <vector>

#include "bvh/bvh_build.h"
#include "scene/scene.h"
#include "shared/host_device.h"

namespace vkpt {

struct PreparedScene {
    BvhTree tree;        // for the reference's stack traversal
    BvhStats bvhStats;   // with the build time
    std::vector<gpu::BvhNode> nodes;
    std::vector<gpu::Triangle> triangles;
    std::vector<gpu::TriangleNormals> normals;
    std::vector<gpu::Material> materials;
    std::vector<gpu::Emitter> emitters;
    double totalEmittedPower = 0.0;
};

struct PrepareOptions {
    BvhBuildOptions bvh;
    // Flatten so that the skip-link walk meets nearer children first along this direction:
    // the camera's forward direction makes camera rays walk near-first (docs/bvh.md).
    std::optional<glm::vec3> nearFirstDirection;
};

PreparedScene prepareScene(const Scene& scene, const PrepareOptions& options = {});

std::vector<gpu::Material> makeGpuMaterials(const std::vector<SceneMaterial>& materials);

// Triangles and shading normals in the order of tree.primitiveOrder.
void makeGpuTriangles(const Scene& scene, const BvhTree& tree,
                      std::vector<gpu::Triangle>& triangles,
                      std::vector<gpu::TriangleNormals>& normals);

} // namespace vkpt
