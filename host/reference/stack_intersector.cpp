// stack_intersector.cpp — each query forwarded to the stack walk (one level, or two for a scene
// with instances), its work counted per thread.
#include "reference/stack_intersector.h"

namespace vkpt {

namespace {

class StackIntersector final : public SceneIntersector {
public:
    StackIntersector(const StackBvh& bvh, const HitFilter* filter) : bvh_(bvh), filter_(filter) {}

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
    const StackBvh& bvh_;
    const HitFilter* filter_;
    TraversalCounters counters_;
};

class TwoLevelStackIntersector final : public SceneIntersector {
public:
    TwoLevelStackIntersector(const TwoLevelStackBvh& bvh, const HitFilter* filter)
        : bvh_(bvh), filter_(filter) {}

    ClosestHit closestHit(const glm::vec3& origin, const glm::vec3& direction) override {
        RayQuery query{origin, direction, 0.0f, VKPT_FAR, filter_};
        return closestHitTwoLevel(bvh_, query, &counters_);
    }

    bool occluded(const glm::vec3& origin, const glm::vec3& direction, float tMax) override {
        RayQuery query{origin, direction, 0.0f, tMax, filter_};
        return anyHitTwoLevel(bvh_, query, &counters_);
    }

    TraversalCounters traversal() const override { return counters_; }

private:
    const TwoLevelStackBvh& bvh_;
    const HitFilter* filter_;
    TraversalCounters counters_;
};

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
