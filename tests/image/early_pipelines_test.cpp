// early_pipelines_test.cpp — pipelines created while the scene is prepared are taken only when
// they were made for what the render needs (the kernels' features and build, the AOV switch,
// no array split into chunks), a render that takes them gives the image of pipelines created
// after the upload, bit for bit, and hands them back for the next render to take.
#include "lib/wavefront.h"
#include "render/early_pipelines.h"
#include "wavefront_test_support.h"

namespace vkpt::test {
namespace {

class EarlyPipelinesTest : public GpuTest {};

TEST_F(EarlyPipelinesTest, ARenderTakesThemAndGivesTheSameImage) {
    const LoadedTestScene box = loadTestScene("cornell-box.gltf");
    RenderSettings settings = testSettings(16, 4);
    settings.seed = 5;
    const gpu::Camera camera =
        makeGpuCamera(selectCamera(box.scene, 0), settings.width, settings.height);
    const WavefrontResult created = renderWavefront(context(), box.prepared, camera, settings);
    EarlyPipelines early(context(), box.prepared.features, false, KernelBuilds::ForFeatureSet);
    WavefrontOptions options;
    options.earlyPipelines = &early;
    const WavefrontResult taken =
        renderWavefront(context(), box.prepared, camera, settings, options);
    EXPECT_FALSE(created.pipelinesCreatedEarly);
    EXPECT_TRUE(taken.pipelinesCreatedEarly);
    EXPECT_EQ(created.output.image.pixels, taken.output.image.pixels);
}

// An animation's frames: the kernels a render took come back when it ends, and the next render
// of the same features takes them again and gives the same image.
TEST_F(EarlyPipelinesTest, ARenderHandsThemBackForTheNext) {
    const LoadedTestScene box = loadTestScene("cornell-box.gltf");
    RenderSettings settings = testSettings(16, 4);
    EarlyPipelines early(context(), box.prepared.features, false, KernelBuilds::ForFeatureSet);
    EXPECT_TRUE(early.serves(box.prepared.features, false, KernelBuilds::ForFeatureSet));
    EXPECT_FALSE(early.serves(box.prepared.features, true, KernelBuilds::ForFeatureSet));
    WavefrontOptions options;
    options.earlyPipelines = &early;
    const gpu::Camera camera =
        makeGpuCamera(selectCamera(box.scene, 0), settings.width, settings.height);
    const WavefrontResult first =
        renderWavefront(context(), box.prepared, camera, settings, options);
    const WavefrontResult second =
        renderWavefront(context(), box.prepared, camera, settings, options);
    EXPECT_TRUE(first.pipelinesCreatedEarly);
    EXPECT_TRUE(second.pipelinesCreatedEarly);
    EXPECT_EQ(first.output.image.pixels, second.output.image.pixels);
}

// A refusal leaves them to be taken by the render they were made for.
TEST_F(EarlyPipelinesTest, RefusedForAnythingButTheInputsTheyWereMadeFor) {
    const LoadedTestScene box = loadTestScene("cornell-box.gltf");
    const SceneFeatures features = box.prepared.features;
    const std::vector<SpecializationConstant> plain{aovConstant(false)};
    EarlyPipelines early(context(), features, false, KernelBuilds::ForFeatureSet);
    const auto taken =
        [&](const SceneFeatures& asked, const std::vector<SpecializationConstant>& constants,
            KernelBuilds builds) { return early.take(asked, constants, builds).has_value(); };
    EXPECT_FALSE(taken(features, {aovConstant(true)}, KernelBuilds::ForFeatureSet)) << "AOVs";
    const std::vector<SpecializationConstant> chunked{
        {SPEC_SCENE_ARRAY_CHUNKS(BINDING_TRIANGLES), 2},
        {SPEC_SCENE_ARRAY_CHUNK_LOG2(BINDING_TRIANGLES), 20},
        aovConstant(false)};
    EXPECT_FALSE(taken(features, chunked, KernelBuilds::ForFeatureSet)) << "a chunked array";
    SceneFeatures layered = features;
    layered.metallicRoughnessMaterials = true;
    EXPECT_FALSE(taken(layered, plain, KernelBuilds::ForFeatureSet)) << "other features";
    EXPECT_FALSE(taken(features, plain, KernelBuilds::Full)) << "the full build";
    const std::optional<std::vector<Kernel>> kernels =
        early.take(features, plain, KernelBuilds::ForFeatureSet);
    ASSERT_TRUE(kernels.has_value());
    EXPECT_EQ(kernels->size(), kWavefrontKernelCount);
    EXPECT_FALSE(taken(features, plain, KernelBuilds::ForFeatureSet)) << "taken twice";
}

} // namespace
} // namespace vkpt::test
