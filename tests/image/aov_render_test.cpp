// aov_render_test.cpp — the AOVs (albedo, normal, depth) each executor takes from its own camera
// samples. At one seed vkpt and vkpt-ref trace the same camera rays and add the same features in
// the same order with the same float arithmetic (shared/sample_features.h), so they agree per
// pixel up to the rounding of the hit itself; a resumed render continues the very same running
// means, and the parts of a split render merge into the one-run features.
#include <string>
#include <vector>

#include "aov_agreement.h"
#include "wavefront_test_support.h"

namespace vkpt::test::aov_render_test {
namespace {

using aov_agreement::agreement;
using aov_agreement::kFeatureAbsolute;
using aov_agreement::renderReferenceAovs;
using aov_agreement::testCamera;

class Aovs : public GpuTest {
protected:
    std::vector<FeatureRecord> renderDeviceAovs(const LoadedTestScene& scene,
                                                const RenderSettings& settings,
                                                WavefrontOptions options = {}) {
        return aov_agreement::renderDeviceAovs(context(), scene, settings, options);
    }

    void expectSameSeedAgreement(const std::string& name, const LoadedTestScene& scene,
                                 const RenderSettings& settings) {
        aov_agreement::expectSameSeedAovs(context(), name, scene, settings);
    }
};

TEST_F(Aovs, SameSeedMatchesTheReference) {
    RenderSettings settings = testSettings(32, 8);
    settings.seed = 11;
    expectSameSeedAgreement("cornell", loadTestScene("cornell-box.gltf"), settings);
    settings.integrator = Integrator::Direct;
    expectSameSeedAgreement("cornell_direct", loadTestScene("cornell-box.gltf"), settings);
}

// Every feature scene's AOVs (textures: the albedo is the textured base colour; spheres, normal
// maps, instances) are compared where that scene's pipelines are made anyway, in
// specialised_vs_general_test.cpp (SpecialisedVsGeneralFeatureFiles).

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
