// stack_intersector.cpp — each query forwarded to the stack walk (one level, or two for a scene
// with instances), its work counted per thread.
#include "reference/stack_intersector.h"

namespace vkpt {

namespace {

// One thread's queries on a layout `Bvh` (one level or two), through its walks.
template <typename Bvh, ClosestHit (*kClosest)(const Bvh&, const RayQuery&, TraversalCounters*),
          bool (*kAny)(const Bvh&, const RayQuery&, TraversalCounters*)>
class LayoutIntersector final : public SceneIntersector {
public:
    LayoutIntersector(const Bvh& bvh, const HitFilter* filter) : bvh_(bvh), filter_(filter) {}

    ClosestHit closestHit(const glm::vec3& origin, const glm::vec3& direction,
                          float tMin) override {
        RayQuery query{origin, direction, tMin, VKPT_FAR, filter_};
        return kClosest(bvh_, query, &counters_);
    }

    bool occluded(const glm::vec3& origin, const glm::vec3& direction, float tMax) override {
        RayQuery query{origin, direction, 0.0f, tMax, filter_};
        return kAny(bvh_, query, &counters_);
    }

    TraversalCounters traversal() const override { return counters_; }

private:
    const Bvh& bvh_;
    const HitFilter* filter_;
    TraversalCounters counters_;
};

using StackIntersector = LayoutIntersector<StackBvh, closestHitStack, anyHitStack>;
using TwoLevelStackIntersector =
    LayoutIntersector<TwoLevelStackBvh, closestHitTwoLevel, anyHitTwoLevel>;

} // namespace

TwoLevelStackBvh makeTwoLevelStackBvh(const PreparedScene& scene) {
    TwoLevelStackBvh bvh;
    bvh.top = makeStackBvhLayout(scene.instanceTree);
    for (const PreparedMesh& mesh : scene.meshes) {
        const std::span<const gpu::Triangle> primitives(
            scene.triangles.data() + mesh.firstPrimitive, mesh.primitiveCount);
        bvh.bottoms.push_back(makeStackBvh(mesh.tree, primitives));
        bvh.firstPrimitives.push_back(mesh.firstPrimitive);
    }
    bvh.instances = scene.instances;
    return bvh;
}

StackIntersectors::StackIntersectors(const PreparedScene& scene)
    : alphaMask_(scene), filter_(scene.features.alphaMask ? &alphaMask_ : nullptr) {
    if (scene.features.instances) {
        twoLevel_ = makeTwoLevelStackBvh(scene);
    } else {
        bvh_ = makeStackBvh(scene.tree, scene.triangles);
    }
}

std::unique_ptr<SceneIntersector> StackIntersectors::makeIntersector() const {
    if (twoLevel_) return std::make_unique<TwoLevelStackIntersector>(*twoLevel_, filter_);
    return std::make_unique<StackIntersector>(bvh_, filter_);
}

} // namespace vkpt
