// wavefront_test_support.h — what the image tests share: a validated device (the GpuTest
// fixture of tests/gpu), renders with vkpt's wavefront executor in-process, and the evidence a
// failed comparison leaves behind (both images and their difference as PFM files).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "../support/reference_render.h"
#include "gpu_test_support.h"
#include "image/render_output.h"
#include "render/wavefront.h"

namespace vkpt::test {

// The scenes shared between projects, for tests that skip when they are absent.
inline std::string sharedScenePath(const std::string& relative) {
    return std::string(VKPT_SCENES_DIR) + "/../../shared/scenes/" + relative;
}

// The feature test scenes (scenes/test/features/*.gltf, *.glb), listed when the test runs so
// that a scene added there is tested without rebuilding; paths relative to scenes/.
std::vector<std::string> featureTestScenes();

// A scene as loadTestScene loads it; test/features/environment.gltf gets its environment map
// (test/features/sky.hdr), which vkpt takes from the command line rather than the file, and
// glass-ball.gltf and absorbing-slab.gltf a constant one.
LoadedTestScene loadFeatureTestScene(const std::string& relative, bool general = false,
                                     LightSampler lightSampler = LightSampler::Auto);

// Renders `loaded` on the device with the camera renderTestScene uses, so that both
// executors see the same rays. Fails the test if a traversal was cut short.
RenderOutput renderOnDevice(GpuContext& context, const LoadedTestScene& loaded,
                            const RenderSettings& settings, RenderStats* stats = nullptr,
                            const WavefrontOptions& options = {});

// Same seed on both executors: per pixel and channel, |gpu − cpu| ≤ relative·|cpu| + absolute.
struct SameSeedAgreement {
    std::uint64_t pixels = 0;
    std::uint64_t within = 0;
    double largestRelative = 0.0; // max over pixels and channels of |gpu − cpu| / max(|cpu|, abs)
    std::uint32_t largestPixel = 0;
    std::uint64_t aboveOneMillionth = 0; // pixels whose relative difference exceeds 1e-6
    double fraction() const { return pixels ? double(within) / double(pixels) : 0.0; }
    std::string summary() const; // one line of the figures above
};

// The bound of docs/wavefront.md: 1e-4 relative (float rounding over a path of up to ~100
// operations in a different order and with fused multiply-adds) plus 1e-6 absolute (sums
// that cancel to near zero, e.g. the normals image's components).
inline constexpr double kSameSeedRelative = 1e-4;
inline constexpr double kSameSeedAbsolute = 1e-6;

SameSeedAgreement compareSameSeed(const RenderOutput& gpu, const RenderOutput& cpu);

// Pixels outside the float bound are paths that diverged: a decision (Russian roulette, a
// direction below the surface, an edge hit) flipped on a last-bit difference. They must stay
// rare: at most 1 % of the pixels.
inline constexpr double kSameSeedMinimumAgreement = 0.99;

// Renders `scene` with vkpt-ref at `settings` and expects the device's render of it (`gpu`,
// with its statistics) to agree: at least kSameSeedMinimumAgreement of the pixels within the
// bound, in the image and in both halves, with the same sample counts. Prints the figures.
void expectSameSeedAsReference(const std::string& name, const LoadedTestScene& scene,
                               const RenderSettings& settings, const RenderOutput& gpu,
                               const RenderStats& gpuStats);

// Writes <name>.gpu.pfm, <name>.cpu.pfm and <name>.diff.pfm (|gpu − cpu|) into the working
// directory and returns a line naming them, for a failure message.
std::string writeComparisonImages(const std::string& name, const RenderOutput& gpu,
                                  const RenderOutput& cpu);

} // namespace vkpt::test
