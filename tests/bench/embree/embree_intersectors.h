// embree_intersectors.h — Embree 3 answering vkpt-ref's ray queries (rtcIntersect1 for closest
// hits, rtcOccluded1 for shadow rays) on the prepared scene's triangles, for the benchmarks'
// baseline: embree-ref (vkpt-ref's integrators on Embree) and traversal_bench. Never linked by
// vkpt or vkpt-ref. Alpha-masked triangles go through the reference's own AlphaMaskFilter
// from Embree's filter functions; spheres are refused.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "reference/scene_intersector.h"

namespace vkpt::bench {

class EmbreeIntersectors final : public IntersectorFactory {
public:
    // Builds Embree's BVH (RTC_BUILD_QUALITY_HIGH) with `threads` threads (0: all cores).
    // Throws InputError for a scene with spheres, std::runtime_error when Embree fails.
    EmbreeIntersectors(const PreparedScene& scene, std::uint32_t threads);
    ~EmbreeIntersectors() override;
    EmbreeIntersectors(const EmbreeIntersectors&) = delete;
    EmbreeIntersectors& operator=(const EmbreeIntersectors&) = delete;

    std::unique_ptr<SceneIntersector> makeIntersector() const override;

    // Any (tMin, tMax), for traversal_bench; safe to call from several threads.
    ClosestHit closestHit(const RayQuery& ray) const;
    bool anyHit(const RayQuery& ray) const;

    double buildSeconds() const { return buildSeconds_; } // geometry upload and commit
    static std::string version();                         // "3.13.5"

private:
    struct State;
    std::unique_ptr<State> state_;
    double buildSeconds_ = 0.0;
};

} // namespace vkpt::bench
