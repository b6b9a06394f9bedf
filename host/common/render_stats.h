// render_stats.h — what a render did: rays by kind, traversal work, samples and time; where it
// stands after a pass, and why it ended. Both executors report in these terms.
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
    std::uint64_t nodesVisited = 0; // BVH nodes whose box was tested
    std::uint64_t triangleTests = 0;
    std::uint64_t samplesTaken = 0;
    std::uint64_t uniformBudget = 0;    // pixels × spp: what uniform sampling would have taken
    std::uint64_t nonFiniteSamples = 0; // discarded, never accumulated

    double megaRaysPerSecond() const {
        return seconds > 0.0 ? double(rays.total()) / seconds * 1e-6 : 0.0;
    }
    double nodesPerRay() const {
        return rays.total() ? double(nodesVisited) / double(rays.total()) : 0.0;
    }
    double trianglesPerRay() const {
        return rays.total() ? double(triangleTests) / double(rays.total()) : 0.0;
    }
};

// Where a render stands after a pass: what an observer of the pass loop sees (vkpt's
// --reference, --target-error, the trade study) and what a point of the error curve records.
struct PassFigures {
    std::uint32_t pass = 0;            // passes finished
    double seconds = 0.0;              // wall time since the first pass began, reporting included
    double renderSeconds = 0.0;        // the same less the time spent measuring and reporting
    double cpuSeconds = 0.0;           // the process's CPU time over renderSeconds (0: unknown)
    std::uint32_t samplesPerPixel = 0; // samples each still-active pixel has taken
    std::uint64_t samplesTaken = 0;    // Σ over the pixels (0 when the pixels were not read)
    std::uint32_t activePixels = 0;
};

// Why a render ended: its sample budget spent, every pixel converged (adaptive sampling),
// --target-error reached (vkpt's observer of the pass loop asked to stop), --time-limit, or a
// stop signal.
enum class RenderStop { Budget, Converged, TargetError, TimeLimit, Interrupted };

// The stop's name in the statistics JSON: "budget", "converged", "target-error", ...
inline const char* stopName(RenderStop stop) {
    switch (stop) {
    case RenderStop::Budget:
        return "budget";
    case RenderStop::Converged:
        return "converged";
    case RenderStop::TargetError:
        return "target-error";
    case RenderStop::TimeLimit:
        return "time-limit";
    case RenderStop::Interrupted:
        return "interrupted";
    }
    return "?";
}

} // namespace vkpt
