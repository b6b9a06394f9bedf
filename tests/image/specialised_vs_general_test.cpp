// specialised_vs_general_test.cpp — kernels specialised to a scene's features render the same
// image as the general kernels (every feature on, every array uploaded: --general) at the same
// seed, up to float rounding: specialisation only removes code the scene cannot reach. Also
// checks that the specialised render uploads no more than the general one, and prints both
// renders' pipeline-creation time and scene memory for comparison.
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <span>
#include <string>
#include <vector>

#include "common/errors.h"
#include "feature_scenes.h"
#include "lib/wavefront.h"
#include "wavefront_test_support.h"

namespace vkpt::test {
namespace {

using feature_scenes::featureScenes;
using feature_scenes::NamedScene;
using feature_scenes::prepareTestScene;
using feature_scenes::sphereScene;

std::string identifierOf(std::string name) {
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return name;
}

std::string testNameOf(const ::testing::TestParamInfo<std::string>& info) {
    return identifierOf(info.param);
}

WavefrontResult render(GpuContext& context, const LoadedTestScene& loaded,
                       const RenderSettings& settings, const WavefrontOptions& options = {}) {
    gpu::Camera camera = makeGpuCamera(selectCamera(loaded.scene, settings.cameraIndex),
                                       settings.width, settings.height);
    WavefrontResult result = renderWavefront(context, loaded.prepared, camera, settings, options);
    EXPECT_EQ(result.truncatedTraversals, 0u) << "BVH walks cut short by a loop limit";
    return result;
}

// Every pixel and channel within the same-seed bound of docs/wavefront.md.
void expectSameImage(const std::string& name, const RenderOutput& specialised,
                     const RenderOutput& general) {
    SameSeedAgreement agreement = compareSameSeed(specialised, general);
    std::printf("%s: %s\n", name.c_str(), agreement.summary().c_str());
    EXPECT_EQ(agreement.within, agreement.pixels)
        << agreement.summary() << "; " << writeComparisonImages(name, specialised, general);
}

// A scene file prepared twice: for its own features and for all of them (--general).
// (loadFeatureTestScene loads any scene as loadTestScene does, an environment where one belongs.)
class SceneComparison {
public:
    explicit SceneComparison(const std::string& path)
        : path_(path), specialised_(loadFeatureTestScene(path)),
          general_(loadFeatureTestScene(path, true)) {}

