// prepared_scene.cpp — builds the BVH over the scene and lays the scene out for rendering.
#include "prepare/prepared_scene.h"

#include <chrono>

#include "bvh/bvh_flatten.h"
#include "common/errors.h"
#include "prepare/emitters.h"

namespace vkpt {

std::vector<gpu::Material> makeGpuMaterials(const std::vector<SceneMaterial>& materials) {
    std::vector<gpu::Material> result;
    result.reserve(materials.size());
    for (const SceneMaterial& m : materials) {
        gpu::Material g{};
        g.baseColor = m.baseColor;
        g.emission = m.emission;
        g.flags = m.doubleSided ? MATERIAL_DOUBLE_SIDED : 0u;
        g.metallic = m.metallic;
        g.roughness = m.roughness;
        g.alphaCutoff = m.alphaCutoff;
        g.alphaMode = std::uint32_t(m.alphaMode);
        result.push_back(g);
    }
    return result;
}

void makeGpuTriangles(const Scene& scene, const BvhTree& tree,
                      std::vector<gpu::Triangle>& triangles,
                      std::vector<gpu::TriangleNormals>& normals) {
    triangles.resize(tree.primitiveOrder.size());
    normals.resize(tree.primitiveOrder.size());
    for (std::size_t i = 0; i < tree.primitiveOrder.size(); ++i) {
        std::uint32_t source = tree.primitiveOrder[i];
        const glm::vec3* p = &scene.positions[3 * std::size_t(source)];
        const glm::vec3* n = &scene.normals[3 * std::size_t(source)];
        triangles[i] = {p[0], scene.materialIndices[source], p[1], NO_EMITTER, p[2], source};
        normals[i] = {glm::vec4(n[0], 0.0f), glm::vec4(n[1], 0.0f), glm::vec4(n[2], 0.0f)};
    }
}

PreparedScene prepareScene(const Scene& scene, const PrepareOptions& options) {
    VKPT_ASSERT(scene.positions.size() == 3 * scene.triangleCount(), "three vertices a triangle");
    VKPT_ASSERT(scene.triangleCount() < BVH_MAX_TRIANGLES, "triangle count fits a leaf word");
    PreparedScene prepared;
    auto start = std::chrono::steady_clock::now();
    prepared.tree = buildBvh(triangleBounds(scene.positions), options.bvh);
    std::chrono::duration<double> buildTime = std::chrono::steady_clock::now() - start;
    prepared.bvhStats = computeBvhStats(prepared.tree, options.bvh);
    prepared.bvhStats.buildSeconds = buildTime.count();
    prepared.nodes = flattenBvh(prepared.tree, {options.nearFirstDirection});
    makeGpuTriangles(scene, prepared.tree, prepared.triangles, prepared.normals);
    prepared.materials = makeGpuMaterials(scene.materials);
    EmitterList emitters = buildEmitters(prepared.triangles, prepared.materials);
    prepared.emitters = std::move(emitters.emitters);
    prepared.totalEmittedPower = emitters.totalPower;
    return prepared;
}

} // namespace vkpt
