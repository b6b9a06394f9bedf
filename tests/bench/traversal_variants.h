// traversal_variants.h — the traversals traversal_bench compares on the same ray sets: Embree
// (the baseline every speed is a ratio of), vkpt-ref's ordered stack walk (the check every
// other answer is compared with), the device's walk run on the CPU (shared/wide_bvh.h) and the
// device kernels themselves. A new walk is one more class in traversal_variants.cpp and one line in
// makeTraversalVariants; its bytes per node and per primitive go in the layout table there.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "gpu/context.h"
#include "prepare/prepared_scene.h"
#include "traversal_rays.h"

namespace vkpt::bench {

// Bytes one node visit and one primitive test read in a walk's own layout; 0: not known.
struct WalkLayout {
    std::size_t nodeBytes = 0;
    std::size_t primitiveBytes = 0;
};

struct VariantInfo {
    std::string name;
    WalkLayout layout;
    bool ratioBase = false;      // every Mrays/s is printed as a ratio of this one's (Embree)
    bool checkReference = false; // every answer is compared with this one's (the stack walk)
};

// One ray's answer: a closest hit's t, or whether a shadow ray is blocked (t unused).
struct TraceOutcome {
    float t = 0.0f;
    bool hit = false;
};

// Work summed over a set's rays; what a variant cannot count stays empty.
struct TraceWork {
    std::optional<std::uint64_t> nodes;
    std::optional<std::uint64_t> primitiveTests;
    // The device kernels: their GPU time alone, without uploads and readbacks.
    std::optional<double> kernelSeconds;
};

class TraversalVariant {
public:
    explicit TraversalVariant(VariantInfo info) : info_(std::move(info)) {}
    virtual ~TraversalVariant() = default;
    const VariantInfo& info() const { return info_; }
    // Traces every ray of the set once: outcomes[i] answers set.rays[i].
    virtual TraceWork trace(const RaySet& set, std::vector<TraceOutcome>& outcomes) = 0;

private:
    VariantInfo info_;
};

struct VariantOptions {
    std::uint32_t threads = 2; // CPU variants and Embree
    bool device = true;        // the device kernels (on lavapipe without a GPU)
    GpuOptions gpu;
    // Rays per upload and dispatch of the device kernels; 0: 16,384 on a CPU device, 2^22 on a
    // GPU, whose cores a small batch leaves idle.
    std::uint32_t deviceBatch = 0;
};

// The variants for one scene; a variant that cannot run here (no Vulkan device) is left out
// with a note on stderr.
std::vector<std::unique_ptr<TraversalVariant>> makeTraversalVariants(const PreparedScene& scene,
                                                                     const VariantOptions& options);

} // namespace vkpt::bench
