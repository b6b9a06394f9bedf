// frame_reuse_test.cpp — what an animation's frames keep from one to the next (docs/scene-model.md,
// "Frames"): the loader keeps what moves apart from the still geometry and walks the still part
// once, the BVH and level caches hand back the trees and records of geometry that did not move
// (and the prepared arrays and the scene hash then equal a preparation from scratch byte for
// byte), and the origin and the default framing do not follow the motion, morphs included.
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
#include "prepare/level_cache.h"
#include "prepare/prepared_scene.h"
#include "prepare/scene_hash.h"
#include "scene/camera.h"
#include "scene/gltf_animation.h"
#include "scene/gltf_loader.h"
#include "scene/gltf_morph.h"

namespace vkpt::frame_reuse_test {
namespace {

// A rippled floor of 72 triangles and a box of 12 that an animation turns and lifts over 4 s
// (scenes/generate_static_set.py).
const std::string kMovingBox = VKPT_SCENES_DIR "/test/moving-box.gltf";
// A quad skinned by two joints; "lift" moves the root joint (scenes/generate_loader_scenes.py).
const std::string kSkin = VKPT_SCENES_DIR "/loader/skin.gltf";
// A still floor and a quad whose morph weight an animation takes from 0 to 3 and back to 1,
// raising two corners from y = 0 to y = 3 (scenes/generate_morph_scene.py).
const std::string kMorphGrow = VKPT_SCENES_DIR "/test/morph-grow.gltf";
// A triangle with two morph targets placed by three nodes; "pulse" takes the first node's
// weights from (0, 0) to (1, 1) (scenes/generate_loader_scenes.py).
const std::string kMorph = VKPT_SCENES_DIR "/loader/morph.gltf";

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

void expectSameSoup(const TriangleSoup& a, const TriangleSoup& b) {
    EXPECT_TRUE(sameBytes(a.positions, b.positions));
    EXPECT_TRUE(sameBytes(a.normals, b.normals));
    EXPECT_TRUE(sameBytes(a.materialIndices, b.materialIndices));
    EXPECT_TRUE(sameBytes(a.texcoords, b.texcoords));
    EXPECT_TRUE(sameBytes(a.tangents, b.tangents));
}

// The same geometry, placements, cameras, lights and spheres, in the same order.
void expectSameScene(const Scene& a, const Scene& b) {
    expectSameSoup(a, b);
    ASSERT_EQ(a.meshes.size(), b.meshes.size());
    for (std::size_t m = 0; m < a.meshes.size(); ++m) {
        expectSameSoup(a.meshes[m], b.meshes[m]);
        EXPECT_EQ(a.meshes[m].origin, b.meshes[m].origin);
    }
    ASSERT_EQ(a.instances.size(), b.instances.size());
    for (std::size_t i = 0; i < a.instances.size(); ++i) {
        EXPECT_EQ(a.instances[i].mesh, b.instances[i].mesh);
        EXPECT_EQ(a.instances[i].objectToWorld, b.instances[i].objectToWorld);
        EXPECT_EQ(a.instances[i].material, b.instances[i].material);
    }
    ASSERT_EQ(a.cameras.size(), b.cameras.size());
    for (std::size_t c = 0; c < a.cameras.size(); ++c)
        EXPECT_EQ(a.cameras[c].position, b.cameras[c].position);
    EXPECT_EQ(a.lights.size(), b.lights.size());
    EXPECT_TRUE(sameBytes(a.spheres, b.spheres));
    EXPECT_EQ(a.materials.size(), b.materials.size());
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

// A source posed frame after frame walks its still part once (the first pose) and gives every
// frame the scene a fresh source gives at that time: a moving instance (the box), a skin with a
// camera riding on its moving joint, and a morph.
TEST(FrameLayout, FramesOfOneSourceEqualFramesOfFreshSources) {
    for (const std::string& path : {kMovingBox, kSkin, kMorphGrow}) {
        SCOPED_TRACE(path);
        const GltfSceneSource source(path);
        for (const double time : {0.0, 0.5, 1.0, 0.25}) {
            SCOPED_TRACE("t = " + std::to_string(time));
            testing::internal::CaptureStderr();
            const Scene kept = source.pose(frameOptions(time));
            const Scene fresh = GltfSceneSource(path).pose(frameOptions(time));
            testing::internal::GetCapturedStderr();
            expectSameScene(kept, fresh);
        }
    }
}

// Frames prepared through the level cache (the floor's and the box's records and hashes taken
// from the frame before) equal frames prepared from scratch, array for array, and so does their
// scene hash; the hash changes as the box moves.
TEST(FrameLevelCache, KeptLevelsGiveTheArraysAndHashOfFramesFromScratch) {
    const GltfSceneSource source(kMovingBox);
    LevelCache levels;
    BvhCache bvhs;
    const gpu::Camera camera{};
    std::string firstHash;
    for (const double time : {0.0, 0.5, 1.0, 2.5}) {
        SCOPED_TRACE("t = " + std::to_string(time));
        PrepareOptions cached;
        cached.bvhCache = &bvhs;
        cached.levelCache = &levels;
        const PreparedScene kept = prepareScene(source.pose(frameOptions(time)), cached);
        const PreparedScene fresh =
            prepareScene(GltfSceneSource(kMovingBox).pose(frameOptions(time)));
        if (time > 0.0) {
            EXPECT_EQ(levels.stats().reused, 2u); // the floor and the box's own geometry
            EXPECT_EQ(levels.stats().prepared, 0u);
            EXPECT_EQ(bvhs.stats().built, 0u);
        }
        levels.endFrame();
        bvhs.endFrame();
        EXPECT_TRUE(sameBytes(kept.nodes, fresh.nodes));
        EXPECT_TRUE(sameBytes(kept.triangles, fresh.triangles));
        EXPECT_TRUE(sameBytes(kept.normals, fresh.normals));
        EXPECT_TRUE(sameBytes(kept.uvs, fresh.uvs));
        EXPECT_TRUE(sameBytes(kept.tangents, fresh.tangents));
        EXPECT_TRUE(sameBytes(kept.instances, fresh.instances));
        EXPECT_TRUE(sameBytes(kept.emitters, fresh.emitters));
        const std::string hash = sceneContentHash(kept, camera);
        EXPECT_EQ(hash, sceneContentHash(fresh, camera));
        if (firstHash.empty()) {
            firstHash = hash;
        } else {
            EXPECT_NE(hash, firstHash) << "the box moved";
        }
    }
}

// The level cache tells geometry apart by all of it, not by its boxes alone: a normal turned
// under the same positions is prepared anew.
TEST(FrameLevelCache, PreparesAgainWhenOnlyANormalChanged) {
    Scene scene = GltfSceneSource(kMovingBox).pose(frameOptions(0.0));
    LevelCache levels;
    PrepareOptions cached;
    cached.levelCache = &levels;
    prepareScene(scene, cached);
    levels.endFrame();
    scene.normals[5] = glm::normalize(scene.normals[5] + glm::vec3(0.25f, 0.0f, 0.0f));
    const PreparedScene kept = prepareScene(scene, cached);
    EXPECT_EQ(levels.stats().reused, 1u); // the box
    EXPECT_EQ(levels.stats().prepared, 1u);
    EXPECT_TRUE(sameBytes(kept.normals, prepareScene(scene).normals));
}

// The scene hash is the same for a general layout (which fills arrays the scene does not use),
// and sees one still vertex move by a float step.
TEST(FrameSceneHash, IgnoresTheGeneralLayoutAndSeesAStillVertexMove) {
    Scene scene = GltfSceneSource(kMovingBox).pose(frameOptions(0.5));
    const gpu::Camera camera{};
    const std::string hash = sceneContentHash(prepareScene(scene), camera);
    PrepareOptions general;
    general.general = true;
    EXPECT_EQ(sceneContentHash(prepareScene(scene, general), camera), hash);
    scene.positions[7].y = std::nextafter(scene.positions[7].y, 10.0f);
    EXPECT_NE(sceneContentHash(prepareScene(scene), camera), hash);
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

// morph-grow.gltf's quad rests flat at y = 0, and its weight's animation raises two corners to
// y = 3 at 0.5 s: the extent measured at rest holds every shape the animation gives, so the
// default framing (and the origin) hold every frame's vertices.
TEST(FrameFraming, TheRestExtentHoldsEveryShapeOfAMorphAnimation) {
    const GltfSceneSource source(kMorphGrow);
    for (const double time : {0.0, 0.25, 0.5, 0.75, 1.0}) {
        SCOPED_TRACE("t = " + std::to_string(time));
        const Scene scene = source.pose(frameOptions(time));
        ASSERT_TRUE(scene.framingBounds.has_value());
        EXPECT_GE(scene.framingBounds->max.y, 3.0f);
        const Bounds posed = computeBounds(scene);
        for (int axis = 0; axis < 3; ++axis) {
            EXPECT_LE(scene.framingBounds->min[axis], posed.min[axis]);
            EXPECT_GE(scene.framingBounds->max[axis], posed.max[axis]);
        }
    }
}

// A weight ranges over its value at rest and every value its animations give: morph.gltf's
// first node rests at its mesh's weights (0.5, 0.25) and "pulse" takes them from (0, 0) to (1, 1);
// its second node rests at (1, 0), unanimated.
TEST(FrameMorphWeights, RangeOverTheRestWeightsAndTheAnimatedValues) {
    tinygltf::Model model;
    tinygltf::TinyGLTF io;
    std::string error, warning;
    ASSERT_TRUE(io.LoadASCIIFromFile(&model, &error, &warning, kMorph)) << error;
    const std::vector<gltf::Animation> animations = gltf::readAnimations(model);
    const std::vector<gltf::WeightRange> pulsed = gltf::morphWeightRanges(model, 0, animations);
    ASSERT_EQ(pulsed.size(), 2u);
    for (const gltf::WeightRange& range : pulsed) {
        EXPECT_EQ(range.low, 0.0);
        EXPECT_EQ(range.high, 1.0);
    }
    const std::vector<gltf::WeightRange> still = gltf::morphWeightRanges(model, 1, animations);
    ASSERT_EQ(still.size(), 2u);
    EXPECT_EQ(still[0].low, 1.0);
    EXPECT_EQ(still[0].high, 1.0);
    EXPECT_EQ(still[1].low, 0.0);
    EXPECT_EQ(still[1].high, 0.0);
}

// A CUBICSPLINE curve overshoots its keyframes: from 0 to 1 with an out-tangent of 6 it passes
// 1.25 at the middle. Its range reaches the Bézier control point 0 + 1·6/3 = 2, which holds the
// whole curve.
TEST(FrameMorphWeights, HoldACubicSplinesOvershoot) {
    tinygltf::Model model;
    tinygltf::TinyGLTF io;
    std::string error, warning;
    ASSERT_TRUE(io.LoadASCIIFromFile(&model, &error, &warning, kMorph)) << error;
    gltf::AnimationChannel channel;
    channel.node = 2; // rests at (0, 0)
    channel.path = gltf::AnimatedPath::Weights;
    channel.track.times = {0.0, 1.0};
    channel.track.width = 2;
    channel.track.interpolation = gltf::Interpolation::CubicSpline;
    // Per keyframe: in-tangents, values, out-tangents.
    channel.track.values = {0, 0, 0, 0, 6, 0, 0, 0, 1, 1, 0, 0};
    gltf::Animation animation;
    animation.channels = {channel};
    const std::vector<gltf::WeightRange> ranges = gltf::morphWeightRanges(model, 2, {animation});
    ASSERT_EQ(ranges.size(), 2u);
    EXPECT_EQ(ranges[0].high, 2.0);
    EXPECT_EQ(ranges[1].high, 1.0);
    for (double time = 0.0; time <= 1.0; time += 0.125) {
        const std::vector<double> weights = gltf::sampleTrack(channel.track, time, false);
        EXPECT_LE(weights[0], ranges[0].high);
        EXPECT_GE(weights[0], ranges[0].low);
    }
    EXPECT_GT(gltf::sampleTrack(channel.track, 0.5, false)[0], 1.0);
}

} // namespace
} // namespace vkpt::frame_reuse_test
