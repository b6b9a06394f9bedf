// aov_agreement.h — the AOVs of vkpt and vkpt-ref at one seed, compared per pixel: the
// comparison aov_render_test.cpp makes for the Cornell box and specialised_vs_general_test.cpp
// for every feature scene (with that scene's pipelines already made in its process).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "wavefront_test_support.h"

namespace vkpt::test::aov_agreement {

// A hit's barycentrics and t differ between the two walks by float rounding (traversal_kernel_test
// measured 2.5e-4 on barycentrics at worst), which moves an interpolated albedo or normal by about
// that much; depth is t times a cosine, within 1e-5 relative. An edge sample can hit the other
// triangle, or miss, in one walk: such pixels must stay rare, as in the colour comparison.
inline constexpr float kFeatureAbsolute = 5e-4f;
inline constexpr float kDepthRelative = 1e-5f;

inline gpu::Camera testCamera(const LoadedTestScene& scene, const RenderSettings& settings) {
    return makeGpuCamera(selectCamera(scene.scene, settings.cameraIndex), settings.width,
                         settings.height);
}

inline ReferenceResult renderReferenceAovs(const LoadedTestScene& scene,
                                           const RenderSettings& settings,
                                           ReferenceOptions options = {}) {
    options.aovs = true;
    RenderStats stats;
    return renderReferenceParts(scene.prepared, testCamera(scene, settings), settings, stats,
                                options);
}

inline bool sameDepth(float a, float b) {
    if (std::isinf(a) || std::isinf(b)) return a == b;
    return std::abs(a - b) <= kDepthRelative * std::max(std::abs(a), std::abs(b));
}

inline bool closeFeatures(const FeatureRecord& a, const FeatureRecord& b, float absolute) {
    for (int c = 0; c < 3; ++c)
        if (std::abs(a.albedo[c] - b.albedo[c]) > absolute ||
            std::abs(a.normal[c] - b.normal[c]) > absolute)
            return false;
    return a.samples == b.samples && sameDepth(a.depth, b.depth);
}

// The fraction of pixels whose features agree within `absolute`.
inline double agreement(const std::vector<FeatureRecord>& a, const std::vector<FeatureRecord>& b,
                        float absolute) {
    EXPECT_EQ(a.size(), b.size());
    if (a.size() != b.size() || a.empty()) return 0.0;
    std::size_t within = 0;
    for (std::size_t i = 0; i < a.size(); ++i)
        within += closeFeatures(a[i], b[i], absolute) ? 1 : 0;
    return double(within) / double(a.size());
}

// Every pixel has averaged `samples` camera samples, and the scene is seen somewhere.
inline void expectCovered(const std::vector<FeatureRecord>& features, std::uint32_t samples) {
    std::size_t hits = 0;
    for (const FeatureRecord& f : features) {
        ASSERT_EQ(f.samples, samples);
        hits += std::isinf(f.depth) ? 0 : 1;
    }
    EXPECT_GT(hits, features.size() / 2) << "most pixels see a surface";
}

inline std::vector<FeatureRecord> renderDeviceAovs(GpuContext& context,
                                                   const LoadedTestScene& scene,
                                                   const RenderSettings& settings,
                                                   WavefrontOptions options = {}) {
    options.aovs = true;
    WavefrontResult result =
        renderWavefront(context, scene.prepared, testCamera(scene, settings), settings, options);
    return std::move(result.features);
}

// The features of both executors at `settings`: every pixel covered, and at least
// kSameSeedMinimumAgreement of the pixels within kFeatureAbsolute (depth kDepthRelative).
inline void expectSameSeedAovs(GpuContext& context, const std::string& name,
                               const LoadedTestScene& scene, const RenderSettings& settings) {
    const std::vector<FeatureRecord> gpu = renderDeviceAovs(context, scene, settings);
    const ReferenceResult cpu = renderReferenceAovs(scene, settings);
    expectCovered(cpu.features, settings.samplesPerPixel);
    const double fraction = agreement(gpu, cpu.features, kFeatureAbsolute);
    std::printf("%s: features of %.2f %% of the pixels within %g\n", name.c_str(), 100.0 * fraction,
                double(kFeatureAbsolute));
    EXPECT_GE(fraction, kSameSeedMinimumAgreement) << name;
}

} // namespace vkpt::test::aov_agreement
