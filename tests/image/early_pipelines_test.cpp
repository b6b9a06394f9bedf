// early_pipelines_test.cpp — pipelines created while the scene is prepared are taken only when
// they were made for what the render needs (the kernels' features and build, no array split
// into chunks), and a render that takes them gives the image of pipelines created after the
// upload, bit for bit. Later renders on the same device take the pipelines earlier ones made
// (gpu/kernel_memo.h), renders with AOVs those of renders without.
#include <algorithm>

#include "lib/wavefront.h"
#include "render/early_pipelines.h"
#include "wavefront_test_support.h"

namespace vkpt::test::early_pipelines_test {
namespace {

class EarlyPipelinesTest : public GpuTest {};

TEST_F(EarlyPipelinesTest, ARenderTakesThemAndGivesTheSameImage) {
    const LoadedTestScene box = loadTestScene("cornell-box.gltf");
    RenderSettings settings = testSettings(16, 4);
    settings.seed = 5;
    const gpu::Camera camera =
        makeGpuCamera(selectCamera(box.scene, 0), settings.width, settings.height);
    const WavefrontResult created = renderWavefront(context(), box.prepared, camera, settings);
    EarlyPipelines early(context(), box.prepared.features, KernelBuilds::ForFeatureSet);
    WavefrontOptions options;
    options.earlyPipelines = &early;
    const WavefrontResult taken =
        renderWavefront(context(), box.prepared, camera, settings, options);
    EXPECT_FALSE(created.pipelinesCreatedEarly);
    EXPECT_TRUE(taken.pipelinesCreatedEarly);
    EXPECT_EQ(created.output.image.pixels, taken.output.image.pixels);
}

// A refusal leaves them to be taken by the render they were made for.
TEST_F(EarlyPipelinesTest, RefusedForAnythingButTheInputsTheyWereMadeFor) {
    const LoadedTestScene box = loadTestScene("cornell-box.gltf");
    const SceneFeatures features = box.prepared.features;
    const std::vector<SpecializationConstant> plain;
    EarlyPipelines early(context(), features, KernelBuilds::ForFeatureSet);
    const auto taken =
        [&](const SceneFeatures& asked, const std::vector<SpecializationConstant>& constants,
            KernelBuilds builds) { return early.take(asked, constants, builds).has_value(); };
    const std::vector<SpecializationConstant> chunked{
        {SPEC_SCENE_ARRAY_CHUNKS(BINDING_TRIANGLES), 2},
        {SPEC_SCENE_ARRAY_CHUNK_LOG2(BINDING_TRIANGLES), 20}};
    EXPECT_FALSE(taken(features, chunked, KernelBuilds::ForFeatureSet)) << "a chunked array";
    SceneFeatures layered = features;
    layered.metallicRoughnessMaterials = true;
    EXPECT_FALSE(taken(layered, plain, KernelBuilds::ForFeatureSet)) << "other features";
    EXPECT_FALSE(taken(features, plain, KernelBuilds::Full)) << "the full build";
    const std::optional<WavefrontKernelSet> kernels =
        early.take(features, plain, KernelBuilds::ForFeatureSet);
    ASSERT_TRUE(kernels.has_value());
    EXPECT_EQ(kernels->kernels.size(), kWavefrontKernelCount);
    EXPECT_FALSE(taken(features, plain, KernelBuilds::ForFeatureSet)) << "taken twice";
}

class KernelMemoTest : public GpuTest {};

// A second render on the same device takes every pipeline the first made (no creation time, the
// same image bit for bit); a render with other features or the full build (specialised by the
// driver) makes its own, once.
TEST_F(KernelMemoTest, RendersOnOneDeviceCreateEachPipelineOnce) {
    const LoadedTestScene box = loadTestScene("cornell-box.gltf");
    RenderSettings settings = testSettings(16, 4);
    const gpu::Camera camera =
        makeGpuCamera(selectCamera(box.scene, 0), settings.width, settings.height);
    const auto createdCount = [](const WavefrontResult& result) {
        return std::count_if(result.pipelineCreations.begin(), result.pipelineCreations.end(),
                             [](const PipelineCreation& p) { return p.seconds > 0.0; });
    };
    const WavefrontResult first = renderWavefront(context(), box.prepared, camera, settings);
    EXPECT_EQ(createdCount(first), std::ptrdiff_t(kWavefrontKernelCount));
    EXPECT_EQ(context().kernelMemo().size(), kWavefrontKernelCount);
    const WavefrontResult second = renderWavefront(context(), box.prepared, camera, settings);
    EXPECT_EQ(createdCount(second), 0);
    EXPECT_EQ(first.output.image.pixels, second.output.image.pixels);

    // A render that records AOVs takes the same pipelines (the switch is a push constant,
    // lib/aovs.glsl) and gives the same colour.
    WavefrontOptions aovs;
    aovs.aovs = true;
    const WavefrontResult withAovs =
        renderWavefront(context(), box.prepared, camera, settings, aovs);
    EXPECT_EQ(createdCount(withAovs), 0);
    EXPECT_EQ(withAovs.features.size(), std::size_t(settings.width) * settings.height);
    EXPECT_EQ(first.output.image.pixels, withAovs.output.image.pixels);

    WavefrontOptions full;
    full.kernelBuilds = KernelBuilds::Full;
    const WavefrontResult whole = renderWavefront(context(), box.prepared, camera, settings, full);
    // The kernels specialised for the scene's features have constants, which the full build
    // leaves to the driver instead of folding them on the host: pipelines of their own. The
    // others have none (the Cornell box splits no array), so both builds are the same module,
    // which the memo already holds.
    std::ptrdiff_t specialised = 0;
    for (std::size_t k = 0; k < kWavefrontKernelCount; ++k)
        if (isSpecialised(WavefrontKernel(k))) ++specialised;
    EXPECT_GT(specialised, 0);
    EXPECT_EQ(createdCount(whole), specialised);
    EXPECT_EQ(first.output.image.pixels, whole.output.image.pixels);
    const std::size_t kept = context().kernelMemo().size();
    renderWavefront(context(), box.prepared, camera, settings, full);
    EXPECT_EQ(context().kernelMemo().size(), kept) << "nothing made twice";
}

} // namespace
} // namespace vkpt::test::early_pipelines_test
