// bvh_flatten.h — the built tree as the linear, stackless node array the GPU traverses.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "bvh/bvh_build.h"
#include "shared/host_device.h"

namespace vkpt {

// The one empty leaf of an empty tree. Its word must not be 0 (that marks an interior node),
// so it claims first triangle 1 with count 0: the kernel reads it as a leaf, tests no
// triangles and continues at missIndex = BVH_END.
inline constexpr std::uint32_t kEmptyLeafTriangles = 1u << BVH_LEAF_COUNT_BITS;

struct FlattenOptions {
    // The skip-link walk visits children in stored order, so it culls by the closest hit only
    // as well as that order is near-first for the ray. When set, each interior node stores
    // first the child whose centre lies nearer along this direction; pass the camera's forward
    // direction so that camera rays walk near-first (docs/bvh.md has the measurements). Unset:
    // the tree's left child first (lower coordinates along the split axis).
    std::optional<glm::vec3> nearFirstDirection;
};

// Depth-first order with skip links (see gpu::BvhNode). Leaf triangle ranges index the
// triangles in primitiveOrder order, i.e. the BVH-ordered triangle array; the child order
// does not change that array, so one triangle buffer serves every flattening of a tree.
std::vector<gpu::BvhNode> flattenBvh(const BvhTree& tree, const FlattenOptions& options = {});

} // namespace vkpt