    void compare(GpuContext& context, const std::string& label, const RenderSettings& settings) {
        WavefrontResult s = render(context, specialised_, settings);
        WavefrontResult g = render(context, general_, settings);
        std::printf("%s %s: pipelines %.3f s specialised, %.3f s general; scene buffers %llu "
                    "bytes specialised, %llu bytes general\n",
                    path_.c_str(), label.c_str(), s.pipelineCreationSeconds,
                    g.pipelineCreationSeconds, (unsigned long long)s.sceneBufferBytes,
                    (unsigned long long)g.sceneBufferBytes);
        EXPECT_LE(s.sceneBufferBytes, g.sceneBufferBytes) << path_;
        expectSameImage(identifierOf(path_) + "_" + label, s.output, g.output);
    }

private:
    std::string path_;
    LoadedTestScene specialised_;
    LoadedTestScene general_;
};

RenderSettings pathSettings() {
    RenderSettings settings = testSettings(24, 8);
    settings.seed = 11;
    settings.lightSamples = 2;
    return settings;
}

RenderSettings directSettings(LightSampling sampling) {
    RenderSettings settings = testSettings(16, 4);
    settings.seed = 12;
    settings.integrator = Integrator::Direct;
    settings.lightSamples = 2;
    settings.lightSampling = sampling;
    return settings;
}

class SpecialisedVsGeneral : public GpuTest, public ::testing::WithParamInterface<std::string> {};

// Every integrator on one device: the integrator is a push constant, so the scene's two
// pipeline sets (specialised and general) are created once for all four renders.
TEST_P(SpecialisedVsGeneral, EveryIntegratorGivesTheSameImage) {
    SceneComparison scene(GetParam());
    scene.compare(context(), "path", pathSettings());
    scene.compare(context(), "direct_light", directSettings(LightSampling::Light));
    scene.compare(context(), "direct_hemisphere", directSettings(LightSampling::Hemisphere));
    RenderSettings normals = testSettings(16, 1);
    normals.integrator = Integrator::Normals;
    scene.compare(context(), "normals", normals);
}

// The Cornell box and scenes with double-sided emitters.
INSTANTIATE_TEST_SUITE_P(Scenes, SpecialisedVsGeneral,
                         ::testing::Values("cornell-box.gltf", "test/furnace-double-sided.gltf",
                                           "test/emission-sides.gltf"),
                         testNameOf);

class SpecialisedVsGeneralFeatureFiles : public GpuTest {};

TEST_F(SpecialisedVsGeneralFeatureFiles, EveryFeatureTestSceneGivesTheSameImage) {
    const std::vector<std::string> scenes = featureTestScenes();
    if (scenes.empty()) GTEST_SKIP() << "no scenes in " << scenePath("test/features");
    for (const std::string& path : scenes) {
        SCOPED_TRACE(path);
        SceneComparison scene(path);
        scene.compare(context(), "path", pathSettings());
        scene.compare(context(), "direct_hemisphere", directSettings(LightSampling::Hemisphere));
    }
}

class SceneUpload : public GpuTest {};

// The specialised upload leaves out what the scene does not have; absentData stands in.
TEST_F(SceneUpload, CornellBoxUploadsNoTexturesAndNoEnvironment) {
    LoadedTestScene box = loadTestScene("cornell-box.gltf");
    RenderSettings settings = testSettings(8, 1);
    WavefrontResult result = render(context(), box, settings);
    std::vector<std::string> names;
    for (const SceneBufferBytes& buffer : result.sceneBuffers)
        names.push_back(buffer.name);
    for (const char* absent :
         {"triangleUvs", "textures", "textureTexels", "environmentTexels", "environmentCdf"})
        EXPECT_EQ(std::count(names.begin(), names.end(), absent), 0) << absent;
    for (const char* present :
         {"absentData", "bvhNodes", "triangles", "triangleNormals", "materials", "emitters"})
        EXPECT_EQ(std::count(names.begin(), names.end(), present), 1) << present;
    EXPECT_GT(result.pipelineCreationSeconds, 0.0);
}

// The general kernels on a scene's own (specialised) buffers: features whose arrays are absent
// are switched on, so the kernels must still never read absentData (the data decide, e.g. no
// material has a texture), and the image is the scene's.
TEST_F(SceneUpload, GeneralKernelsNeedOnlyTheArraysTheSceneHas) {
    for (const NamedScene& named : featureScenes()) {
        LoadedTestScene scene = prepareTestScene(named.make());
        RenderSettings settings = testSettings(12, 2);
        settings.seed = 31;
        WavefrontOptions general;
        general.features = generalFeatures(scene.prepared.usedFeatures);
        RenderOutput own = render(context(), scene, settings).output;
        RenderOutput all = render(context(), scene, settings, general).output;
        SameSeedAgreement a = compareSameSeed(all, own);
        EXPECT_EQ(a.within, a.pixels) << named.name << ": " << a.summary();
    }
}

// Whether a SPIR-V module declares a variable at descriptor binding `binding` (an OpDecorate
// with the Binding decoration): spirv-opt removes the variables the code no longer reads.
bool declaresBinding(std::span<const std::uint32_t> spirv, std::uint32_t binding) {
    constexpr std::uint32_t kOpDecorate = 71, kDecorationBinding = 33, kHeaderWords = 5;
    for (std::size_t i = kHeaderWords; i < spirv.size();) {
        const std::uint32_t words = spirv[i] >> 16, opcode = spirv[i] & 0xffffu;
        if (words == 0) break;
        if (opcode == kOpDecorate && words >= 4 && spirv[i + 2] == kDecorationBinding &&
            spirv[i + 3] == binding)
            return true;
        i += words;
    }
    return false;
}

// The feature-set builds (shade_hits for Lambertian scenes, shaders/CMakeLists.txt) hold only
// what such a scene can reach — no layered BSDF, so not even its albedo tables' buffer — and
// render the full build's image bit for bit.
TEST_F(SceneUpload, LambertianScenesTakeTheDiffuseBuildAndRenderTheSameBits) {
    LoadedTestScene box = loadTestScene("cornell-box.gltf");
    const SceneFeatures& features = box.prepared.features;
    ASSERT_FALSE(features.metallicRoughnessMaterials);
    const auto diffuse = kernelSpirv(WavefrontKernel::ShadeHits, features);
    const auto full = kernelSpirv(WavefrontKernel::ShadeHits, features, KernelBuilds::Full);
    EXPECT_FALSE(declaresBinding(diffuse, BINDING_ALBEDO_TABLES));
    EXPECT_TRUE(declaresBinding(full, BINDING_ALBEDO_TABLES));
    SceneFeatures instanced = features;
    instanced.instances = true;
    EXPECT_FALSE(
        declaresBinding(kernelSpirv(WavefrontKernel::ShadeHits, instanced), BINDING_ALBEDO_TABLES));
    SceneFeatures layered = features;
    layered.metallicRoughnessMaterials = true;
    EXPECT_TRUE(
        declaresBinding(kernelSpirv(WavefrontKernel::ShadeHits, layered), BINDING_ALBEDO_TABLES));

    RenderSettings settings = testSettings(16, 4);
    settings.seed = 9;
    WavefrontOptions fullBuild;
    fullBuild.kernelBuilds = KernelBuilds::Full;
    const WavefrontResult lean = render(context(), box, settings);
    const WavefrontResult whole = render(context(), box, settings, fullBuild);
    std::printf("pipelines: %.3f s with the diffuse shade_hits, %.3f s with the full one\n",
                lean.pipelineCreationSeconds, whole.pipelineCreationSeconds);
    EXPECT_EQ(lean.output.image.pixels, whole.output.image.pixels);
    EXPECT_EQ(lean.stats.rays.total(), whole.stats.rays.total());
}

// GGX scenes without the newer material extensions take the core build of shade_hits
// (shaders/CMakeLists.txt: those features pruned), smaller than the full one, and render the
// full build's image bit for bit; a scene with anisotropy takes the full build. The GGX
// feature scene, 16 x 16 at 4 spp: every pixel compared.
TEST_F(SceneUpload, GgxScenesWithoutTheNewerExtensionsTakeTheCoreBuild) {
    LoadedTestScene ggx = loadFeatureTestScene("test/features/ggx.gltf");
    const SceneFeatures& features = ggx.prepared.features;
    ASSERT_TRUE(features.metallicRoughnessMaterials);
    const auto core = kernelSpirv(WavefrontKernel::ShadeHits, features);
    const auto full = kernelSpirv(WavefrontKernel::ShadeHits, features, KernelBuilds::Full);
    EXPECT_LT(core.size(), full.size());
    SceneFeatures anisotropic = features;
    anisotropic.anisotropy = true;
    EXPECT_EQ(kernelSpirv(WavefrontKernel::ShadeHits, anisotropic).size(), full.size());

    RenderSettings settings = testSettings(16, 4);
    settings.seed = 10;
    WavefrontOptions fullBuild;
    fullBuild.kernelBuilds = KernelBuilds::Full;
    const WavefrontResult lean = render(context(), ggx, settings);
    const WavefrontResult whole = render(context(), ggx, settings, fullBuild);
    std::printf("pipelines: %.3f s with the core shade_hits (%zu words), %.3f s with the full one "
                "(%zu words)\n",
                lean.pipelineCreationSeconds, core.size(), whole.pipelineCreationSeconds,
                full.size());
    EXPECT_EQ(lean.output.image.pixels, whole.output.image.pixels);
    EXPECT_EQ(lean.stats.rays.total(), whole.stats.rays.total());
}

// Kernels built without a feature the scene uses would drop it silently: refused instead.
TEST_F(SceneUpload, KernelsWithoutAFeatureTheSceneUsesAreRefused) {
    LoadedTestScene spheres = prepareTestScene(sphereScene());
    ASSERT_TRUE(spheres.prepared.usedFeatures.spheres);
    WavefrontOptions options;
    options.features = SceneFeatures{};
    EXPECT_THROW(render(context(), spheres, testSettings(8, 1), options), InternalError);
}

} // namespace
} // namespace vkpt::test
