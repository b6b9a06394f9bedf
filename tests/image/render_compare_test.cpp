// render_compare_test.cpp — vkpt against vkpt-ref. At one seed the two trace the same paths,
// so images agree pixel by pixel up to float rounding (docs/wavefront.md derives the bound);
// at different seeds they agree in distribution (per-pixel z-test, Šidák-corrected). Also:
// the same seed gives the same device image, bit for bit, whatever the slot count. At one seed
// the two halves' images (even and odd sample indices) agree by the same bound as the image.
#include <cstdio>
#include <filesystem>

#include "image/image_compare.h"
#include "wavefront_test_support.h"

namespace vkpt::test::render_compare_test {
namespace {

class SameSeed : public GpuTest {
protected:
    // The device's image, for a test's own checks.
    RenderOutput expectAgreement(const std::string& name, const std::string& scenePath,
                                 const RenderSettings& settings,
                                 const WavefrontOptions& options = {}) {
        return expectAgreement(name, loadTestScene(scenePath), settings, options);
    }

    RenderOutput expectAgreement(const std::string& name, const LoadedTestScene& scene,
                                 const RenderSettings& settings,
                                 const WavefrontOptions& options = {}) {
        RenderStats gpuStats;
        RenderOutput gpu = renderOnDevice(context(), scene, settings, &gpuStats, options);
        expectSameSeedAsReference(name, scene, settings, gpu, gpuStats);
        return gpu;
    }
};

TEST_F(SameSeed, PathTracerMatchesTheReference) {
    RenderSettings settings = testSettings(32, 16);
    settings.seed = 3;
    expectAgreement("path", "cornell-box.gltf", settings);
}

// The default sampler is Sobol (shared/sampler.h); the independent one must agree as well.
TEST_F(SameSeed, IndependentSamplerMatchesTheReference) {
    RenderSettings settings = testSettings(32, 16);
    settings.seed = 3;
    settings.sampler = Sampler::Independent;
    expectAgreement("path_independent", "cornell-box.gltf", settings);
}

TEST_F(SameSeed, PathTracerWithSeveralLightSamplesMatchesTheReference) {
    RenderSettings settings = testSettings(24, 8);
    settings.seed = 5;
    settings.lightSamples = 3;
    expectAgreement("path_light_samples", "cornell-box.gltf", settings);
}

TEST_F(SameSeed, PathFiltersMatchTheReference) {
    RenderSettings settings = testSettings(24, 8);
    settings.pathFilter = PathFilter::DirectOnly;
    expectAgreement("direct_only", "cornell-box.gltf", settings);
    settings.pathFilter = PathFilter::IndirectOnly;
    expectAgreement("indirect_only", "cornell-box.gltf", settings);
}

TEST_F(SameSeed, DirectIntegratorWithLightSamplingMatchesTheReference) {
    RenderSettings settings = testSettings(24, 8);
    settings.integrator = Integrator::Direct;
    settings.lightSamples = 2;
    expectAgreement("direct_light", "cornell-box.gltf", settings);
}

TEST_F(SameSeed, DirectIntegratorWithHemisphereSamplingMatchesTheReference) {
    RenderSettings settings = testSettings(24, 8);
    settings.integrator = Integrator::Direct;
    settings.lightSampling = LightSampling::Hemisphere;
    settings.lightSamples = 2;
    expectAgreement("direct_hemisphere", "cornell-box.gltf", settings);
}

TEST_F(SameSeed, NormalsMatchTheReference) {
    RenderSettings settings = testSettings(24, 2);
    settings.integrator = Integrator::Normals;
    expectAgreement("normals", "cornell-box.gltf", settings);
}

// Few slots: several chunks per pass, and the active list read back between passes.
TEST_F(SameSeed, ChunkedPassesMatchTheReference) {
    RenderSettings settings = testSettings(24, 4);
    WavefrontOptions options;
    options.slotCount = 256;
    expectAgreement("chunked", "cornell-box.gltf", settings, options);
}

// Without Russian roulette every path in the closed furnace lives to the depth limit, so the
// bounces span two submissions per pass (32 each) and the second continues the first's queue.
TEST_F(SameSeed, PathsLongerThanOneSubmissionMatchTheReference) {
    RenderSettings settings = testSettings(16, 4);
    settings.maxDepth = 40;
    settings.rrStartDepth = 1000;
    expectAgreement("deep_paths", "furnace.gltf", settings);
}

// The device takes exactly the reference's samples: same stopping tests at the same counts.
TEST_F(SameSeed, AdaptiveSamplingTakesTheReferenceSamples) {
    RenderSettings settings = testSettings(16, 256);
    settings.adaptive = {true, 16, 0.2f, 32, true};
    expectAgreement("adaptive", "cornell-box.gltf", settings);
}

// A scene from the shared set, with many more triangles and long thin ones.
TEST_F(SameSeed, SharedCornellBoxMatchesTheReference) {
    const std::string path = sharedScenePath("CornellBox/cornellBox.gltf");
    if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " is not there";
    RenderSettings settings = testSettings(32, 8);
    settings.seed = 4;
    expectAgreement("shared_cornell", "../../shared/scenes/CornellBox/cornellBox.gltf", settings);
}

TEST_F(SameSeed, EmittingSidesMatchTheReference) {
    RenderSettings settings = testSettings(24, 8);
    expectAgreement("emission_sides", "test/emission-sides.gltf", settings);
}

// A closed room of single-sided walls facing in, the camera outside: camera rays pass the near
// wall's back (glTF doubleSided false) on both executors alike, and the inside shows, lit
// (mean 0.30 at 64 samples; black, 0, when the near wall stopped them). 24 x 24 pixels and 8
// samples, as the Cornell box's cases: the same kernels, and the bound needs no more.
TEST_F(SameSeed, SingleSidedRoomSeenThroughItsNearWallMatchesTheReference) {
    RenderSettings settings = testSettings(24, 8);
    const RenderOutput gpu =
        expectAgreement("single_sided_room", "test/single-sided-room.gltf", settings);
    double sum = 0.0;
    for (const glm::vec3& p : gpu.image.pixels)
        sum += double(p.r + p.g + p.b) / 3.0;
    EXPECT_GT(sum / double(gpu.image.pixels.size()), 0.15) << "the inside is not lit";
}

// Thousands of small emitters chosen by the light BVH, and by power.
TEST_F(SameSeed, ManyLightsMatchTheReference) {
    RenderSettings settings = testSettings(32, 8);
    settings.seed = 7;
    settings.lightSamples = 2;
    expectAgreement("many_lights_bvh", "test/many-lights.gltf", settings);
    expectAgreement("many_lights_power",
                    loadTestScene("test/many-lights.gltf", {{}, false, LightSampler::Power}),
                    settings);
}

// The feature scenes whose emitters are of several kinds (spheres, point, spot and directional
// lights, the environment under the tree's by-power root, textured emitters), chosen by the
// light BVH whatever their count.
TEST_F(SameSeed, FeatureTestScenesByTheLightBvhMatchTheReference) {
    for (const char* name : {"punctual", "spheres", "environment", "textured"}) {
        SCOPED_TRACE(name);
        const std::string path = std::string("test/features/") + name + ".gltf";
        LoadedTestScene scene = loadFeatureTestScene(path, false, LightSampler::Bvh);
        RenderSettings settings = testSettings(24, 8);
        settings.seed = 8;
        settings.lightSamples = 2;
        expectAgreement(std::string(name) + "_light_bvh", scene, settings);
    }
}

class DifferentSeeds : public GpuTest {
protected:
    void expectSameDistribution(const std::string& name, const std::string& scenePath,
                                RenderSettings settings) {
        LoadedTestScene scene = loadTestScene(scenePath);
        settings.seed = 1;
        RenderOutput gpu = renderOnDevice(context(), scene, settings);
        settings.seed = 2;
        RenderOutput cpu = renderTestScene(scene, settings);
        ZTestResult z = zTestPerPixel(gpu, cpu, 0.01);
        std::printf("%s: %s\n", name.c_str(), z.summary.c_str());
        EXPECT_TRUE(z.passed) << z.summary << "\n" << writeComparisonImages(name, gpu, cpu);
    }
};

TEST_F(DifferentSeeds, CornellBoxAgreesPixelByPixelInDistribution) {
    expectSameDistribution("z_cornell", "cornell-box.gltf", testSettings(24, 32));
}

TEST_F(DifferentSeeds, QuadLightAgreesPixelByPixelInDistribution) {
    RenderSettings settings = testSettings(24, 32);
    settings.lightSamples = 2;
    expectSameDistribution("z_quad_light", "test/quad-light-floor.gltf", settings);
}

// The device's walk of the light BVH and its MIS pmf against the reference's, in distribution
// (tests/render/light_sampler_test.cpp holds the tree against power sampling).
TEST_F(DifferentSeeds, ManyLightsAgreePixelByPixelInDistribution) {
    expectSameDistribution("z_many_lights", "test/many-lights.gltf", testSettings(24, 64));
}

class Determinism : public GpuTest {};

// No float atomics and per-sample order everywhere: bit-identical, even with other chunking.
TEST_F(Determinism, SameSeedGivesTheSameImageBitForBit) {
    LoadedTestScene scene = loadTestScene("cornell-box.gltf");
    RenderSettings settings = testSettings(24, 8);
    settings.seed = 9;
    RenderOutput first = renderOnDevice(context(), scene, settings);
    RenderOutput second = renderOnDevice(context(), scene, settings);
    WavefrontOptions fewSlots;
    fewSlots.slotCount = 320;
    RenderOutput chunked = renderOnDevice(context(), scene, settings, nullptr, fewSlots);
    ASSERT_EQ(first.image.pixels.size(), second.image.pixels.size());
    for (std::size_t i = 0; i < first.image.pixels.size(); ++i) {
        ASSERT_EQ(first.image.pixels[i], second.image.pixels[i]) << "pixel " << i;
        ASSERT_EQ(first.image.pixels[i], chunked.image.pixels[i]) << "pixel " << i << ", chunked";
        ASSERT_EQ(first.luminanceM2[i], chunked.luminanceM2[i]) << "pixel " << i;
    }
    settings.seed = 10;
    RenderOutput other = renderOnDevice(context(), scene, settings);
    EXPECT_NE(first.image.pixels, other.image.pixels) << "a new seed must give new noise";
}

} // namespace
} // namespace vkpt::test::render_compare_test
