// default_lighting_render_test.cpp — the built-in studio (prepare/scene_lighting.h) lights a
// scene without lights the same way on both executors: at one seed vkpt and vkpt-ref trace the
// same paths and agree pixel by pixel up to float rounding; at different seeds they agree in
// distribution (per-pixel Welch test, Šidák-corrected, render_checks.h), as for every light.
#include <cstdio>
#include <filesystem>

#include "../support/render_checks.h"
#include "image/image_compare.h"
#include "prepare/scene_lighting.h"
#include "wavefront_test_support.h"

namespace vkpt::test::default_lighting_render_test {
namespace {

// The scene as vkpt and vkpt-ref load it without --env, --env-color or --default-light off.
LoadedTestScene loadWithDefaultLighting(const std::string& relative) {
    LoadOptions options;
    options.warnUnsupportedExtensions = false;
    LoadedTestScene loaded{loadGltfScene(scenePath(relative), options), {}};
    const LightingDecision decision = applyDefaultLighting(loaded.scene, {});
    EXPECT_TRUE(decision.useStudio)
        << relative << ": " << describeLightingMeasure(decision.measure);
    loaded.prepared = prepareScene(loaded.scene);
    return loaded;
}

class DefaultLighting : public GpuTest {
protected:
    void expectSameSeedAgreement(const std::string& name, const LoadedTestScene& scene,
                                 const RenderSettings& settings) {
        RenderOutput gpu = renderOnDevice(context(), scene, settings);
        RenderOutput cpu = renderTestScene(scene, settings);
        const SameSeedAgreement a = compareSameSeed(gpu, cpu);
        std::printf("%s: %s; mean luminance %.4f\n", name.c_str(), a.summary().c_str(),
                    meanLuminance(cpu).mean);
        EXPECT_GE(a.fraction(), kSameSeedMinimumAgreement) << writeComparisonImages(name, gpu, cpu);
        EXPECT_GT(meanLuminance(cpu).mean, 0.05) << name << ": the studio leaves the image dark";
    }

    void expectSameDistribution(const std::string& name, const LoadedTestScene& scene,
                                RenderSettings settings) {
        settings.seed = 1;
        RenderOutput gpu = renderOnDevice(context(), scene, settings);
        settings.seed = 2;
        RenderOutput cpu = renderTestScene(scene, settings);
        expectSameImage(gpu, cpu, name);
    }
};

TEST_F(DefaultLighting, ASceneWithoutLightsMatchesTheReferenceAtOneSeed) {
    RenderSettings settings = testSettings(24, 16);
    settings.seed = 7;
    expectSameSeedAgreement("studio_no_lights", loadWithDefaultLighting("test/no-lights.gltf"),
                            settings);
}

TEST_F(DefaultLighting, ASceneWithoutLightsMatchesTheReferenceInDistribution) {
    expectSameDistribution("studio_no_lights_seeds", loadWithDefaultLighting("test/no-lights.gltf"),
                           testSettings(24, 64));
}

// A published asset with textures, normal maps and metal: DamagedHelmet, whose emissive panels
// are too faint to light it (docs/scene-model.md, "Default lighting").
TEST_F(DefaultLighting, APublishedAssetMatchesTheReference) {
    const std::string helmet = "../../shared/scenes/DamagedHelmet/DamagedHelmet.glb";
    if (!std::filesystem::exists(scenePath(helmet))) GTEST_SKIP() << helmet << " is not present";
    const LoadedTestScene scene = loadWithDefaultLighting(helmet);
    RenderSettings settings = testSettings(32, 8);
    settings.seed = 11;
    expectSameSeedAgreement("studio_helmet", scene, settings);
    expectSameDistribution("studio_helmet_seeds", scene, testSettings(32, 48));
}

} // namespace
} // namespace vkpt::test::default_lighting_render_test
