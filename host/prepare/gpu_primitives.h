// gpu_primitives.h — a triangle soup's triangles and the scene's spheres as one primitive list
// for the BVH: their bounds for the build, and their records, normals, texture coordinates and
// tangents in the BVH's leaf order. Primitive p < triangleCount is triangle p; above, sphere
// p − triangleCount.
#pragma once

#include <span>
#include <vector>

#include "bvh/bvh_build.h"
#include "scene/scene.h"
#include "shared/host_device.h"

namespace vkpt {

std::vector<Aabb> primitiveBounds(const TriangleSoup& soup, std::span<const SceneSphere> spheres);

// The scene's own geometry: its soup and its spheres.
std::vector<Aabb> primitiveBounds(const Scene& scene);

struct GpuPrimitives {
    std::vector<gpu::Triangle> records;
    std::vector<gpu::TriangleNormals> normals;
    std::vector<glm::vec2> uvs;                  // 3 per record, when asked for
    std::vector<gpu::TriangleTangents> tangents; // 1 per record, when asked for
};

// withUvs: fill uvs from the soup's texcoords ((0, 0) for spheres and when the soup has none).
// withTangents: fill tangents from the soup's tangents (zero, no frame, for spheres and when the
// soup has none). Materials mark alpha-masked primitives (PRIMITIVE_ALPHA_MASKED).
GpuPrimitives makeGpuPrimitives(const TriangleSoup& soup, std::span<const SceneSphere> spheres,
                                std::span<const SceneMaterial> materials, const BvhTree& tree,
                                bool withUvs, bool withTangents = false);

// The scene's own geometry: its soup and its spheres.
GpuPrimitives makeGpuPrimitives(const Scene& scene, const BvhTree& tree, bool withUvs,
                                bool withTangents = false);

} // namespace vkpt
