// animation_frames_render_test.cpp — an animation's frames on the device (docs/scene-model.md,
// "Frames"). Rendered one after another through what they keep (the still part walked once by the
// source, the still geometry's bottom levels and BVHs, the device arrays of the frame before with
// only changed blocks uploaded), frames equal the same frames rendered from scratch, bit for bit
// at one seed: the BVHs are the same trees and the device arrays the same bytes. And a posed
// skinned scene agrees with vkpt-ref.
#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <initializer_list>

#include "prepare/bvh_cache.h"
#include "prepare/level_cache.h"
#include "render/kept_scene.h"
#include "wavefront_test_support.h"

namespace vkpt::test::animation_frames_render_test {
namespace {

// An animation's frame as vkpt renders it: what moves kept apart, under a constant white sky (the
// scenes bring no light; a constant needs no --env file).
Scene poseFrame(const GltfSceneSource& source, double time) {
    LoadOptions options;
    options.warnUnsupportedExtensions = false;
    options.time = time;
    options.keepMovingApart = true;
    Scene scene = source.pose(options);
    scene.environment.radiance = glm::vec3(1.0f);
    return scene;
}

gpu::Camera cameraOf(const Scene& scene, const RenderSettings& settings) {
    return makeGpuCamera(selectCamera(scene, settings.cameraIndex), settings.width,
                         settings.height);
}

bool sameImage(const Image& a, const Image& b) {
    return a.pixels.size() == b.pixels.size() &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(glm::vec3)) == 0;
}

class AnimationFrames : public GpuTest {
protected:
    // Renders moving-box.gltf at `times` in turn through a level cache, a BVH cache and a kept
    // device scene, and each frame again from scratch; the images must be equal bit for bit, and
    // differ from the first frame's (the box moved). `split`: some array must be in several
    // chunks.
    void expectKeptFramesEqualFramesFromScratch(std::initializer_list<double> times,
                                                bool split = false) {
        const std::string path = scenePath("test/moving-box.gltf");
        RenderSettings settings = testSettings(16, 2);
        settings.seed = 5;
        const GltfSceneSource source(path);
        BvhCache bvhs;
        LevelCache levels;
        KeptDeviceScene kept;
        Image first;
        for (const double time : times) {
            SCOPED_TRACE("t = " + std::to_string(time));
            const Scene scene = poseFrame(source, time);
            PrepareOptions options;
            options.bvhCache = &bvhs;
            options.levelCache = &levels;
            PreparedScene prepared = prepareScene(scene, options);
            bvhs.endFrame();
            levels.endFrame();
            const WavefrontResult frame = renderWavefrontKeeping(
                context(), prepared, cameraOf(scene, settings), settings, {}, kept);
            const bool chunked =
                std::any_of(frame.sceneBuffers.begin(), frame.sceneBuffers.end(),
                            [](const SceneBufferBytes& array) { return array.buffers > 1; });
            EXPECT_EQ(chunked, split);
            if (first.pixels.empty()) {
                first = frame.output.image;
            } else {
                // The floor's arrays stay; the instance record and the top of the node array
                // change.
                EXPECT_GT(kept.stats().keptBytes, 0u);
                EXPECT_GT(kept.stats().uploadedBytes, 0u);
                EXPECT_FALSE(sameImage(frame.output.image, first)) << "the box did not move";
            }
            const Scene fresh = poseFrame(GltfSceneSource(path), time);
            const WavefrontResult scratch = renderWavefront(context(), prepareScene(fresh),
                                                            cameraOf(fresh, settings), settings);
            EXPECT_TRUE(sameImage(frame.output.image, scratch.output.image))
                << writeComparisonImages("kept_frame", frame.output, scratch.output);
        }
    }
};

// scenes/test/moving-box.gltf: a still floor and a box an animation turns and lifts. 16 × 16 at 2
// spp: every pixel sees the floor or the box, and a stale block of any array (nodes, instances)
// changes some pixel's first hit.
TEST_F(AnimationFrames, KeptFramesEqualFramesRenderedFromScratch) {
    expectKeptFramesEqualFramesFromScratch({0.0, 0.5, 1.0});
}

// VKPT_TEST_BINDING_BYTES set for its lifetime (scene_arrays.h): splittable arrays are cut into
// chunks of at most that many bytes.
struct SmallBindings {
    explicit SmallBindings(const char* bytes) { setenv("VKPT_TEST_BINDING_BYTES", bytes, 1); }
    ~SmallBindings() { unsetenv("VKPT_TEST_BINDING_BYTES"); }
    SmallBindings(const SmallBindings&) = delete;
    SmallBindings& operator=(const SmallBindings&) = delete;
};

// The same with the splittable arrays cut into 2 KiB chunks (the triangles' 4 KiB into 2 or 3):
// a changed block is written across the chunks that hold it.
TEST_F(AnimationFrames, KeptFramesOfSplitArraysEqualFramesRenderedFromScratch) {
    const SmallBindings small("2048");
    expectKeptFramesEqualFramesFromScratch({0.0, 1.0}, true);
}

// CesiumMan walking, posed at 0.5 s: skinned by its 19 joints, kept as a posed mesh of its own
// and placed by an instance. 16 × 16 at 4 spp is enough for the same-seed comparison to see every
// pixel's path (its bound: docs/wavefront.md).
TEST_F(AnimationFrames, APosedSkinnedSceneMatchesTheReference) {
    // scenePath, not sharedScenePath: GCC 12 warns falsely (-Warray-bounds, its bug 105651)
    // about the latter's temporaries once inlined here.
    const std::string path = scenePath("../../shared/scenes/CesiumMan/CesiumMan.glb");
    if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " is not there";
    LoadedTestScene loaded;
    loaded.scene = poseFrame(GltfSceneSource(path), 0.5);
    ASSERT_FALSE(loaded.scene.instances.empty());
    loaded.prepared = prepareScene(loaded.scene);
    RenderSettings settings = testSettings(16, 4);
    settings.seed = 3;
    const RenderOutput gpu = renderOnDevice(context(), loaded, settings);
    const RenderOutput cpu = renderTestScene(loaded, settings);
    const SameSeedAgreement agreement = compareSameSeed(gpu, cpu);
    std::printf("cesium_man_posed: %s\n", agreement.summary().c_str());
    // As the other same-seed comparisons: at most 1 % of the paths diverge on a last-bit decision.
    EXPECT_GE(agreement.fraction(), 0.99) << writeComparisonImages("cesium_man_posed", gpu, cpu);
}

} // namespace
} // namespace vkpt::test::animation_frames_render_test
