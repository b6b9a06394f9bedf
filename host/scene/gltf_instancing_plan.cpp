// gltf_instancing_plan.cpp — counts each mesh's placements and triangles without reading a vertex,
// and applies the instancing rule.
#include "scene/gltf_instancing_plan.h"

#include <cstdint>
#include <map>

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

int attributeAccessor(const tinygltf::Primitive& primitive, const char* name) {
    const auto found = primitive.attributes.find(name);
    return found == primitive.attributes.end() ? -1 : found->second;
}

// Whether a group of `placements` placements of `triangles` triangles is kept once.
bool instances(std::uint64_t placements, std::uint64_t triangles, Instancing mode) {
    if (placements == 0 || triangles == 0) return false;
    switch (mode) {
    case Instancing::On:
        return true;
    case Instancing::Off:
        return false;
    case Instancing::Auto:
        break;
    }
    if (placements < kInstancingMinPlacements) return false;
    const std::uint64_t flattened =
        saturatingMultiply(saturatingMultiply(placements, triangles), kBytesPerPlacedTriangle);
    const std::uint64_t kept = saturatingAdd(saturatingMultiply(triangles, kBytesPerPlacedTriangle),
                                             saturatingMultiply(placements, kBytesPerInstance));
    return flattened > kept && flattened - kept >= kInstancingMinSavedBytes;
}

} // namespace

std::vector<std::int64_t> geometryKey(const tinygltf::Model& model, int mesh,
                                      const std::vector<SceneMaterial>& materials) {
    const tinygltf::Mesh& source = model.meshes[static_cast<std::size_t>(mesh)];
    std::vector<std::int64_t> key;
    std::vector<std::int64_t> keptMaterials;
    for (const tinygltf::Primitive& primitive : source.primitives) {
        const int material = primitive.material;
        const bool known = material >= 0 && static_cast<std::size_t>(material) < materials.size();
        if (known && materials[static_cast<std::size_t>(material)].emits()) continue;
        const bool normalMapped =
            known && materials[static_cast<std::size_t>(material)].hasNormalMap();
        const bool masked =
            known && materials[static_cast<std::size_t>(material)].alphaMode == AlphaMode::Mask;
        key.insert(key.end(),
                   {primitive.mode, primitive.indices, attributeAccessor(primitive, "POSITION"),
                    attributeAccessor(primitive, "NORMAL"),
                    attributeAccessor(primitive, "TEXCOORD_0"),
                    attributeAccessor(primitive, "TANGENT"), normalMapped ? 1 : 0, masked ? 1 : 0});
        // Morph targets and compressed data: not compared, the mesh's own; an unknown material
        // (the loader names it): the same.
        if (!primitive.targets.empty() || !primitive.extensions.empty() ||
            (material != -1 && !known))
            key.push_back(-2 - std::int64_t(mesh));
        keptMaterials.push_back(material);
    }
    if (keptMaterials.size() > 1) key.insert(key.end(), keptMaterials.begin(), keptMaterials.end());
    return key;
}

InstancingPlan planInstancing(const tinygltf::Model& model, int sceneIndex, Instancing mode,
                              const std::vector<SceneMaterial>& materials) {
    const std::size_t meshCount = model.meshes.size();
    InstancingPlan plan;
    plan.instanced.assign(meshCount, 0);
    plan.geometry.assign(meshCount, -1);
    plan.placements.assign(meshCount, 0);
    plan.meshTriangles.assign(meshCount, 0);
    std::map<std::vector<std::int64_t>, int> firstOfGeometry;
    for (std::size_t m = 0; m < meshCount; ++m) {
        plan.meshTriangles[m] = meshTriangleCount(model, model.meshes[m]);
        std::vector<std::int64_t> key = geometryKey(model, static_cast<int>(m), materials);
        if (key.empty()) continue;
        plan.geometry[m] =
            firstOfGeometry.try_emplace(std::move(key), static_cast<int>(m)).first->second;
    }
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
    std::vector<std::uint64_t> geometryPlacements(meshCount, 0);
    for (std::size_t m = 0; m < meshCount; ++m) {
        plan.placedTriangles = saturatingAdd(
            plan.placedTriangles, saturatingMultiply(plan.placements[m], plan.meshTriangles[m]));
        if (plan.geometry[m] >= 0) {
            std::uint64_t& count = geometryPlacements[static_cast<std::size_t>(plan.geometry[m])];
            count = saturatingAdd(count, plan.placements[m]);
        }
    }
    for (std::size_t m = 0; m < meshCount; ++m) {
        if (plan.geometry[m] < 0 || plan.placements[m] == 0) continue;
        const auto first = static_cast<std::size_t>(plan.geometry[m]);
        plan.instanced[m] =
            instances(geometryPlacements[first], plan.meshTriangles[first], mode) ? 1 : 0;
    }
    return plan;
}

} // namespace vkpt::gltf
