// light_tree.h — builds the light BVH that shared/light_tree.h walks: a binary tree over the
// emitters of the power table, each node bounding the positions, emission directions (a cone of
// normals θo and a spread θe about each) and total power of the emitters below it.
#pragma once

#include <span>
#include <vector>

#include "shared/host_device.h"

namespace vkpt {

// Emitters with power 0 (a black emissive texture, say) get a leaf without a parent and are
// never chosen. Finite emitters (triangles, spheres, point and spot lights) form a tree split by
// pbrt-v4's light-BVH cost (section 12.6.3: power × orientation measure × surface area × an
// aspect term, over 12 buckets per axis); infinite ones (directional, environment) a tree chosen
// by power alone, and the root then splits between the two by power too, so that an infinite
// light is chosen with its power table probability. The layout is LightTreeNode's
// (shared/host_device.h): leaves in emitter order, then the root, then the other inner nodes.
std::vector<gpu::LightTreeNode> buildLightTree(std::span<const gpu::Emitter> emitters,
                                               std::span<const double> powers,
                                               std::span<const gpu::Triangle> primitives,
                                               std::span<const gpu::Material> materials);

} // namespace vkpt
