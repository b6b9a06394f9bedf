// frame_reuse_test.cpp — what an animation's frames keep from one to the next (docs/scene-model.md,
// "Frames"): the loader keeps what moves apart from the still geometry, the BVH cache hands back
// the trees of geometry that did not move (and the prepared arrays then equal a preparation from
// scratch byte for byte), and the origin and the default framing do not follow the motion.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>
#include <span>
#include <vector>

#include "../support/gltf_writer.h"
#include "../support/scratch_directory.h"
#include "prepare/bvh_cache.h"
#include "prepare/prepared_scene.h"
#include "scene/camera.h"
#include "scene/gltf_loader.h"

namespace vkpt {
namespace {

// A rippled floor of 72 triangles and a box of 12 that an animation turns and lifts over 4 s
// (scenes/generate_static_set.py).
const std::string kMovingBox = VKPT_SCENES_DIR "/test/moving-box.gltf";
// A quad skinned by two joints; "lift" moves the root joint (scenes/generate_loader_scenes.py).
const std::string kSkin = VKPT_SCENES_DIR "/loader/skin.gltf";

LoadOptions frameOptions(double time) {
    LoadOptions options;
    options.warnUnsupportedExtensions = false;
    options.time = time;
    options.keepMovingApart = true;
    return options;
}

template <class T> bool sameBytes(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

std::vector<Aabb> boxes(std::initializer_list<float> xs) {
    std::vector<Aabb> result;
    for (float x : xs) {
        Aabb box;
        box.extend(glm::vec3(x, 0.0f, 0.0f));
        box.extend(glm::vec3(x + 1.0f, 1.0f, 1.0f));
        result.push_back(box);
    }
    return result;
}

TEST(FrameBvhCache, TakesTheTreeAgainForTheSameBoxesAndBuildsForOthers) {
    BvhCache cache;
    const std::vector<Aabb> still = boxes({0, 2, 4, 6, 8});
    const FlattenedBvh first = buildFlattenedBvh(still, {}, &cache);
    EXPECT_EQ(cache.stats().built, 1u);
    cache.endFrame();
    const FlattenedBvh again = buildFlattenedBvh(still, {}, &cache);
    EXPECT_EQ(cache.stats().reused, 1u);
    EXPECT_EQ(cache.stats().built, 0u);
    EXPECT_EQ(cache.stats().reusedPrimitives, still.size());
    EXPECT_TRUE(sameBytes(again.nodes, first.nodes));
    EXPECT_EQ(again.tree.primitiveOrder, first.tree.primitiveOrder);
    // The same boxes under other build options are another tree; one box moved by one float step
    // is another geometry.
    BvhBuildOptions oneLeaf;
    oneLeaf.maxLeafSize = 1;
    buildFlattenedBvh(still, oneLeaf, &cache);
    std::vector<Aabb> moved = still;
    moved[3].max.x = std::nextafter(moved[3].max.x, 100.0f);
    buildFlattenedBvh(moved, {}, &cache);
    EXPECT_EQ(cache.stats().built, 2u);
    EXPECT_EQ(cache.stats().reused, 1u);
}

TEST(FrameBvhCache, DropsTreesAFrameDidNotUse) {
    BvhCache cache;
    buildFlattenedBvh(boxes({0, 2}), {}, &cache);
    cache.endFrame();
    buildFlattenedBvh(boxes({5, 7}), {}, &cache); // the frame after: the first tree is unused
    cache.endFrame();
    buildFlattenedBvh(boxes({0, 2}), {}, &cache);
    EXPECT_EQ(cache.stats().built, 1u);
    EXPECT_EQ(cache.stats().reused, 0u);
}

TEST(FrameLayout, AnAnimatedNodesMeshIsAnInstanceAndTheFloorStaysStill) {
    const GltfSceneSource source(kMovingBox);
    const Scene start = source.pose(frameOptions(0.0));
    const Scene later = source.pose(frameOptions(1.0));
    for (const Scene* scene : {&start, &later}) {
        EXPECT_EQ(scene->triangleCount(), 72u); // the floor, flattened
        ASSERT_EQ(scene->meshes.size(), 1u);
        EXPECT_EQ(scene->meshes[0].triangleCount(), 12u);
        ASSERT_EQ(scene->instances.size(), 1u);
    }
    EXPECT_TRUE(sameBytes(start.positions, later.positions));
    EXPECT_TRUE(sameBytes(start.meshes[0].positions, later.meshes[0].positions));
    EXPECT_NE(start.instances[0].objectToWorld, later.instances[0].objectToWorld);
    // Without keeping apart, the box is flattened with the floor, as before.
    LoadOptions flattened = frameOptions(1.0);
    flattened.keepMovingApart = false;
    const Scene whole = source.pose(flattened);
    EXPECT_EQ(whole.triangleCount(), 84u);
    EXPECT_TRUE(whole.instances.empty());
}

TEST(FrameLayout, ASkinnedMeshIsAPosedMeshOfItsOwnPlacedUnmoved) {
    const GltfSceneSource source(kSkin);
    const Scene scene = source.pose(frameOptions(0.5));
    EXPECT_EQ(scene.triangleCount(), 0u);
    ASSERT_EQ(scene.meshes.size(), 1u);
    ASSERT_EQ(scene.instances.size(), 1u);
    EXPECT_EQ(scene.instances[0].objectToWorld, glm::dmat4(1.0));
    LoadOptions flattened = frameOptions(0.5);
    flattened.keepMovingApart = false;
    const Scene whole = source.pose(flattened);
    // The same posed triangles, whichever way they are kept.
    EXPECT_TRUE(sameBytes(scene.meshes[0].positions, whole.positions));
}

// Frames prepared through the cache equal frames prepared from scratch, array for array: the
// device then renders exactly the image a fresh preparation gives at the same seed.
TEST(FrameBvhCache, CachedFramesPrepareTheArraysOfFramesFromScratch) {
    const GltfSceneSource source(kMovingBox);
    BvhCache cache;
    for (const double time : {0.0, 0.5, 1.0, 2.5}) {
        SCOPED_TRACE("t = " + std::to_string(time));
        const Scene scene = source.pose(frameOptions(time));
        PrepareOptions cached;
        cached.bvhCache = &cache;
        const PreparedScene kept = prepareScene(scene, cached);
        const PreparedScene fresh =
            prepareScene(GltfSceneSource(kMovingBox).pose(frameOptions(time)));
        if (time > 0.0) {
            EXPECT_EQ(cache.stats().reused, 2u); // the floor and the box's own geometry
            EXPECT_EQ(cache.stats().built, 0u);
        }
        cache.endFrame();
        EXPECT_TRUE(sameBytes(kept.nodes, fresh.nodes));
        EXPECT_TRUE(sameBytes(kept.triangles, fresh.triangles));
        EXPECT_TRUE(sameBytes(kept.normals, fresh.normals));
        EXPECT_TRUE(sameBytes(kept.instances, fresh.instances));
        EXPECT_TRUE(sameBytes(kept.emitters, fresh.emitters));
    }
}

// The moving box far from the origin: the scene is recentred, at the same origin at every time
// (measured at rest), so that the floor's floats are the same in every frame.
TEST(FrameOrigin, IsTheSameAtEveryTime) {
    const std::string far = test::scratchPath("moving-box-far.gltf");
    test::writeTranslatedCopy(kMovingBox, far, {3.0e6, 0.0, -2.0e6});
    const GltfSceneSource source(far);
    testing::internal::CaptureStderr();
    const Scene start = source.pose(frameOptions(0.0));
    const Scene later = source.pose(frameOptions(1.0));
    testing::internal::GetCapturedStderr();
    EXPECT_NEAR(start.worldOrigin.x, 3.0e6, 20.0);
    EXPECT_EQ(start.worldOrigin, later.worldOrigin);
    EXPECT_TRUE(sameBytes(start.positions, later.positions));
}

// A skinned node's own transform does not place its mesh (glTF 2.0, section 3.7.3.1), so it does
// not decide the origin either: skin.gltf's quad with its node moved far away stays where its
// joints put it, near the origin, and nothing is recentred.
TEST(FrameOrigin, PlacesASkinnedMeshByItsJointsNotByItsNode) {
    tinygltf::Model model;
    tinygltf::TinyGLTF io;
    std::string error, warning;
    ASSERT_TRUE(io.LoadASCIIFromFile(&model, &error, &warning, kSkin)) << error;
    model.nodes.at(0).translation = {4.0e7, 0.0, 0.0}; // "skinned"
    // Without its normal texture: the writer would put the image beside the file, not inside it.
    model.materials.at(0).normalTexture = {};
    model.textures.clear();
    model.images.clear();
    const std::string path = test::scratchPath("skin-far-node.gltf");
    test::GltfWriter::writeModel(model, path);
    for (const std::optional<double> time : {std::optional<double>(), std::optional<double>(0.5)}) {
        LoadOptions options;
        options.time = time;
        const Scene scene = loadGltfScene(path, options);
        EXPECT_EQ(scene.worldOrigin, glm::dvec3(0.0));
    }
}

// Without a camera, a posed scene is framed by its bounds at rest: every frame is seen from one
// place, not from one that follows the box.
TEST(FrameFraming, TheDefaultCameraDoesNotFollowTheMotion) {
    tinygltf::Model model;
    tinygltf::TinyGLTF io;
    std::string error, warning;
    ASSERT_TRUE(io.LoadASCIIFromFile(&model, &error, &warning, kMovingBox)) << error;
    std::vector<int>& roots = model.scenes.at(0).nodes;
    roots.erase(std::remove_if(roots.begin(), roots.end(),
                               [&](int n) { return model.nodes.at(std::size_t(n)).camera >= 0; }),
                roots.end());
    const std::string path = test::scratchPath("moving-box-no-camera.gltf");
    test::GltfWriter::writeModel(model, path);
    testing::internal::CaptureStderr();
    const SceneCamera start = selectCamera(loadGltfScene(path, frameOptions(0.0)), std::nullopt);
    const SceneCamera later = selectCamera(loadGltfScene(path, frameOptions(1.0)), std::nullopt);
    testing::internal::GetCapturedStderr();
    EXPECT_EQ(start.position, later.position);
    EXPECT_EQ(start.forward, later.forward);
}

} // namespace
} // namespace vkpt
