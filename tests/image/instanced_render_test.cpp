// instanced_render_test.cpp — two-level scenes render the image of the same scene flattened.
// Every feature scene (textures, normal maps, alpha cut-outs, glass, clearcoat, sheen, spheres,
// punctual lights, environments) is turned into a two-level scene whose one mesh holds all its
// non-emitting triangles (test::instanceWholeScene); and the loader's own instancing of a
// generated file (tests/support/instanced_scene.h: shared meshes, EXT_mesh_gpu_instancing) is
// compared with its flattening.
//
// Placed by a transform that floats carry exactly (a quarter turn, power-of-two scales with a
// mirror, a dyadic move), the mesh's rays and hits round as the flattened scene's do, so at one
// seed both trace the same paths and the images agree pixel by pixel in the bound of
// docs/wavefront.md, on vkpt and on vkpt-ref. Placed by a general transform (turned about a
// slanted axis, scaled unevenly, mirrored), a wall's normal is axis-aligned in the flattened
// scene but a few 1e-10 off in the placed one; the shading frame's construction (Duff et al.
// 2017) branches on the sign of its z, so some paths take the mirror image of their flattened
// twin: same distribution, other samples. There the images are held equal per pixel by Welch's
// test (expectSameImage), and vkpt to vkpt-ref at one seed.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "../support/instancing.h"
#include "../support/render_checks.h"
#include "../support/scratch_directory.h"
#include "feature_scenes.h"
#include "instanced_scene.h"
#include "wavefront_test_support.h"

