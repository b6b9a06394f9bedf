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
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "../support/room_scene.h"
#include "../support/scratch_directory.h"
#include "feature_scenes.h"
#include "lib/wavefront.h"
#include "render/scene_arrays.h"
#include "scene/gltf_loader.h"
#include "wavefront_test_support.h"

namespace vkpt::test::split_arrays_test {
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

// How many buffers the array `name` took (0: the scene has none).
std::uint32_t buffersOf(const WavefrontResult& result, const std::string& name) {
    const auto array =
        std::find_if(result.sceneBuffers.begin(), result.sceneBuffers.end(),
                     [&name](const SceneBufferBytes& bytes) { return bytes.name == name; });
    return array == result.sceneBuffers.end() ? 0u : array->buffers;
}

// The benchmarks' room with a textured sphere of about 2,000 triangles, written and loaded as
// vkpt would: its texture coordinates (24 bytes a triangle) are half as large as its
// triangles, so one limit splits both the texel arrays and this storage array.
LoadedTestScene texturedRoom() {
    const std::string path = scratchPath("split_textured_room.gltf");
    writeRoomSceneGltf(makeRoomScene(2000, true), path);
    LoadOptions options;
    options.warnUnsupportedExtensions = false;
    LoadedTestScene loaded{loadGltfScene(path, options), {}};
    loaded.prepared = prepareScene(loaded.scene);
    return loaded;
}

LoadedTestScene cornellBox() {
    return loadFeatureTestScene("cornell-box.gltf");
}

// The feature scenes' textures (feature_scenes.h) with the floor's and a sphere's texture
// (image 0) at 64 × 64 and no two texels alike, so that a texel read from the wrong chunk
// changes the image: its 16 KiB of texels are then the largest array, cut into three chunks.
LoadedTestScene largeTexture() {
    Scene scene = feature_scenes::textureScene();
    SceneImage& image = scene.images.at(0);
    image.width = 64;
    image.height = 64;
    image.texels.clear();
    for (std::uint32_t y = 0; y < image.height; ++y)
        for (std::uint32_t x = 0; x < image.width; ++x)
            image.texels.push_back((4 * x) | (4 * y) << 8 | ((7 * x + 13 * y) % 256) << 16 |
                                   255u << 24);
    return feature_scenes::prepareTestScene(std::move(scene));
}

// The feature scenes' environment map (32 × 16, a sun and a sky that changes row by row), lit
// by it alone: its texels (8 KiB) go into four chunks and its CDF (2 KiB and 64 bytes) into
// two, the last holding the marginal CDF.
LoadedTestScene environmentMap() {
    return feature_scenes::prepareTestScene(feature_scenes::environmentScene(true));
}

struct SplitCase {
    std::string name;
    LoadedTestScene (*load)();
    std::vector<std::string> splitArrays; // each must take two buffers or more
};

void PrintTo(const SplitCase& scene, std::ostream* out) {
    *out << scene.name;
}

class SplitArrays : public GpuTest, public ::testing::WithParamInterface<SplitCase> {};

TEST_P(SplitArrays, RenderTheSameImageAsWholeArrays) {
    const LoadedTestScene loaded = GetParam().load();
    RenderSettings settings = testSettings(24, 4);
    settings.seed = 21;
    settings.lightSamples = 2;
    const WavefrontResult whole = render(context(), loaded, settings);
    ASSERT_EQ(mostBuffers(whole), 1u);
    const std::uint64_t limit = splittingLimit(loaded.prepared);
    std::printf("%s: split at %llu bytes per binding\n", GetParam().name.c_str(),
                (unsigned long long)limit);
    const ForcedBindingLimit forced(limit);
    const WavefrontResult split = render(context(), loaded, settings);
    EXPECT_GT(mostBuffers(split), 2u) << "the largest array should take three or four buffers";
    for (const std::string& name : GetParam().splitArrays)
        EXPECT_GE(buffersOf(split, name), 2u) << name << " should be split too";
    ASSERT_EQ(split.output.image.pixels.size(), whole.output.image.pixels.size());
    EXPECT_TRUE(split.output.image.pixels == whole.output.image.pixels)
        << writeComparisonImages("split_" + GetParam().name, split.output, whole.output);
    EXPECT_EQ(split.output.sampleCounts, whole.output.sampleCounts);
}

// The Cornell box splits texel arrays (triangles, normals, materials); the textured room also
// its texture coordinates, a storage array; the last two the arrays that the shared texture and
// environment code reads (shared/texture_sampling.h, shared/environment.h).
INSTANTIATE_TEST_SUITE_P(
    Scenes, SplitArrays,
    ::testing::Values(
        SplitCase{"CornellBox", cornellBox, {"triangles"}},
        SplitCase{"TexturedRoom", texturedRoom, {"triangleUvs"}},
        SplitCase{"LargeTexture", largeTexture, {"textureTexels"}},
        SplitCase{"EnvironmentMap", environmentMap, {"environmentTexels", "environmentCdf"}}),
    [](const ::testing::TestParamInfo<SplitCase>& scene) { return scene.param.name; });

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
} // namespace vkpt::test::split_arrays_test
