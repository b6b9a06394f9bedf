// ray_queries.h — the traversal kernels on a list of rays given by the host, outside a render:
// trace_closest and trace_shadow exactly as a pass dispatches them for extension rays (not
// camera rays, which pass single-sided back faces), for the tests that hold them equal to the
// CPU traversals and for benchmarks.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "lib/wavefront.h"
#include "prepare/prepared_scene.h"

namespace vkpt {

class GpuContext;

struct DeviceRay {
    glm::vec3 origin;
    glm::vec3 direction;
    float tMax = VKPT_FAR; // any-hit queries only; closest-hit queries use (0, VKPT_FAR)
};

class DeviceRayQueries {
public:
    // batchSize: rays per dispatch (a multiple of WORKGROUP_SIZE).
    DeviceRayQueries(GpuContext& context, const PreparedScene& scene,
                     std::uint32_t batchSize = 1u << 14);
    ~DeviceRayQueries();
    DeviceRayQueries(const DeviceRayQueries&) = delete;
    DeviceRayQueries& operator=(const DeviceRayQueries&) = delete;

    // trace_closest: t in (0, VKPT_FAR); triangle NO_HIT on a miss. With `instances`, each hit's
    // instance too (NO_INSTANCE in a scene of one level).
    std::vector<gpu::HitRecord> closest(std::span<const DeviceRay> rays,
                                        std::vector<std::uint32_t>* instances = nullptr);
    // trace_shadow on segment records: true where something lies at t in (0, tMax).
    std::vector<bool> occluded(std::span<const DeviceRay> rays);

    // Walks cut short by a driver loop limit so far (COUNTER_TRUNCATED); 0 when all is well.
    std::uint32_t truncatedTraversals();
    // BVH nodes tested so far, over all queries.
    std::uint64_t nodesVisited();
    // GPU time of the traversal dispatches so far (timestamps; 0 on a device without them):
    // the kernels' own time, without uploads and readbacks.
    double kernelSeconds() const;

private:
    struct State;
    std::unique_ptr<State> state_;
};

} // namespace vkpt