namespace vkpt::test::instanced_render_test {
namespace {

// A quarter turn about y, scaled by (2, −0.5, 1) (a mirror) and moved by dyadic steps, written
// out so that every entry and its inverse's is exact in float.
glm::dmat4 exactPlacement() {
    glm::dmat4 t(0.0);
    t[0] = glm::dvec4(0.0, 0.0, -2.0, 0.0); // x → −2z
    t[1] = glm::dvec4(0.0, -0.5, 0.0, 0.0); // y → −y/2
    t[2] = glm::dvec4(1.0, 0.0, 0.0, 0.0);  // z → x
    t[3] = glm::dvec4(0.25, -0.5, 0.125, 1.0);
    return t;
}

// Turned 40° about (1, 2, 3), scaled by (1.5, −0.75, 1.2) (a mirror) and moved.
glm::dmat4 generalPlacement() {
    glm::dmat4 t = glm::translate(glm::dmat4(1.0), glm::dvec3(0.3, -0.2, 0.5));
    t = glm::rotate(t, 0.7, glm::normalize(glm::dvec3(1.0, 2.0, 3.0)));
    return glm::scale(t, glm::dvec3(1.5, -0.75, 1.2));
}

struct ScenePair {
    LoadedTestScene flat;
    LoadedTestScene instanced; // placed exactly: the same paths as flat
    LoadedTestScene turned;    // placed by a general transform
};

LoadedTestScene prepared(Scene scene) {
    LoadedTestScene loaded{std::move(scene), {}};
    loaded.prepared = prepareScene(loaded.scene);
    return loaded;
}

// All frame with the flattened scene's camera: a scene without one is framed by its bounds,
// which for instances are their transformed boxes, a little larger.
ScenePair pairOf(LoadedTestScene flat, Scene instanced, Scene turned) {
    flat.scene.cameras = {selectCamera(flat.scene, std::nullopt, 1.0f)};
    instanced.cameras = turned.cameras = flat.scene.cameras;
    return {std::move(flat), prepared(std::move(instanced)), prepared(std::move(turned))};
}

struct InstancedCase {
    std::string name;
    ScenePair (*make)();
};

void PrintTo(const InstancedCase& c, std::ostream* out) {
    *out << c.name;
}

ScenePair wholeScene(Scene flat) {
    Scene instanced = instanceWholeScene(flat, exactPlacement());
    Scene turned = instanceWholeScene(flat, generalPlacement());
    return pairOf(feature_scenes::prepareTestScene(std::move(flat)), std::move(instanced),
                  std::move(turned));
}

ScenePair wholeSceneFile(const std::string& relative) {
    LoadedTestScene flat = loadFeatureTestScene(relative);
    Scene instanced = instanceWholeScene(flat.scene, exactPlacement());
    Scene turned = instanceWholeScene(flat.scene, generalPlacement());
    return pairOf(std::move(flat), std::move(instanced), std::move(turned));
}

// The generated scene as the loader reads it: flattened, and with every mesh kept once.
ScenePair generatedFile() {
    const std::string path = scratchPath("instanced_scene.gltf");
    InstancedSceneSpec spec;
    spec.columns = spec.rows = 3;
    writeInstancedScene(spec, path);
    LoadOptions options;
    options.warnUnsupportedExtensions = false;
    options.instancing = Instancing::Off;
    LoadedTestScene flat{loadGltfScene(path, options), {}};
    flat.prepared = prepareScene(flat.scene);
    options.instancing = Instancing::On;
    // The file's placements turn about y by any angle: its own general case.
    Scene instanced = loadGltfScene(path, options);
    return pairOf(std::move(flat), instanced, instanced);
}

std::vector<InstancedCase> instancedCases() {
    std::vector<InstancedCase> cases;
    cases.push_back({"generated_file", generatedFile});
    cases.push_back({"spheres", [] { return wholeScene(feature_scenes::sphereScene()); }});
    cases.push_back({"textures", [] { return wholeScene(feature_scenes::textureScene()); }});
    cases.push_back({"alpha_mask", [] { return wholeScene(feature_scenes::alphaMaskScene()); }});
    cases.push_back({"punctual", [] { return wholeScene(feature_scenes::punctualScene()); }});
    cases.push_back({"everything", [] { return wholeScene(feature_scenes::everythingScene()); }});
    cases.push_back({"cornell_box", [] { return wholeSceneFile("cornell-box.gltf"); }});
    cases.push_back({"normal_map", [] { return wholeSceneFile("test/features/normal_map.gltf"); }});
    cases.push_back({"clearcoat", [] { return wholeSceneFile("test/features/clearcoat.gltf"); }});
    cases.push_back({"sheen", [] { return wholeSceneFile("test/features/sheen.gltf"); }});
    cases.push_back({"glass", [] { return wholeSceneFile("test/features/glass.gltf"); }});
    cases.push_back(
        {"environment_map", [] { return wholeSceneFile("test/features/environment.gltf"); }});
    return cases;
}

std::string nameOf(const ::testing::TestParamInfo<InstancedCase>& info) {
    return info.param.name;
}

class InstancedScenes : public GpuTest, public ::testing::WithParamInterface<InstancedCase> {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        scenes_ = GetParam().make();
        ASSERT_TRUE(scenes_.instanced.prepared.features.instances);
        ASSERT_TRUE(scenes_.turned.prepared.features.instances);
        ASSERT_FALSE(scenes_.flat.prepared.features.instances);
    }

    static RenderSettings settings() {
        RenderSettings s = testSettings(20, 4);
        s.seed = 31;
        s.lightSamples = 2;
        return s;
    }

    void expectAgreement(const std::string& what, const RenderOutput& a, const RenderOutput& b) {
        const std::string name = GetParam().name + "_" + what;
        SameSeedAgreement agreement = compareSameSeed(a, b);
        std::printf("%s: %s\n", name.c_str(), agreement.summary().c_str());
        EXPECT_GE(agreement.fraction(), kSameSeedMinimumAgreement)
            << writeComparisonImages(name, a, b);
        double total = 0.0;
        for (const glm::vec3& p : a.image.pixels)
            total += double(p.x + p.y + p.z);
        EXPECT_GT(total, 0.0) << name << ": the image is black";
    }

