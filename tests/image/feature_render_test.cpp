// feature_render_test.cpp — the scene model's features on the device (feature_scenes.h):
// spheres, metallic-roughness materials, textures, alpha cut-outs, punctual lights and the
// environment. At one seed vkpt and vkpt-ref trace the same paths, so their images agree pixel
// by pixel up to float rounding (docs/wavefront.md).
#include <cstdio>
#include <string>

#include "feature_scenes.h"
#include "wavefront_test_support.h"

namespace vkpt::test::feature_render_test {
namespace {

using feature_scenes::featureScenes;
using feature_scenes::NamedScene;
using feature_scenes::prepareTestScene;

std::string nameOf(const ::testing::TestParamInfo<NamedScene>& info) {
    return info.param.name;
}

class FeatureScenes : public GpuTest, public ::testing::WithParamInterface<NamedScene> {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        scene_ = prepareTestScene(GetParam().make());
    }

    void expectSameSeedAgreement(const std::string& label, const RenderSettings& settings) {
        const std::string name = GetParam().name + "_" + label;
        RenderStats gpuStats, cpuStats;
        RenderOutput gpu = renderOnDevice(context(), scene_, settings, &gpuStats);
        RenderOutput cpu = renderTestScene(scene_, settings, &cpuStats);
        SameSeedAgreement a = compareSameSeed(gpu, cpu);
        std::printf("%s (%s): %s; rays %llu vs %llu\n", name.c_str(),
                    describeFeatures(scene_.prepared.usedFeatures).c_str(), a.summary().c_str(),
                    (unsigned long long)gpuStats.rays.total(),
                    (unsigned long long)cpuStats.rays.total());
        EXPECT_GE(a.fraction(), kSameSeedMinimumAgreement) << writeComparisonImages(name, gpu, cpu);
        EXPECT_EQ(gpuStats.samplesTaken, cpuStats.samplesTaken);
        // A black image would agree trivially; but hemisphere probes cannot hit a punctual
        // light, so a scene lit by those alone is black to them.
        const bool probes = settings.integrator == Integrator::Direct &&
                            settings.lightSampling == LightSampling::Hemisphere;
        if (probes && onlyPunctualLights()) {
            EXPECT_EQ(totalOf(gpu), 0.0) << name << ": probes found a punctual light";
        } else {
            EXPECT_GT(totalOf(gpu), 0.0) << name << ": the image is black";
        }
    }

    bool onlyPunctualLights() const {
        for (const gpu::Emitter& e : scene_.prepared.emitters)
            if (e.kind == EMITTER_TRIANGLE || e.kind == EMITTER_SPHERE ||
                e.kind == EMITTER_ENVIRONMENT)
                return false;
        return true;
    }

    static double totalOf(const RenderOutput& output) {
        double sum = 0.0;
        for (const glm::vec3& p : output.image.pixels)
            sum += double(p.x + p.y + p.z);
        return sum;
    }

    LoadedTestScene scene_;
};

// Every check of a scene runs on one device, so that the scene's pipelines are created once for
// the path tracer, both direct estimators and the normals (the integrator is a push constant, not
// a specialisation). The same scenes under the general kernels: specialised_vs_general_test.cpp.
TEST_P(FeatureScenes, EveryIntegratorMatchesTheReference) {
    {
        SCOPED_TRACE("path tracer");
        RenderSettings settings = testSettings(24, 8);
        settings.seed = 21;
        settings.lightSamples = 2;
        expectSameSeedAgreement("path", settings);
    }
    {
        SCOPED_TRACE("direct integrators");
        RenderSettings settings = testSettings(20, 4);
        settings.seed = 22;
        settings.integrator = Integrator::Direct;
        settings.lightSamples = 3;
        expectSameSeedAgreement("direct_light", settings);
        settings.lightSampling = LightSampling::Hemisphere;
        expectSameSeedAgreement("direct_hemisphere", settings);
    }
    {
        SCOPED_TRACE("normals");
        RenderSettings settings = testSettings(20, 1);
        settings.integrator = Integrator::Normals;
        expectSameSeedAgreement("normals", settings);
    }
}

INSTANTIATE_TEST_SUITE_P(Features, FeatureScenes, ::testing::ValuesIn(featureScenes()), nameOf);

} // namespace
} // namespace vkpt::test::feature_render_test
