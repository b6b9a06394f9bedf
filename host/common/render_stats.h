// render_stats.h — what a render did: rays by kind, traversal work, samples and time.
#pragma once

#include <cstdint>

namespace vkpt {

struct RayCounts {
    std::uint64_t camera = 0;
    std::uint64_t extension = 0; // secondary rays after a scattering event
    std::uint64_t shadow = 0;

    std::uint64_t total() const { return camera + extension + shadow; }
    RayCounts& operator+=(const RayCounts& o) {
        camera += o.camera;
        extension += o.extension;
        shadow += o.shadow;
        return *this;
    }
};

struct RenderStats {
    double seconds = 0.0;
    // CPU time of the render threads (vkpt-ref; 0 for vkpt): unlike `seconds` it does not grow
    // while other processes hold the cores, so it compares renders on a shared machine.
    double cpuSeconds = 0.0;
    RayCounts rays;
    std::uint64_t nodesVisited = 0;  // BVH nodes whose box was tested
    std::uint64_t triangleTests = 0;
    std::uint64_t samplesTaken = 0;
    std::uint64_t uniformBudget = 0; // pixels × spp: what uniform sampling would have taken
    std::uint64_t nonFiniteSamples = 0; // discarded, never accumulated

    double megaRaysPerSecond() const { return seconds > 0.0 ? double(rays.total()) / seconds * 1e-6 : 0.0; }
    double nodesPerRay() const { return rays.total() ? double(nodesVisited) / double(rays.total()) : 0.0; }
    double trianglesPerRay() const {
        return rays.total() ? double(triangleTests) / double(rays.total()) : 0.0;
    }
};

} // namespace vkpt
