// specialised_vs_general_test.cpp — kernels specialised to a scene's features render the same
// image as the general kernels (every feature on, every array uploaded: --general) at the same
// seed, up to float rounding: specialisation only removes code the scene cannot reach. Also
// checks that the specialised render uploads no more than the general one, and prints both
// renders' pipeline-creation time and scene memory for comparison.
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "aov_agreement.h"
#include "common/errors.h"
#include "feature_scenes.h"
#include "gpu/spirv_specialise.h"
#include "lib/wavefront.h"
#include "wavefront_test_support.h"

namespace vkpt::test::specialised_vs_general_test {
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

    // Renders both at `settings` and compares them; returns the specialised render.
    WavefrontResult compare(GpuContext& context, const std::string& label,
                            const RenderSettings& settings) {
        WavefrontResult s = render(context, specialised_, settings);
        WavefrontResult g = render(context, general_, settings);
        std::printf("%s %s: pipelines %.3f s specialised, %.3f s general; scene buffers %llu "
                    "bytes specialised, %llu bytes general\n",
                    path_.c_str(), label.c_str(), s.pipelineCreationSeconds,
                    g.pipelineCreationSeconds, (unsigned long long)s.sceneBufferBytes,
                    (unsigned long long)g.sceneBufferBytes);
        EXPECT_LE(s.sceneBufferBytes, g.sceneBufferBytes) << path_;
        expectSameImage(identifierOf(path_) + "_" + label, s.output, g.output);
        return s;
    }

