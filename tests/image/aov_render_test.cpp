// aov_render_test.cpp — the AOVs (albedo, normal, depth) each executor takes from its own camera
// samples. At one seed vkpt and vkpt-ref trace the same camera rays and add the same features in
// the same order with the same float arithmetic (shared/sample_features.h), so they agree per
// pixel up to the rounding of the hit itself; a resumed render continues the very same running
// means, and the parts of a split render merge into the one-run features.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "wavefront_test_support.h"

namespace vkpt::test::aov_render_test {
namespace {

// A hit's barycentrics and t differ between the two walks by float rounding (traversal_kernel_test
// measured 2.5e-4 on barycentrics at worst), which moves an interpolated albedo or normal by about
// that much; depth is t times a cosine, within 1e-5 relative. An edge sample can hit the other
// triangle, or miss, in one walk: such pixels must stay rare, as in the colour comparison.
constexpr float kFeatureAbsolute = 5e-4f;
constexpr float kDepthRelative = 1e-5f;

gpu::Camera testCamera(const LoadedTestScene& scene, const RenderSettings& settings) {
    return makeGpuCamera(selectCamera(scene.scene, settings.cameraIndex), settings.width,
                         settings.height);
}

ReferenceResult renderReferenceAovs(const LoadedTestScene& scene, const RenderSettings& settings,
                                    ReferenceOptions options = {}) {
    options.aovs = true;
    RenderStats stats;
    return renderReferenceParts(scene.prepared, testCamera(scene, settings), settings, stats,
                                options);
}

bool sameDepth(float a, float b) {
    if (std::isinf(a) || std::isinf(b)) return a == b;
    return std::abs(a - b) <= kDepthRelative * std::max(std::abs(a), std::abs(b));
}

bool closeFeatures(const FeatureRecord& a, const FeatureRecord& b, float absolute) {
    for (int c = 0; c < 3; ++c)
        if (std::abs(a.albedo[c] - b.albedo[c]) > absolute ||
            std::abs(a.normal[c] - b.normal[c]) > absolute)
            return false;
    return a.samples == b.samples && sameDepth(a.depth, b.depth);
}

// The fraction of pixels whose features agree within `absolute`.
double agreement(const std::vector<FeatureRecord>& a, const std::vector<FeatureRecord>& b,
                 float absolute) {
    EXPECT_EQ(a.size(), b.size());
    if (a.size() != b.size() || a.empty()) return 0.0;
    std::size_t within = 0;
    for (std::size_t i = 0; i < a.size(); ++i)
        within += closeFeatures(a[i], b[i], absolute) ? 1 : 0;
    return double(within) / double(a.size());
}

// Every pixel has averaged `samples` camera samples, and the scene is seen somewhere.
void expectCovered(const std::vector<FeatureRecord>& features, std::uint32_t samples) {
    std::size_t hits = 0;
    for (const FeatureRecord& f : features) {
        ASSERT_EQ(f.samples, samples);
        hits += std::isinf(f.depth) ? 0 : 1;
    }
    EXPECT_GT(hits, features.size() / 2) << "most pixels see a surface";
}

class Aovs : public GpuTest {
protected:
    std::vector<FeatureRecord> renderDeviceAovs(const LoadedTestScene& scene,
                                                const RenderSettings& settings,
                                                WavefrontOptions options = {}) {
        options.aovs = true;
        WavefrontResult result = renderWavefront(context(), scene.prepared,
                                                 testCamera(scene, settings), settings, options);
        return std::move(result.features);
    }

