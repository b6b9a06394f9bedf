// stack_intersector.h — vkpt-ref's own ray queries: the ordered stack walk of the BVH tree
// (bvh_traverse.h), which the device's stackless walk is checked against.
#pragma once

#include "reference/alpha_mask_filter.h"
#include "reference/scene_intersector.h"

namespace vkpt {

// Lays the tree out for the walk once (makeStackBvh); each thread's intersector shares it.
class StackIntersectors final : public IntersectorFactory {
public:
    explicit StackIntersectors(const PreparedScene& scene);
    std::unique_ptr<SceneIntersector> makeIntersector() const override;

    const StackBvh& bvh() const { return bvh_; }

private:
    const PreparedScene& scene_;
    StackBvh bvh_;
    AlphaMaskFilter alphaMask_;
    const HitFilter* filter_; // the alpha test, only when the scene has cut-outs
};

} // namespace vkpt
