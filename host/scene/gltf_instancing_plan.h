// gltf_instancing_plan.h — which glTF meshes the loader keeps once, in their own space, and places
// by instances, and which it flattens into world space at every placement (docs/scene-model.md,
// "Instancing"). Decided before any vertex is read, from the node tree and accessor counts.
#pragma once

#include <cstdint>
#include <vector>

#include <tiny_gltf.h>

#include "common/render_settings.h"
#include "scene/scene.h"

namespace vkpt::gltf {

// The rule of Instancing::Auto (docs/scene-model.md, "When to instance"): a geometry placed at
// least kInstancingMinPlacements times is kept once when that saves at least
// kInstancingMinSavedBytes of scene arrays, counted as kBytesPerPlacedTriangle per flattened
// triangle (measured: device bytes of the flattened field over its triangles) against
// kBytesPerInstance per placement (the 112-byte record and its top-level node). Below that
// saving a flattened scene is small, and it renders at least as fast without the second level.
inline constexpr std::uint64_t kInstancingMinPlacements = 2;
inline constexpr std::uint64_t kInstancingMinSavedBytes = std::uint64_t(1) << 20;
inline constexpr std::uint64_t kBytesPerPlacedTriangle = 115;
inline constexpr std::uint64_t kBytesPerInstance = 176;

struct InstancingPlan {
    std::vector<char> instanced; // per glTF mesh
    // Per glTF mesh: the first mesh of the same geometry ("Shared geometry": the same index and
    // vertex accessors of its kept primitives), whose copy every mesh of the group places; -1
    // when the mesh keeps nothing (no triangles, or all of them emit).
    std::vector<int> geometry;
    std::vector<std::uint64_t> placements;    // per glTF mesh: nodes and EXT instances placing it
    std::vector<std::uint64_t> meshTriangles; // per glTF mesh, estimated from accessor counts
    std::uint64_t placedTriangles = 0;        // Σ placements × triangles

    bool isInstanced(int mesh) const {
        return mesh >= 0 && static_cast<std::size_t>(mesh) < instanced.size() &&
               instanced[static_cast<std::size_t>(mesh)] != 0;
    }
    // The mesh whose kept copy places `mesh` (itself unless its geometry is shared).
    int geometryOf(int mesh) const { return geometry[static_cast<std::size_t>(mesh)]; }
};

// The kept primitives of glTF mesh `mesh` as the geometry they give the BVH and shading, for
// comparing meshes: per primitive that does not emit its mode, index accessor, POSITION, NORMAL,
// TEXCOORD_0 and TANGENT accessors, whether its material is normal-mapped (tangents) and
// whether it is alpha-masked (the triangle's mark that the walk tests it); and the materials when
// more than one primitive is kept (an instance replaces one material only). A
// primitive with morph targets or extensions (compressed data) makes the key the mesh's own.
// Empty when nothing is kept. `materials` are the file's, by glTF index.
std::vector<std::int64_t> geometryKey(const tinygltf::Model& model, int mesh,
                                      const std::vector<SceneMaterial>& materials);

// The plan for the default scene `sceneIndex` under `mode`; meshes of one geometry are one
// group, counted and decided together. Tolerant: a node tree the loading
// walk will reject gets a plan that instances nothing, and that walk names the problem.
InstancingPlan planInstancing(const tinygltf::Model& model, int sceneIndex, Instancing mode,
                              const std::vector<SceneMaterial>& materials);

} // namespace vkpt::gltf
