// gltf_instancing_plan.cpp — counts each mesh's placements and triangles without reading a vertex,
// and applies the instancing rule.
#include "scene/gltf_instancing_plan.h"

#include <cstdint>

#include "scene/gltf_document.h"
#include "scene/gltf_mesh_instancing.h"
#include "scene/gltf_nodes.h"

namespace vkpt::gltf {
namespace {

// Counts come from the file unchecked: sums and products saturate rather than wrap.
std::uint64_t saturatingAdd(std::uint64_t a, std::uint64_t b) {
    return a > UINT64_MAX - b ? UINT64_MAX : a + b;
}

std::uint64_t saturatingMultiply(std::uint64_t a, std::uint64_t b) {
    return b != 0 && a > UINT64_MAX / b ? UINT64_MAX : a * b;
}

std::uint64_t accessorCount(const tinygltf::Model& model, int accessor) {
    if (accessor < 0 || static_cast<std::size_t>(accessor) >= model.accessors.size()) return 0;
    return model.accessors[static_cast<std::size_t>(accessor)].count;
}

// Triangles of a TRIANGLES primitive: its index count / 3, or its vertex count / 3 when it has no
// index accessor (a Draco primitive's indices are inside the compressed data: an estimate then).
std::uint64_t primitiveTriangles(const tinygltf::Model& model,
                                 const tinygltf::Primitive& primitive) {
    if (primitive.mode != TINYGLTF_MODE_TRIANGLES) return 0;
    if (primitive.indices >= 0) return accessorCount(model, primitive.indices) / 3;
    const auto position = primitive.attributes.find("POSITION");
    if (position == primitive.attributes.end()) return 0;
    return accessorCount(model, position->second) / 3;
}

std::uint64_t meshTriangleCount(const tinygltf::Model& model, const tinygltf::Mesh& mesh) {
    std::uint64_t count = 0;
    for (const tinygltf::Primitive& primitive : mesh.primitives)
        count = saturatingAdd(count, primitiveTriangles(model, primitive));
    return count;
}

bool instances(const InstancingPlan& plan, std::size_t mesh, Instancing mode) {
    if (plan.placements[mesh] == 0 || plan.meshTriangles[mesh] == 0) return false;
    switch (mode) {
    case Instancing::On:
        return true;
    case Instancing::Off:
        return false;
    case Instancing::Auto:
        break;
    }
    return plan.placedTriangles >= kInstancingMinPlacedTriangles &&
           plan.placements[mesh] >= kInstancingMinPlacements;
}

} // namespace

InstancingPlan planInstancing(const tinygltf::Model& model, int sceneIndex, Instancing mode) {
    const std::size_t meshCount = model.meshes.size();
    InstancingPlan plan;
    plan.instanced.assign(meshCount, 0);
    plan.placements.assign(meshCount, 0);
    plan.meshTriangles.assign(meshCount, 0);
    for (std::size_t m = 0; m < meshCount; ++m)
        plan.meshTriangles[m] = meshTriangleCount(model, model.meshes[m]);
    try {
        walkSceneNodes(model, sceneIndex, [&](int node, const glm::dmat4&) {
            const int mesh = model.nodes[static_cast<std::size_t>(node)].mesh;
            if (mesh < 0 || static_cast<std::size_t>(mesh) >= meshCount) return;
            std::uint64_t& placements = plan.placements[static_cast<std::size_t>(mesh)];
            placements = saturatingAdd(placements, meshPlacementCount(model, node));
        });
    } catch (const GltfProblem&) {
        return plan; // the loading walk names the problem
    }
    for (std::size_t m = 0; m < meshCount; ++m)
        plan.placedTriangles = saturatingAdd(
            plan.placedTriangles, saturatingMultiply(plan.placements[m], plan.meshTriangles[m]));
    for (std::size_t m = 0; m < meshCount; ++m)
        plan.instanced[m] = instances(plan, m, mode) ? 1 : 0;
    return plan;
}

} // namespace vkpt::gltf