    ScenePair scenes_;
};

// Both on one device: the turned placement takes the instanced scene's pipelines (its features
// are the same), so the two checks create two pipeline sets instead of three.
TEST_P(InstancedScenes, DeviceRendersTheFlattenedImageAndTheReferenceUnderAGeneralPlacement) {
    {
        SCOPED_TRACE("instanced against flattened");
        expectAgreement("device", renderOnDevice(context(), scenes_.instanced, settings()),
                        renderOnDevice(context(), scenes_.flat, settings()));
    }
    SCOPED_TRACE("a general placement against the reference");
    expectAgreement("device_vs_reference", renderOnDevice(context(), scenes_.turned, settings()),
                    renderTestScene(scenes_.turned, settings()));
}

TEST_P(InstancedScenes, ReferenceRendersTheFlattenedImage) {
    expectAgreement("reference", renderTestScene(scenes_.instanced, settings()),
                    renderTestScene(scenes_.flat, settings()));
}

// Welch's test per pixel at family-wise α = 0.01 (render_checks.h), variances from the images;
// vkpt-ref renders both, 16 samples a pixel.
TEST_P(InstancedScenes, GeneralPlacementRendersTheFlattenedImageInDistribution) {
    RenderSettings s = settings();
    s.samplesPerPixel = 16;
    const RenderOutput turned = renderTestScene(scenes_.turned, s);
    s.seed = 32; // independent samples, as the test assumes
    expectSameImage(turned, renderTestScene(scenes_.flat, s), GetParam().name);
}

INSTANTIATE_TEST_SUITE_P(Instancing, InstancedScenes, ::testing::ValuesIn(instancedCases()),
                         nameOf);

// 103 million placed triangles (6,272 spheres of 16,384 triangles and as many boxes), which the
// default rule instances: the scene takes a few MiB of device memory and renders on lavapipe.
// Flattened it would need about 11 GB of scene arrays.
class HundredMillionTriangles : public GpuTest {};

TEST_F(HundredMillionTriangles, RenderInstancedByDefault) {
    const std::string path = scratchPath("hundred_million.gltf");
    InstancedSceneSpec spec;
    spec.columns = spec.rows = 112;
    spec.rings = 64;
    spec.separateBuffer = true;
    writeInstancedScene(spec, path);
    LoadOptions options;
    options.warnUnsupportedExtensions = false;
    LoadedTestScene loaded{loadGltfScene(path, options), {}};
    EXPECT_GE(loaded.scene.placedTriangleCount(), 100000000u);
    EXPECT_LT(loaded.scene.storedTriangleCount(), 20000u);
    loaded.prepared = prepareScene(loaded.scene);
    ASSERT_TRUE(loaded.prepared.features.instances);
    RenderSettings settings = testSettings(32, 1);
    settings.maxDepth = 2;
    WavefrontResult result = renderWavefront(
        context(), loaded.prepared,
        makeGpuCamera(selectCamera(loaded.scene, std::nullopt), settings.width, settings.height),
        settings, {});
    EXPECT_EQ(result.truncatedTraversals, 0u);
    double total = 0.0;
    for (const glm::vec3& p : result.output.image.pixels) {
        ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
        total += double(p.x + p.y + p.z);
    }
    EXPECT_GT(total, 0.0);
    const std::uint64_t sceneBytes = result.sceneBufferBytes;
    std::printf("%llu placed triangles, %llu stored, %zu instances: scene buffers %.2f MiB, peak "
                "device memory %.2f MiB\n",
                static_cast<unsigned long long>(loaded.scene.placedTriangleCount()),
                static_cast<unsigned long long>(loaded.scene.storedTriangleCount()),
                loaded.scene.instances.size(), double(sceneBytes) / 1048576.0,
                double(context().memoryStats().peakBytes) / 1048576.0);
    EXPECT_LT(sceneBytes, 16u << 20);
}

} // namespace
} // namespace vkpt::test::instanced_render_test
