// gpu_primitives.cpp — triangles and spheres in BVH order.
#include "prepare/gpu_primitives.h"

namespace vkpt {

std::vector<Aabb> primitiveBounds(const TriangleSoup& soup, std::span<const SceneSphere> spheres) {
    std::vector<Aabb> bounds = triangleBounds(soup.positions);
    bounds.reserve(bounds.size() + spheres.size());
    for (const SceneSphere& sphere : spheres) {
        Aabb box;
        box.extend(sphere.centre - glm::vec3(sphere.radius));
        box.extend(sphere.centre + glm::vec3(sphere.radius));
        bounds.push_back(box);
    }
    return bounds;
}

std::vector<Aabb> primitiveBounds(const Scene& scene) {
    return primitiveBounds(scene, scene.spheres);
}

GpuPrimitives makeGpuPrimitives(const TriangleSoup& soup, std::span<const SceneSphere> spheres,
                                std::span<const SceneMaterial> materials, const BvhTree& tree,
                                bool withUvs, bool withTangents) {
    const std::size_t count = tree.primitiveOrder.size();
    const std::size_t triangleCount = soup.triangleCount();
    const bool haveTexcoords = soup.texcoords.size() == 3 * triangleCount;
    const bool haveTangents = soup.tangents.size() == 3 * triangleCount;
    GpuPrimitives result;
    result.records.resize(count);
    result.normals.resize(count);
    if (withUvs) result.uvs.assign(3 * count, glm::vec2(0.0f));
    if (withTangents) result.tangents.assign(count, gpu::TriangleTangents{});
    for (std::size_t i = 0; i < count; ++i) {
        const std::uint32_t source = tree.primitiveOrder[i];
        if (source >= triangleCount) {
            const std::uint32_t sphereIndex = source - std::uint32_t(triangleCount);
            const SceneSphere& sphere = spheres[sphereIndex];
            result.records[i] = {sphere.centre, sphere.material, glm::vec3(sphere.radius, 0, 0),
                                 NO_EMITTER,    glm::vec3(0.0f), sphereIndex | PRIMITIVE_SPHERE};
            result.normals[i] = {};
            continue;
        }
        const glm::vec3* p = &soup.positions[3 * std::size_t(source)];
        const glm::vec3* n = &soup.normals[3 * std::size_t(source)];
        result.records[i] = {p[0], soup.materialIndices[source], p[1], NO_EMITTER, p[2], source};
        result.normals[i] = {glm::vec4(n[0], 0.0f), glm::vec4(n[1], 0.0f), glm::vec4(n[2], 0.0f)};
        if (withUvs && haveTexcoords)
            for (std::size_t k = 0; k < 3; ++k)
                result.uvs[3 * i + k] = soup.texcoords[3 * std::size_t(source) + k];
        if (withTangents && haveTangents) {
            const glm::vec4* t = &soup.tangents[3 * std::size_t(source)];
            result.tangents[i] = {t[0], t[1], t[2]};
        }
    }
    for (gpu::Triangle& record : result.records)
        if (materials[record.materialIndex].alphaMode == AlphaMode::Mask)
            record.sourceIndex |= PRIMITIVE_ALPHA_MASKED;
    return result;
}

GpuPrimitives makeGpuPrimitives(const Scene& scene, const BvhTree& tree, bool withUvs,
                                bool withTangents) {
    return makeGpuPrimitives(scene, scene.spheres, scene.materials, tree, withUvs, withTangents);
}

} // namespace vkpt