    const LoadedTestScene& specialised() const { return specialised_; }

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

class SpecialisedVsGeneral : public GpuTest {};

// Scene files under the kernels specialised to them and under the general ones, each test on
// one device, so that the general pipelines, the costliest to create, are created once for all
// its scenes and integrators (the integrator is a push constant; the device's kernel memo keeps
// each set). Two tests, so that each stays a few minutes even with a cold Mesa cache.

// The Cornell box and the scenes with double-sided emitters under every integrator.
TEST_F(SpecialisedVsGeneral, NamedScenesGiveTheGeneralKernelsImage) {
    for (const char* path :
         {"cornell-box.gltf", "test/furnace-double-sided.gltf", "test/emission-sides.gltf"}) {
        SCOPED_TRACE(path);
        SceneComparison scene(path);
        scene.compare(context(), "path", pathSettings());
        scene.compare(context(), "direct_light", directSettings(LightSampling::Light));
        scene.compare(context(), "direct_hemisphere", directSettings(LightSampling::Hemisphere));
        RenderSettings normals = testSettings(16, 1);
        normals.integrator = Integrator::Normals;
        scene.compare(context(), "normals", normals);
    }
}

// The feature test scenes (scenes/test/features) under the path tracer and both direct
// estimators against vkpt-ref at the same seed, and under the path tracer and the hemisphere
// probes against the general kernels: the specialised renders serve both comparisons; then
// their AOVs against vkpt-ref's (aov_agreement.h), with the same pipelines. In two
// halves (every other scene), each a process of its own: each half creates the general set
// once and its scenes' own sets, a few minutes with a cold Mesa cache.
class SpecialisedVsGeneralFeatureFiles : public GpuTest,
                                         public ::testing::WithParamInterface<int> {};

TEST_P(SpecialisedVsGeneralFeatureFiles, GiveTheReferenceAndTheGeneralKernelsImage) {
    const std::vector<std::string> scenes = featureTestScenes();
    ASSERT_FALSE(scenes.empty()) << "no scenes in " << scenePath("test/features");
    for (std::size_t i = std::size_t(GetParam()); i < scenes.size(); i += 2) {
        const std::string& path = scenes[i];
        SCOPED_TRACE(path);
        SceneComparison scene(path);
        const std::string name = std::filesystem::path(path).stem().string();
        RenderSettings settings = testSettings(24, 8);
        settings.seed = 6;
        settings.lightSamples = 2;
        WavefrontResult own = scene.compare(context(), "path", settings);
        expectSameSeedAsReference(name + "_path", scene.specialised(), settings, own.output,
                                  own.stats);
        settings = testSettings(16, 4);
        settings.integrator = Integrator::Direct;
        settings.lightSamples = 2;
        own = render(context(), scene.specialised(), settings);
        expectSameSeedAsReference(name + "_direct_light", scene.specialised(), settings, own.output,
                                  own.stats);
        settings.lightSampling = LightSampling::Hemisphere;
        own = scene.compare(context(), "direct_hemisphere", settings);
        expectSameSeedAsReference(name + "_direct_hemisphere", scene.specialised(), settings,
                                  own.output, own.stats);
        // The AOVs (textures: the albedo is the textured base colour; spheres, normal maps,
        // instances) against vkpt-ref's, under the path tracer: a render with AOVs takes the
        // pipelines just made (they are switched by a push constant, lib/aovs.glsl).
        RenderSettings aovs = testSettings(16, 2);
        aovs.seed = 12;
        aov_agreement::expectSameSeedAovs(context(), name + "_aovs", scene.specialised(), aovs);
    }
}

INSTANTIATE_TEST_SUITE_P(Halves, SpecialisedVsGeneralFeatureFiles, ::testing::Values(0, 1));

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

// The scene model's features (feature_scenes.h) under the general kernels, in one test on one
// device so that those pipelines are created once: prepared for every feature (every array
// uploaded, as --general does), and on the scene's own buffers, where features whose arrays are
// absent are switched on, so the kernels must still never read absentData (the data decide,
// e.g. no material has a texture). Both give the specialised kernels' image, every pixel.
TEST_F(SceneUpload, GeneralKernelsGiveEachFeatureSceneItsOwnImage) {
    for (const NamedScene& named : featureScenes()) {
        SCOPED_TRACE(named.name);
        LoadedTestScene scene = prepareTestScene(named.make());
        LoadedTestScene everyArray = prepareTestScene(scene.scene, true);
        RenderSettings settings = testSettings(20, 4);
        settings.seed = 23;
        settings.lightSamples = 2;
        WavefrontOptions ownArrays;
        ownArrays.features = generalFeatures(scene.prepared.usedFeatures);
        RenderOutput own = render(context(), scene, settings).output;
        expectSameImage(named.name + "_general", own,
                        render(context(), everyArray, settings).output);
        expectSameImage(named.name + "_general_own_arrays", own,
                        render(context(), scene, settings, ownArrays).output);
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

// `scene` rendered 16 x 16 at 4 spp with the pipelines made for its feature set and with the full
// build specialised by the driver, which must give the same image bit for bit and the same rays.
struct OwnAndFullBuild {
    WavefrontResult own;
    WavefrontResult full;
};
OwnAndFullBuild expectTheFullBuildsBits(GpuContext& context, const LoadedTestScene& scene,
                                        std::uint32_t seed) {
    RenderSettings settings = testSettings(16, 4);
    settings.seed = seed;
    WavefrontOptions fullBuild;
    fullBuild.kernelBuilds = KernelBuilds::Full;
    OwnAndFullBuild renders{render(context, scene, settings),
                            render(context, scene, settings, fullBuild)};
    EXPECT_EQ(renders.own.output.image.pixels, renders.full.output.image.pixels);
    EXPECT_EQ(renders.own.stats.rays.total(), renders.full.stats.rays.total());
    return renders;
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

    const OwnAndFullBuild renders = expectTheFullBuildsBits(context(), box, 9);
    std::printf("pipelines: %.3f s with the diffuse shade_hits, %.3f s with the full one\n",
                renders.own.pipelineCreationSeconds, renders.full.pipelineCreationSeconds);
}

// Pipelines get their feature constants folded into the module on the host (the default,
// gpu/spirv_specialise.h): for a GGX scene without the newer material extensions the module
// loses their code, and with anisotropy it keeps it; either way the image is the driver's own
// specialisation of the module as built, bit for bit, and so are the ray counts. The GGX and
// anisotropy feature scenes, 16 x 16 at 4 spp: every pixel compared.
TEST_F(SceneUpload, FeatureConstantsFoldedOnTheHostRenderTheDriversBits) {
    for (const char* path : {"test/features/ggx.gltf", "test/features/anisotropy.gltf"}) {
        SCOPED_TRACE(path);
        LoadedTestScene scene = loadFeatureTestScene(path);
        const SceneFeatures& features = scene.prepared.features;
        ASSERT_TRUE(features.metallicRoughnessMaterials);
        const KernelDesc desc = wavefrontKernelDesc(WavefrontKernel::ShadeHits, features);
        ASSERT_TRUE(desc.foldConstantsOnHost);
        const std::size_t folded = specialiseSpirv(desc).size();
        SceneFeatures withoutAnisotropy = features;
        withoutAnisotropy.anisotropy = false;
        const std::size_t plainFolded =
            specialiseSpirv(wavefrontKernelDesc(WavefrontKernel::ShadeHits, withoutAnisotropy))
                .size();
        EXPECT_LT(folded, desc.spirv.size());
        if (features.anisotropy) {
            EXPECT_GT(folded, plainFolded) << "anisotropy's code must stay";
        }

        const OwnAndFullBuild renders = expectTheFullBuildsBits(context(), scene, 10);
        std::printf("%s: pipelines %.3f s folded on the host (shade_hits %zu of %zu words), "
                    "%.3f s specialised by the driver\n",
                    path, renders.own.pipelineCreationSeconds, folded, desc.spirv.size(),
                    renders.full.pipelineCreationSeconds);
    }
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
} // namespace vkpt::test::specialised_vs_general_test
