// lobe_same_seed_test.cpp — vkpt against vkpt-ref on the scenes of the lobes that only some
// scenes compile (scenes/test/lobes: a leaf with KHR_materials_diffuse_transmission lit from
// behind, a prism with KHR_materials_dispersion before a narrow light). At one seed the two
// trace the same paths, wavelengths included, so their images agree pixel by pixel up to float
// rounding (docs/wavefront.md), as render_compare_test's feature scenes do. These scenes are
// kept out of that sweep, which would compile each one's pipelines for three integrators: here
// only the path tracer, whose shading is what the lobes change.
#include <cstdio>
#include <string>

#include "wavefront_test_support.h"

namespace vkpt::test::lobe_same_seed_test {
namespace {

// As render_compare_test.cpp: paths that diverge on a last-bit difference stay rare.
constexpr double kMinimumAgreement = 0.99;

class LobeScenesSameSeed : public GpuTest {
protected:
    // 24 × 24 pixels at 8 samples and 2 light samples, the feature sweep's path-tracer settings:
    // enough paths through the leaf, the prism and its caustics that a divergence would show.
    void expectAgreement(const std::string& name, const std::string& path) {
        LoadedTestScene scene = loadTestScene(path);
        RenderSettings settings = testSettings(24, 8);
        settings.seed = 6;
        settings.lightSamples = 2;
        RenderStats gpuStats, cpuStats;
        RenderOutput gpu = renderOnDevice(context(), scene, settings, &gpuStats);
        RenderOutput cpu = renderTestScene(scene, settings, &cpuStats);
        SameSeedAgreement a = compareSameSeed(gpu, cpu);
        std::printf("%s (%s): %s\n", name.c_str(),
                    describeFeatures(scene.prepared.usedFeatures).c_str(), a.summary().c_str());
        EXPECT_GE(a.fraction(), kMinimumAgreement) << writeComparisonImages(name, gpu, cpu);
        EXPECT_EQ(gpuStats.samplesTaken, cpuStats.samplesTaken);
    }
};

TEST_F(LobeScenesSameSeed, LeafLitFromBehindMatchesTheReference) {
    expectAgreement("leaf", "test/lobes/leaf.gltf");
}

TEST_F(LobeScenesSameSeed, DispersivePrismMatchesTheReference) {
    expectAgreement("prism", "test/lobes/prism.gltf");
}

} // namespace
} // namespace vkpt::test::lobe_same_seed_test
