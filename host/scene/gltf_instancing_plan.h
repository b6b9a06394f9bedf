// gltf_instancing_plan.h — which glTF meshes the loader keeps once, in their own space, and places
// by instances, and which it flattens into world space at every placement (docs/scene-model.md,
// "Instancing"). Decided before any vertex is read, from the node tree and accessor counts.
#pragma once

#include <cstdint>
#include <vector>

#include <tiny_gltf.h>

#include "common/render_settings.h"

namespace vkpt::gltf {

// The measured rule of Instancing::Auto (docs/scene-model.md, "When to instance"): a scene that
// places fewer triangles than this renders faster flattened, and a mesh placed fewer times than
// kInstancingMinPlacements saves too little to pay for its second level of BVH.
inline constexpr std::uint64_t kInstancingMinPlacedTriangles = std::uint64_t(1) << 22;
inline constexpr std::uint64_t kInstancingMinPlacements = 2;

struct InstancingPlan {
    std::vector<char> instanced;              // per glTF mesh
    std::vector<std::uint64_t> placements;    // per glTF mesh: nodes and EXT instances placing it
    std::vector<std::uint64_t> meshTriangles; // per glTF mesh, estimated from accessor counts
    std::uint64_t placedTriangles = 0;        // Σ placements × triangles

    bool isInstanced(int mesh) const {
        return mesh >= 0 && static_cast<std::size_t>(mesh) < instanced.size() &&
               instanced[static_cast<std::size_t>(mesh)] != 0;
    }
};

// The plan for the default scene `sceneIndex` under `mode`. Tolerant: a node tree the loading
// walk will reject gets a plan that instances nothing, and that walk names the problem.
InstancingPlan planInstancing(const tinygltf::Model& model, int sceneIndex, Instancing mode);

} // namespace vkpt::gltf
