// stack_intersector.h — vkpt-ref's own ray queries: the ordered stack walk of the BVH tree
// (bvh_traverse.h), or of both levels of a scene with instances, which the device's stackless
// walk is checked against.
#pragma once

#include <optional>

#include "reference/alpha_mask_filter.h"
#include "reference/scene_intersector.h"

namespace vkpt {

// The scene's two levels laid out for the stack walk (features.instances).
TwoLevelStackBvh makeTwoLevelStackBvh(const PreparedScene& scene);

// Lays the tree (or both levels) out for the walk once; each thread's intersector shares it.
class StackIntersectors final : public IntersectorFactory {
public:
    explicit StackIntersectors(const PreparedScene& scene);
    std::unique_ptr<SceneIntersector> makeIntersector() const override;

    const StackBvh& bvh() const { return bvh_; } // empty for a two-level scene

private:
    StackBvh bvh_;
    std::optional<TwoLevelStackBvh> twoLevel_;
    AlphaMaskFilter alphaMask_;
    const HitFilter* filter_; // the alpha test, only when the scene has cut-outs
};

} // namespace vkpt
