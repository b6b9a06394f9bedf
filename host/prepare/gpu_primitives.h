// gpu_primitives.h — the scene's triangles and spheres as one primitive list for the BVH:
// their bounds for the build, and their records, normals, texture coordinates and tangents in the
// BVH's leaf order. Primitive p < triangleCount is triangle p; above, sphere p − triangleCount.
#pragma once

#include <vector>

#include "bvh/bvh_build.h"
#include "scene/scene.h"
#include "shared/host_device.h"

namespace vkpt {

std::vector<Aabb> primitiveBounds(const Scene& scene);

struct GpuPrimitives {
    std::vector<gpu::Triangle> records;
    std::vector<gpu::TriangleNormals> normals;
    std::vector<glm::vec2> uvs;                  // 3 per record, when asked for
    std::vector<gpu::TriangleTangents> tangents; // 1 per record, when asked for
};

// withUvs: fill uvs from Scene::texcoords ((0, 0) for spheres and when the scene has none).
// withTangents: fill tangents from Scene::tangents (zero, no frame, for spheres and when the
// scene has none).
GpuPrimitives makeGpuPrimitives(const Scene& scene, const BvhTree& tree, bool withUvs,
                                bool withTangents = false);

} // namespace vkpt
