// split_arrays_test.cpp — a scene whose arrays are split across several buffers (the path a
// scene larger than one binding takes, lib/scene_arrays.glsl) renders the very same image as
// when each array is one buffer: same seed, same data, same arithmetic, only the fetches go
// through the chunk selection, so the images must be equal bit for bit. The split is forced on
// small scenes by lowering the per-binding limit (VKPT_TEST_BINDING_BYTES).
#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "../support/room_scene.h"
#include "lib/wavefront.h"
#include "render/scene_arrays.h"
#include "scene/gltf_loader.h"
#include "wavefront_test_support.h"

namespace vkpt::test {
namespace {

// Sets VKPT_TEST_BINDING_BYTES for its lifetime.
class ForcedBindingLimit {
public:
    explicit ForcedBindingLimit(std::uint64_t bytes) {
        setenv("VKPT_TEST_BINDING_BYTES", std::to_string(bytes).c_str(), 1);
    }
    ~ForcedBindingLimit() { unsetenv("VKPT_TEST_BINDING_BYTES"); }
    ForcedBindingLimit(const ForcedBindingLimit&) = delete;
    ForcedBindingLimit& operator=(const ForcedBindingLimit&) = delete;
};

// The smallest power-of-two limit at which every splittable array fits the kernels' chunks:
// the largest array then takes three or four of them.
std::uint64_t splittingLimit(const PreparedScene& scene) {
    std::uint64_t largest = 0;
    for (const SceneArrayDesc& desc : sceneArrayList())
        if (desc.splittable) largest = std::max<std::uint64_t>(largest, desc.bytes(scene).size());
    return std::bit_ceil((largest + SCENE_ARRAY_MAX_CHUNKS - 1) / SCENE_ARRAY_MAX_CHUNKS);
}

WavefrontResult render(GpuContext& context, const LoadedTestScene& loaded,
                       const RenderSettings& settings) {
    gpu::Camera camera = makeGpuCamera(selectCamera(loaded.scene, settings.cameraIndex),
                                       settings.width, settings.height);
    WavefrontResult result = renderWavefront(context, loaded.prepared, camera, settings);
    EXPECT_EQ(result.truncatedTraversals, 0u) << "BVH walks cut short by a loop limit";
    return result;
}

std::uint32_t mostBuffers(const WavefrontResult& result) {
    std::uint32_t most = 0;
    for (const SceneBufferBytes& array : result.sceneBuffers) {
        std::printf("  %s: %llu bytes in %u buffers\n", array.name.c_str(),
                    (unsigned long long)array.bytes, array.buffers);
        most = std::max(most, array.buffers);
    }
    return most;
}

// The benchmarks' room with a textured sphere of about 2,000 triangles, written and loaded as
// vkpt would: its texture coordinates (24 bytes a triangle) are half as large as its
// triangles, so one limit splits both the texel arrays and this storage array.
LoadedTestScene texturedRoom() {
    const std::string path =
        (std::filesystem::current_path() / "split_textured_room.gltf").string();
    writeRoomSceneGltf(makeRoomScene(2000, true), path);
    LoadOptions options;
    options.warnUnsupportedExtensions = false;
    LoadedTestScene loaded{loadGltfScene(path, options), {}};
    loaded.prepared = prepareScene(loaded.scene);
    return loaded;
}

LoadedTestScene loadScene(const std::string& name) {
    return name == "textured room" ? texturedRoom() : loadFeatureTestScene(name);
}

class SplitArrays : public GpuTest, public ::testing::WithParamInterface<std::string> {};

TEST_P(SplitArrays, RenderTheSameImageAsWholeArrays) {
    const LoadedTestScene loaded = loadScene(GetParam());
    RenderSettings settings = testSettings(24, 4);
    settings.seed = 21;
    settings.lightSamples = 2;
    const WavefrontResult whole = render(context(), loaded, settings);
    ASSERT_EQ(mostBuffers(whole), 1u);
    const std::uint64_t limit = splittingLimit(loaded.prepared);
    std::printf("%s: split at %llu bytes per binding\n", GetParam().c_str(),
                (unsigned long long)limit);
    const ForcedBindingLimit forced(limit);
    const WavefrontResult split = render(context(), loaded, settings);
    EXPECT_GT(mostBuffers(split), 2u) << "the largest array should take three or four buffers";
    ASSERT_EQ(split.output.image.pixels.size(), whole.output.image.pixels.size());
    EXPECT_TRUE(split.output.image.pixels == whole.output.image.pixels)
        << writeComparisonImages("split_" + std::to_string(limit), split.output, whole.output);
    EXPECT_EQ(split.output.sampleCounts, whole.output.sampleCounts);
    if (GetParam() == "textured room") {
        const auto uvs =
            std::find_if(split.sceneBuffers.begin(), split.sceneBuffers.end(),
                         [](const SceneBufferBytes& array) { return array.name == "triangleUvs"; });
        ASSERT_NE(uvs, split.sceneBuffers.end());
        EXPECT_GE(uvs->buffers, 2u) << "the storage array should be split too";
    }
}

// The Cornell box splits texel arrays (triangles, normals, materials); the textured room also
// its texture coordinates, a storage array.
INSTANTIATE_TEST_SUITE_P(Scenes, SplitArrays,
                         ::testing::Values("cornell-box.gltf", "textured room"),
                         [](const ::testing::TestParamInfo<std::string>& scene) {
                             return scene.param == "cornell-box.gltf" ? std::string("CornellBox")
                                                                      : std::string("TexturedRoom");
                         });

TEST(SceneArrayChunks, WholeWhenItFits) {
    const ChunkPlan plan = planChunks(1000, 16, 16000);
    EXPECT_EQ(plan.chunkCount, 1u);
}

TEST(SceneArrayChunks, PowerOfTwoChunksBelowTheLimit) {
    // 1000 texels at 3000 bytes per binding: 187.5 texels fit, so chunks of 128 texels, 8 of
    // them (the last holds 104).
    const ChunkPlan plan = planChunks(1000, 16, 3000);
    EXPECT_EQ(plan.chunkLog2, 7u);
    EXPECT_EQ(plan.chunkCount, 8u);
}

TEST(SceneArrayChunks, OneElementPerChunkAtLeast) {
    const ChunkPlan plan = planChunks(3, 8, 4);
    EXPECT_EQ(plan.chunkLog2, 0u);
    EXPECT_EQ(plan.chunkCount, 3u);
}

} // namespace
} // namespace vkpt::test
