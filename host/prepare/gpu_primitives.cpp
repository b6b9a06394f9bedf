// gpu_primitives.cpp — triangles and spheres in BVH order.
#include "prepare/gpu_primitives.h"

namespace vkpt {

std::vector<Aabb> primitiveBounds(const Scene& scene) {
    std::vector<Aabb> bounds = triangleBounds(scene.positions);
    bounds.reserve(bounds.size() + scene.spheres.size());
    for (const SceneSphere& sphere : scene.spheres) {
        Aabb box;
        box.extend(sphere.centre - glm::vec3(sphere.radius));
        box.extend(sphere.centre + glm::vec3(sphere.radius));
        bounds.push_back(box);
    }
    return bounds;
}

GpuPrimitives makeGpuPrimitives(const Scene& scene, const BvhTree& tree, bool withUvs,
                                bool withTangents) {
    const std::size_t count = tree.primitiveOrder.size();
    const std::size_t triangleCount = scene.triangleCount();
    const bool haveTexcoords = scene.texcoords.size() == 3 * triangleCount;
    const bool haveTangents = scene.tangents.size() == 3 * triangleCount;
    GpuPrimitives result;
    result.records.resize(count);
    result.normals.resize(count);
    if (withUvs) result.uvs.assign(3 * count, glm::vec2(0.0f));
    if (withTangents) result.tangents.assign(count, gpu::TriangleTangents{});
    for (std::size_t i = 0; i < count; ++i) {
        const std::uint32_t source = tree.primitiveOrder[i];
        if (source >= triangleCount) {
            const std::uint32_t sphereIndex = source - std::uint32_t(triangleCount);
            const SceneSphere& sphere = scene.spheres[sphereIndex];
            result.records[i] = {sphere.centre, sphere.material, glm::vec3(sphere.radius, 0, 0),
                                 NO_EMITTER,    glm::vec3(0.0f), sphereIndex | PRIMITIVE_SPHERE};
            result.normals[i] = {};
            continue;
        }
        const glm::vec3* p = &scene.positions[3 * std::size_t(source)];
        const glm::vec3* n = &scene.normals[3 * std::size_t(source)];
        result.records[i] = {p[0], scene.materialIndices[source], p[1], NO_EMITTER, p[2], source};
        result.normals[i] = {glm::vec4(n[0], 0.0f), glm::vec4(n[1], 0.0f), glm::vec4(n[2], 0.0f)};
        if (withUvs && haveTexcoords)
            for (std::size_t k = 0; k < 3; ++k)
                result.uvs[3 * i + k] = scene.texcoords[3 * std::size_t(source) + k];
        if (withTangents && haveTangents) {
            const glm::vec4* t = &scene.tangents[3 * std::size_t(source)];
            result.tangents[i] = {t[0], t[1], t[2]};
        }
    }
    for (gpu::Triangle& record : result.records)
        if (scene.materials[record.materialIndex].alphaMode == AlphaMode::Mask)
            record.sourceIndex |= PRIMITIVE_ALPHA_MASKED;
    return result;
}

} // namespace vkpt