    void expectSameSeedAgreement(const std::string& name, const LoadedTestScene& scene,
                                 const RenderSettings& settings) {
        const std::vector<FeatureRecord> gpu = renderDeviceAovs(scene, settings);
        const ReferenceResult cpu = renderReferenceAovs(scene, settings);
        expectCovered(cpu.features, settings.samplesPerPixel);
        const double fraction = agreement(gpu, cpu.features, kFeatureAbsolute);
        std::printf("%s: features of %.2f %% of the pixels within %g\n", name.c_str(),
                    100.0 * fraction, double(kFeatureAbsolute));
        EXPECT_GE(fraction, kSameSeedMinimumAgreement) << name;
    }
};

TEST_F(Aovs, SameSeedMatchesTheReference) {
    RenderSettings settings = testSettings(32, 8);
    settings.seed = 11;
    expectSameSeedAgreement("cornell", loadTestScene("cornell-box.gltf"), settings);
    settings.integrator = Integrator::Direct;
    expectSameSeedAgreement("cornell_direct", loadTestScene("cornell-box.gltf"), settings);
}

// Textures (the albedo is the textured base colour), spheres, normal maps, instances: every
// feature scene, under the path tracer.
TEST_F(Aovs, FeatureTestScenesMatchTheReference) {
    const std::vector<std::string> scenes = featureTestScenes();
    if (scenes.empty()) GTEST_SKIP() << "no scenes in " << scenePath("test/features");
    RenderSettings settings = testSettings(16, 2);
    settings.seed = 12;
    for (const std::string& path : scenes)
        expectSameSeedAgreement(std::filesystem::path(path).stem().string(),
                                loadFeatureTestScene(path), settings);
}

// Resuming at sample 8 continues each pixel's running means from the state's values: the same
// float operations as one run of 16, so the same bits on either executor.
TEST_F(Aovs, ResumedRenderContinuesTheSameMeans) {
    const LoadedTestScene scene = loadTestScene("cornell-box.gltf");
    RenderSettings settings = testSettings(8, 16);
    const SamplePlan whole{fullFrame(8, 8), {0, 16}};
    const SamplePlan first{fullFrame(8, 8), {0, 8}};

    ReferenceOptions cpuFirst;
    cpuFirst.plan = first;
    const ReferenceResult cpuHalf = renderReferenceAovs(scene, settings, cpuFirst);
    ReferenceOptions cpuRest;
    cpuRest.plan = whole;
    cpuRest.resume = &cpuHalf.records;
    cpuRest.resumeFeatures = &cpuHalf.features;
    EXPECT_EQ(agreement(renderReferenceAovs(scene, settings, cpuRest).features,
                        renderReferenceAovs(scene, settings).features, 0.0f),
              1.0);

    WavefrontOptions gpuHalf;
    gpuHalf.plan = first;
    gpuHalf.aovs = true;
    WavefrontResult half =
        renderWavefront(context(), scene.prepared, testCamera(scene, settings), settings, gpuHalf);
    WavefrontOptions gpuRest;
    gpuRest.plan = whole;
    gpuRest.resume = &half.records;
    gpuRest.resumeFeatures = &half.features;
    EXPECT_EQ(agreement(renderDeviceAovs(scene, settings, gpuRest),
                        renderDeviceAovs(scene, settings), 0.0f),
              1.0);
}

// Two tasks' shares of the samples, merged, weigh each part's means by its count: the one-run
// features up to the rounding of a float running mean (a few ulps of values at most 1).
TEST_F(Aovs, SplitSamplesMergeIntoTheWholeRun) {
    const LoadedTestScene scene = loadTestScene("cornell-box.gltf");
    RenderSettings settings = testSettings(16, 12);
    ReferenceOptions low, high;
    low.plan = SamplePlan{fullFrame(16, 16), {0, 4}};
    high.plan = SamplePlan{fullFrame(16, 16), {4, 12}};
    const ReferenceResult a = renderReferenceAovs(scene, settings, low);
    const ReferenceResult b = renderReferenceAovs(scene, settings, high);
    std::vector<FeatureRecord> merged;
    for (std::size_t i = 0; i < a.features.size(); ++i)
        merged.push_back(combineFeatures(a.features[i], b.features[i]));
    EXPECT_EQ(agreement(merged, renderReferenceAovs(scene, settings).features, 1e-6f), 1.0);
    EXPECT_EQ(agreement(merged, renderDeviceAovs(scene, settings), kFeatureAbsolute), 1.0);
}

// A render whose outputs need no AOVs records none, on either executor.
TEST_F(Aovs, NoneUnlessAsked) {
    const LoadedTestScene scene = loadTestScene("cornell-box.gltf");
    const RenderSettings settings = testSettings(8, 2);
    RenderStats stats;
    EXPECT_TRUE(
        renderReferenceParts(scene.prepared, testCamera(scene, settings), settings, stats, {})
            .features.empty());
    EXPECT_TRUE(renderWavefront(context(), scene.prepared, testCamera(scene, settings), settings)
                    .features.empty());
}

} // namespace
} // namespace vkpt::test::aov_render_test
