// stack_intersector.cpp — each query forwarded to the stack walk, its work counted per thread.
#include "reference/stack_intersector.h"

namespace vkpt {

namespace {

class StackIntersector final : public SceneIntersector {
public:
    StackIntersector(const PreparedScene& scene, const StackBvh& bvh, const HitFilter* filter)
        : scene_(scene), bvh_(bvh), filter_(filter) {}

    ClosestHit closestHit(const glm::vec3& origin, const glm::vec3& direction) override {
        RayQuery query{origin, direction, 0.0f, VKPT_FAR, filter_};
        return closestHitStack(bvh_, query, &counters_);
    }

    bool occluded(const glm::vec3& origin, const glm::vec3& direction, float tMax) override {
        RayQuery query{origin, direction, 0.0f, tMax, filter_};
        return anyHitStack(bvh_, query, &counters_);
    }

    TraversalCounters traversal() const override { return counters_; }

private:
    const PreparedScene& scene_;
    const StackBvh& bvh_;
    const HitFilter* filter_;
    TraversalCounters counters_;
};

} // namespace

StackIntersectors::StackIntersectors(const PreparedScene& scene)
    : scene_(scene), bvh_(makeStackBvh(scene.tree, scene.triangles)), alphaMask_(scene),
      filter_(scene.features.alphaMask ? &alphaMask_ : nullptr) {}

std::unique_ptr<SceneIntersector> StackIntersectors::makeIntersector() const {
    return std::make_unique<StackIntersector>(scene_, bvh_, filter_);
}

} // namespace vkpt
