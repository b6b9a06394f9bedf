// gltf_animation_test.cpp — skins, morph targets and animations: keyframe sampling by each
// interpolation, the hand-made scenes/loader/skin.gltf and morph.gltf posed at rest and at
// chosen times (every vertex computed by hand in the comments), and the Khronos sample assets
// in shared/scenes against values read off their keyframes and, for CesiumMan's skin, against a
// pose the test computes itself from the file.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include "common/errors.h"
#include "scene/gltf_animation.h"
#include "scene/gltf_document.h"
#include "scene/gltf_loader.h"

namespace vkpt::gltf_animation_test {
namespace {

const std::string kSkinScene = VKPT_SCENES_DIR "/loader/skin.gltf";
const std::string kMorphScene = VKPT_SCENES_DIR "/loader/morph.gltf";
const std::string kSharedScenesDir = VKPT_SCENES_DIR "/../../shared/scenes/";

constexpr float kTolerance = 1e-5f;
const double kSqrtHalf = std::sqrt(0.5);

void expectNear(const glm::vec3& actual, const glm::vec3& expected, float tolerance = kTolerance) {
    EXPECT_NEAR(actual.x, expected.x, tolerance) << "component x";
    EXPECT_NEAR(actual.y, expected.y, tolerance) << "component y";
    EXPECT_NEAR(actual.z, expected.z, tolerance) << "component z";
}

void expectTriangle(const Scene& scene, std::size_t t, const std::vector<glm::vec3>& expected) {
    ASSERT_LT(t, scene.triangleCount());
    for (std::size_t i = 0; i < 3; ++i) {
        SCOPED_TRACE("triangle " + std::to_string(t) + ", corner " + std::to_string(i));
        expectNear(scene.positions[3 * t + i], expected[i]);
    }
}

Scene loadAt(const std::string& path, std::optional<double> time,
             const std::string& animation = "") {
    LoadOptions options;
    options.time = time;
    options.animation = animation;
    return loadGltfScene(path, options);
}

// --- Sampling one track ----------------------------------------------------------------------

gltf::KeyframeTrack scalarTrack(gltf::Interpolation interpolation, std::vector<double> values) {
    gltf::KeyframeTrack track;
    track.times = {1.0, 2.0, 4.0};
    track.values = std::move(values);
    track.width = 1;
    track.interpolation = interpolation;
    return track;
}

double sampleScalar(const gltf::KeyframeTrack& track, double time) {
    return gltf::sampleTrack(track, time, false).at(0);
}

TEST(GltfKeyframeSampling, StepHoldsEachKeyframeUntilTheNext) {
    const auto track = scalarTrack(gltf::Interpolation::Step, {10.0, 20.0, 40.0});
    EXPECT_EQ(sampleScalar(track, 1.0), 10.0);
    EXPECT_EQ(sampleScalar(track, 1.999), 10.0);
    EXPECT_EQ(sampleScalar(track, 2.0), 20.0);
    EXPECT_EQ(sampleScalar(track, 3.9), 20.0);
}

TEST(GltfKeyframeSampling, LinearInterpolatesWithinEachInterval) {
    const auto track = scalarTrack(gltf::Interpolation::Linear, {10.0, 20.0, 40.0});
    EXPECT_DOUBLE_EQ(sampleScalar(track, 1.5), 15.0);
    EXPECT_DOUBLE_EQ(sampleScalar(track, 3.0), 30.0); // halfway through the 2 s interval
}

TEST(GltfKeyframeSampling, ClampsBeforeTheFirstAndAfterTheLastKeyframe) {
    for (auto kind : {gltf::Interpolation::Step, gltf::Interpolation::Linear}) {
        const auto track = scalarTrack(kind, {10.0, 20.0, 40.0});
        EXPECT_EQ(sampleScalar(track, -5.0), 10.0);
        EXPECT_EQ(sampleScalar(track, 100.0), 40.0);
    }
}

TEST(GltfKeyframeSampling, CubicSplineFollowsTheHermiteBasisOfAppendixC) {
    // Keyframes (in-tangent, value, out-tangent): (0, 10, 3), (5, 20, 0), (0, 40, 0). Between
    // t = 1 and 2 (interval 1) at u = 0.5: h00 = 0.5, h10 = 0.125, h01 = 0.5, h11 = -0.125, so
    // 0.5·10 + 0.125·1·3 + 0.5·20 − 0.125·1·5 = 14.75. At u = 0.25 of the second interval
    // (t = 2.5, interval 2, both tangents 0): h00 = 0.84375, h01 = 0.15625: 20·0.84375 +
    // 40·0.15625 = 23.125.
    const auto track = scalarTrack(gltf::Interpolation::CubicSpline,
                                   {0.0, 10.0, 3.0, 5.0, 20.0, 0.0, 0.0, 40.0, 0.0});
    EXPECT_DOUBLE_EQ(sampleScalar(track, 1.5), 14.75);
    EXPECT_DOUBLE_EQ(sampleScalar(track, 2.5), 23.125);
    EXPECT_DOUBLE_EQ(sampleScalar(track, 2.0), 20.0); // a keyframe's own value
    EXPECT_DOUBLE_EQ(sampleScalar(track, 0.0), 10.0);
    EXPECT_DOUBLE_EQ(sampleScalar(track, 9.0), 40.0);
}

TEST(GltfKeyframeSampling, SlerpTakesTheShorterArcAtConstantSpeed) {
    // From the identity to 90° about Z, stored as its negative (−q is the same rotation): a
    // quarter of the way is 22.5° about Z, along the short arc.
    gltf::KeyframeTrack track;
    track.times = {0.0, 1.0};
    const double s = std::sin(M_PI / 4), c = std::cos(M_PI / 4);
    track.values = {0.0, 0.0, 0.0, 1.0, 0.0, 0.0, -s, -c};
    track.width = 4;
    const std::vector<double> q = gltf::sampleTrack(track, 0.25, true);
    const double sign = q[3] < 0.0 ? -1.0 : 1.0;
    EXPECT_NEAR(sign * q[0], 0.0, 1e-12);
    EXPECT_NEAR(sign * q[1], 0.0, 1e-12);
    EXPECT_NEAR(sign * q[2], std::sin(M_PI / 16), 1e-12);
    EXPECT_NEAR(sign * q[3], std::cos(M_PI / 16), 1e-12);
}

// --- skin.gltf: linear blend skinning by hand ------------------------------------------------
// Joint 0 (the root) is at z = 1, joint 1 at (0, 1, 1) turned by the angle a about Z; the
// inverse bind matrices are I and T(0, −1, 0). The quad's corners v0 (0, 0), v1 (1, 0) follow
// joint 0, v2 (0, 2) joint 1, v3 (1, 2) half each. Triangles (v0, v1, v3) and (v0, v3, v2).

TEST(GltfSkinLoading, RestPoseBendsTheTopAndIgnoresTheSkinnedNodesTransform) {
    testing::internal::CaptureStderr();
    const Scene scene = loadGltfScene(kSkinScene);
    const std::string notes = testing::internal::GetCapturedStderr();
    // a = 90°: v2 = (0, 1) + R90 (0, 1) = (−1, 1); v3 = ((1, 2) + (0, 1) + R90 (1, 1)) / 2 =
    // ((1, 2) + (−1, 2)) / 2 = (0, 2); all at z = 1, and not moved by the node's x + 5.
    ASSERT_EQ(scene.triangleCount(), 2u);
    expectTriangle(scene, 0, {{0, 0, 1}, {1, 0, 1}, {0, 2, 1}});
    expectTriangle(scene, 1, {{0, 0, 1}, {0, 2, 1}, {-1, 1, 1}});
    for (const glm::vec3& normal : scene.normals)
        expectNear(normal, {0, 0, 1}); // turning about Z keeps the quad's normal
    // Tangents (1, 0, 0) turn with their joints: v2's by R90 to (0, 1, 0); v3's by the blend
    // (I + R90) / 2 to (1, 1, 0) / 2, unit (√½, √½, 0). Corners: v0 v1 v3, v0 v3 v2.
    const auto h = static_cast<float>(kSqrtHalf);
    ASSERT_EQ(scene.tangents.size(), 6u);
    const glm::vec3 expectedTangents[6] = {{1, 0, 0}, {1, 0, 0}, {h, h, 0},
                                           {1, 0, 0}, {h, h, 0}, {0, 1, 0}};
    for (std::size_t i = 0; i < 6; ++i) {
        SCOPED_TRACE("corner " + std::to_string(i));
        expectNear(glm::vec3(scene.tangents[i]), expectedTangents[i]);
        EXPECT_EQ(scene.tangents[i].w, 1.0f);
    }
    // v1's single weight of 0.5 counts as 1, and says so.
    EXPECT_EQ(scene.repairs.renormalisedSkinWeights, 1u);
    EXPECT_NE(notes.find("1 skinned vertex has weights that do not sum to one; they are "
                         "renormalised"),
              std::string::npos)
        << notes;
    ASSERT_EQ(scene.animations.size(), 2u);
    EXPECT_EQ(scene.animations[0].name, "bend");
    EXPECT_EQ(scene.animations[1].end, 1.0);
}

TEST(GltfSkinLoading, TimeZeroStraightensTheQuad) {
    // a = 0 ("bend" starts at the identity) and z = 1 ("lift" holds its first key).
    const Scene scene = loadAt(kSkinScene, 0.0);
    ASSERT_EQ(scene.triangleCount(), 2u);
    expectTriangle(scene, 0, {{0, 0, 1}, {1, 0, 1}, {1, 2, 1}});
    expectTriangle(scene, 1, {{0, 0, 1}, {1, 2, 1}, {0, 2, 1}});
}

TEST(GltfSkinLoading, OneAnimationAloneTurnsTheJointByItsSlerp) {
    // "bend" alone at t = 0.25: a = 45°, so v2 = (0, 1) + R45 (0, 1) = (−√½, 1 + √½) at z = 1,
    // and v3 = ((1, 2) + (0, 1) + R45 (1, 1)) / 2 = ((1, 2) + (0, 1 + √2)) / 2.
    const Scene scene = loadAt(kSkinScene, 0.25, "bend");
    const auto h = static_cast<float>(kSqrtHalf);
    const glm::vec3 v3(0.5f, 0.5f * (3.0f + std::sqrt(2.0f)), 1.0f);
    ASSERT_EQ(scene.triangleCount(), 2u);
    expectTriangle(scene, 1, {{0, 0, 1}, v3, {-h, 1 + h, 1}});
}

TEST(GltfSkinLoading, AfterTheEndEveryChannelHoldsItsLastKeyAndTheCameraFollows) {
    // t = 1.5: a = 180° and z = 3. v2 = (0, 1) + R180 (0, 1) = (0, 0): the second triangle
    // (v0, v3, v2) has no area and is skipped; v3 = ((1, 2) + (−1, 0)) / 2 = (0, 1).
    const Scene scene = loadAt(kSkinScene, 1.5);
    ASSERT_EQ(scene.triangleCount(), 1u);
    EXPECT_EQ(scene.repairs.zeroAreaTriangles, 1u);
    expectTriangle(scene, 0, {{0, 0, 3}, {1, 0, 3}, {0, 1, 3}});
    // The camera rides 5 above joint 0: at z = 6 at rest, z = 8 now.
    ASSERT_EQ(scene.cameras.size(), 1u);
    expectNear(scene.cameras[0].position, {0, 0, 8});
    expectNear(loadGltfScene(kSkinScene).cameras[0].position, {0, 0, 6});
}

TEST(GltfSkinLoading, RejectsAnAnimationThatDoesNotExist) {
    try {
        loadAt(kSkinScene, 0.0, "walk");
        ADD_FAILURE() << "loaded";
    } catch (const InputError& error) {
        EXPECT_EQ(std::string(error.what()),
                  kSkinScene + ": animation 'walk' does not exist (the file has 2 animations)");
    }
}

// --- morph.gltf: weighted displacements by hand ---------------------------------------------
// Target 0 lifts v0 by z = 1, adds (1, 0, −1) to its normal (0, 0, 1) and (0, 1, 0) to its
// tangent (1, 0, 0); target 1 (sparse) lifts v1 by z = 2. Nodes: the mesh's weights (0.5, 0.25);
// node weights (1, 0) at x = 2; (0, 0) at x = 4.

TEST(GltfMorphLoading, MeshWeightsApplyInAStillAndNodeWeightsOverrideThem) {
    const Scene scene = loadGltfScene(kMorphScene);
    ASSERT_EQ(scene.triangleCount(), 3u);
    expectTriangle(scene, 0, {{0, 0, 0.5f}, {1, 0, 0.5f}, {0, 1, 0}});
    expectTriangle(scene, 1, {{2, 0, 1}, {3, 0, 0}, {2, 1, 0}});
    expectTriangle(scene, 2, {{4, 0, 0}, {5, 0, 0}, {4, 1, 0}});
    // v0's normal: (0, 0, 1) + 0.5 (1, 0, −1) = (0.5, 0, 0.5), unit (√½, 0, √½); with weight 1
    // (1, 0, 0).
    const auto h = static_cast<float>(kSqrtHalf);
    expectNear(scene.normals[0], {h, 0, h});
    expectNear(scene.normals[3], {1, 0, 0});
    expectNear(scene.normals[6], {0, 0, 1});
    // v0's tangent (1, 0, 0) plus w0 (0, 1, 0): (1, 0.5, 0) / √1.25, then (1, 1, 0) / √2, then as
    // stored; the bitangent sign −1 kept.
    ASSERT_EQ(scene.tangents.size(), 9u);
    const float a = 1.0f / std::sqrt(1.25f);
    expectNear(glm::vec3(scene.tangents[0]), {a, 0.5f * a, 0});
    expectNear(glm::vec3(scene.tangents[3]), {h, h, 0});
    expectNear(glm::vec3(scene.tangents[6]), {1, 0, 0});
    EXPECT_EQ(scene.tangents[0].w, -1.0f);
}

TEST(GltfMorphLoading, AWeightsChannelReplacesTheStoredWeights) {
    // "pulse" at t = 0.5: weights (0.5, 0.5) on the first node: v1 rises by 0.5 · 2.
    const Scene scene = loadAt(kMorphScene, 0.5);
    expectTriangle(scene, 0, {{0, 0, 0.5f}, {1, 0, 1}, {0, 1, 0}});
    expectTriangle(scene, 1, {{2, 0, 1}, {3, 0, 0}, {2, 1, 0}}); // not animated
}

// --- One file read once, posed many times ---------------------------------------------------

TEST(GltfSceneSourcePoses, EachPoseEqualsALoadAtItsTime) {
    // As an animation's frames use it: the same triangles and cameras as separate loads, in
    // either order (a pose leaves the source as it was).
    const GltfSceneSource source(kSkinScene);
    for (const double time : {1.5, 0.0, 0.25}) {
        SCOPED_TRACE("time " + std::to_string(time));
        LoadOptions options;
        options.time = time;
        const Scene posed = source.pose(options);
        const Scene loaded = loadAt(kSkinScene, time);
        EXPECT_EQ(posed.positions, loaded.positions);
        EXPECT_EQ(posed.normals, loaded.normals);
        ASSERT_EQ(posed.cameras.size(), 1u);
        EXPECT_EQ(posed.cameras[0].position, loaded.cameras[0].position);
        EXPECT_EQ(posed.materials.size(), loaded.materials.size());
    }
}

// --- The Khronos sample assets -----------------------------------------------------------------

bool sharedScenesPresent() {
    return std::filesystem::exists(kSharedScenesDir + "InterpolationTest");
}

// The pose of `file` at `time` under the animation named `name`.
gltf::ScenePose poseOf(const std::string& file, const std::string& name, double time) {
    const tinygltf::Model model = gltf::parseGltfFile(kSharedScenesDir + file);
    const std::vector<gltf::Animation> animations = gltf::readAnimations(model);
    return gltf::poseAt(model, animations, gltf::selectAnimations(animations, name), time);
}

glm::dmat4 localOf(const gltf::ScenePose& pose, int node) {
    const auto& local = pose.locals.at(static_cast<std::size_t>(node));
    EXPECT_TRUE(local.has_value()) << "node " << node << " is not animated";
    return local.value_or(glm::dmat4(1.0));
}

glm::vec3 translationOf(const gltf::ScenePose& pose, int node) {
    return glm::vec3(localOf(pose, node)[3]);
}

double scaleXOf(const gltf::ScenePose& pose, int node) {
    return glm::length(glm::dvec3(localOf(pose, node)[0]));
}

// The angle about Z, in degrees, of a node that InterpolationTest turns about Z only.
double angleAboutZ(const gltf::ScenePose& pose, int node) {
    const glm::dmat4 m = localOf(pose, node);
    return glm::degrees(std::atan2(m[0][1], m[0][0]));
}

class GltfAnimatedSamples : public testing::Test {
protected:
    void SetUp() override {
        if (!sharedScenesPresent())
            GTEST_SKIP() << "shared scenes not found at " << kSharedScenesDir;
    }
};

// InterpolationTest.glb's keyframes (read off the file): scales 1, 0.5, 1, 0.5, 1 at
// 0.041667, 0.416667, 0.875, 1.25, 1.666667 s; rotations about Z of 0, −45, −90, −135, −180°
// at 0, 0.416667, 0.875, 1.25, 1.708333 s; translations y = 6.67, 10, 6, 10, 6 (cubic and
// linear at 0, 0.416667, 0.833333, ...); every cubic tangent is 0.
constexpr const char* kInterpolationTest = "InterpolationTest/InterpolationTest.glb";
constexpr double kKey1 = 0.4166666567325592, kKey2 = 0.875, kKey2Translation = 0.8333333134651184;

TEST_F(GltfAnimatedSamples, InterpolationTestScales) {
    EXPECT_NEAR(scaleXOf(poseOf(kInterpolationTest, "Step Scale", 0.5), 0), 0.5, 1e-6);
    EXPECT_NEAR(scaleXOf(poseOf(kInterpolationTest, "Step Scale", 0.0), 0), 1.0, 1e-6);
    const double middle = 0.5 * (kKey1 + kKey2);
    EXPECT_NEAR(scaleXOf(poseOf(kInterpolationTest, "Linear Scale", middle), 3), 0.75, 1e-6);
    // Zero tangents, u = 1/4: 0.5 · h00 + 1 · h01 = 0.5 · 0.84375 + 0.15625.
    const double quarter = kKey1 + 0.25 * (kKey2 - kKey1);
    EXPECT_NEAR(scaleXOf(poseOf(kInterpolationTest, "CubicSpline Scale", quarter), 4), 0.578125,
                1e-6);
}

TEST_F(GltfAnimatedSamples, InterpolationTestRotations) {
    EXPECT_NEAR(angleAboutZ(poseOf(kInterpolationTest, "Step Rotation", 1.0), 5), -90.0, 1e-4);
    const double middle = 0.5 * (kKey1 + kKey2);
    EXPECT_NEAR(angleAboutZ(poseOf(kInterpolationTest, "Linear Rotation", middle), 7), -67.5, 1e-4);
    EXPECT_NEAR(angleAboutZ(poseOf(kInterpolationTest, "CubicSpline Rotation", kKey2), 6), -90.0,
                1e-4);
}

TEST_F(GltfAnimatedSamples, InterpolationTestTranslations) {
    expectNear(translationOf(poseOf(kInterpolationTest, "Step Translation", 0.6), 8), {0, 10, 0});
    const double middle = 0.5 * (kKey1 + kKey2Translation);
    expectNear(translationOf(poseOf(kInterpolationTest, "Linear Translation", middle), 10),
               {-3.2975807f, 8, 0});
    expectNear(translationOf(poseOf(kInterpolationTest, "CubicSpline Translation", middle), 9),
               {3.3051798f, 8, 0});
    expectNear(translationOf(poseOf(kInterpolationTest, "Linear Translation", 50.0), 10),
               {-3.2975807f, 6, 0}); // clamped at the last key
}

TEST_F(GltfAnimatedSamples, BoxAnimatedNodeChannels) {
    // Node 0 rises linearly to y = 2.52 at 1.25 s; node 2 turns from the identity (stored as
    // w = −1) to 180° about X between 1.25 and 2.5 s: halfway, 90° about X takes +Y to +Z.
    const std::string file = "BoxAnimated/BoxAnimated.glb";
    expectNear(translationOf(poseOf(file, "", 0.625), 0), {0, 1.26f, 0});
    const glm::dmat4 halfway = localOf(poseOf(file, "", 1.875), 2);
    expectNear(glm::vec3(halfway * glm::dvec4(0, 1, 0, 0)), {0, 0, 1});
    const glm::dmat4 end = localOf(poseOf(file, "", 3.0), 2);
    expectNear(glm::vec3(end * glm::dvec4(0, 1, 0, 0)), {0, -1, 0});
}

TEST_F(GltfAnimatedSamples, AnimatedMorphCubeWeights) {
    // Keys every 1/30 s: weights (0.0050637, 0) at 2/30 s, (0.0112305, 0) at 3/30 s.
    const std::string file = "AnimatedMorphCube/AnimatedMorphCube.glb";
    const gltf::ScenePose pose = poseOf(file, "Square", 2.5 / 30.0);
    const auto& weights = pose.weights.at(0);
    ASSERT_TRUE(weights.has_value());
    ASSERT_EQ(weights->size(), 2u);
    EXPECT_NEAR((*weights)[0], 0.5 * (0.005063657183200121 + 0.011230469681322575), 1e-6);
    EXPECT_NEAR((*weights)[1], 0.0, 1e-9);
}

TEST_F(GltfAnimatedSamples, CesiumManWalksAwayFromItsRestPose) {
    const std::string path = kSharedScenesDir + "CesiumMan/CesiumMan.glb";
    const Scene rest = loadGltfScene(path);
    const Scene walking = loadAt(path, 0.5);
    ASSERT_EQ(rest.triangleCount(), walking.triangleCount());
    float largestMove = 0.0f;
    for (std::size_t i = 0; i < rest.positions.size(); ++i)
        largestMove = std::max(largestMove, glm::length(walking.positions[i] - rest.positions[i]));
    // A stride of the legs moves some vertex by centimetres at least (the figure is 1.5 high);
    // a broken skin would move it metres or not at all.
    EXPECT_GT(largestMove, 0.05f);
    EXPECT_LT(largestMove, 1.5f);
}

// --- CesiumMan posed by hand ------------------------------------------------------------------
// An independent pose of CesiumMan.glb read with tinygltf alone, from the formulas of the glTF
// 2.0 specification (sections 3.5.3, 3.7.3 and 3.11, Appendix C), to hold the loader's skinned
// vertices against.

// CesiumMan's texture is not needed for its geometry.
bool skipImage(tinygltf::Image*, const int, std::string*, std::string*, int, int,
               const unsigned char*, int, void*) {
    return true;
}

tinygltf::Model readGlbWithTinyGltf(const std::string& path) {
    tinygltf::TinyGLTF io;
    io.SetImageLoader(&skipImage, nullptr);
    tinygltf::Model model;
    std::string error, warning;
    EXPECT_TRUE(io.LoadBinaryFromFile(&model, &error, &warning, path)) << error;
    return model;
}

// Every component of accessor `index` as a double, element after element (floats and unsigned
// integers, not normalized: what CesiumMan's positions, weights, joints, keyframes and matrices
// use).
std::vector<double> accessorValues(const tinygltf::Model& model, int index) {
    const tinygltf::Accessor& accessor = model.accessors.at(static_cast<std::size_t>(index));
    EXPECT_FALSE(accessor.sparse.isSparse) << "accessor " << index;
    EXPECT_FALSE(accessor.normalized) << "accessor " << index;
    const tinygltf::BufferView& view =
        model.bufferViews.at(static_cast<std::size_t>(accessor.bufferView));
    const tinygltf::Buffer& buffer = model.buffers.at(static_cast<std::size_t>(view.buffer));
    const auto width = static_cast<std::size_t>(
        tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(accessor.type)));
    const auto componentSize = static_cast<std::size_t>(
        tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(accessor.componentType)));
    const auto stride = static_cast<std::size_t>(accessor.ByteStride(view));
    const unsigned char* first = buffer.data.data() + view.byteOffset + accessor.byteOffset;
    std::vector<double> values;
    for (std::size_t element = 0; element < accessor.count; ++element) {
        for (std::size_t c = 0; c < width; ++c) {
            const unsigned char* at = first + element * stride + c * componentSize;
            switch (accessor.componentType) {
            case TINYGLTF_COMPONENT_TYPE_FLOAT: {
                float value;
                std::memcpy(&value, at, sizeof value);
                values.push_back(value);
                break;
            }
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
                std::uint16_t value;
                std::memcpy(&value, at, sizeof value);
                values.push_back(value);
                break;
            }
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
                values.push_back(*at);
                break;
            default:
                ADD_FAILURE() << "accessor " << index << ": component type "
                              << accessor.componentType;
                return {};
            }
        }
    }
    return values;
}

glm::dquat quaternionAt(const std::vector<double>& values, std::size_t key) {
    return {values[4 * key + 3], values[4 * key], values[4 * key + 1], values[4 * key + 2]};
}

// Appendix C's spherical interpolation along the shorter arc (q and −q are the same rotation),
// written as sin((1 − u)θ)/sin θ · a + sin(uθ)/sin θ · b; linear then normalised where the two
// nearly coincide and sin θ vanishes.
glm::dquat slerpByHand(const glm::dquat& a, glm::dquat b, double u) {
    double cosine = a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z;
    if (cosine < 0.0) {
        b = -b;
        cosine = -cosine;
    }
    if (cosine > 0.9995) return glm::normalize((1.0 - u) * a + u * b);
    const double theta = std::acos(cosine);
    return (std::sin((1.0 - u) * theta) * a + std::sin(u * theta) * b) / std::sin(theta);
}

// A node's translation, rotation and scale (section 3.5.3: the defaults where absent).
struct NodeTrs {
    glm::dvec3 translation{0.0};
    glm::dquat rotation{1.0, 0.0, 0.0, 0.0};
    glm::dvec3 scale{1.0};
};

// Overwrites the property `path` of `trs` by a LINEAR sampler at `time` (section 3.11): clamped
// to the first and last keys, else between keys k and k + 1 at u = (t − t_k) / (t_k+1 − t_k),
// lerp for translations and scales, slerp for rotations.
void applyLinearSampler(const std::vector<double>& times, const std::vector<double>& values,
                        const std::string& path, double time, NodeTrs& trs) {
    std::size_t k = 0;
    double u = 0.0;
    if (time >= times.back()) {
        k = times.size() - 1;
    } else if (time > times.front()) {
        while (times[k + 1] <= time)
            ++k;
        u = (time - times[k]) / (times[k + 1] - times[k]);
    }
    const std::size_t next = std::min(k + 1, times.size() - 1);
    if (path == "rotation") {
        trs.rotation = slerpByHand(quaternionAt(values, k), quaternionAt(values, next), u);
        return;
    }
    const glm::dvec3 a(values[3 * k], values[3 * k + 1], values[3 * k + 2]);
    const glm::dvec3 b(values[3 * next], values[3 * next + 1], values[3 * next + 2]);
    (path == "translation" ? trs.translation : trs.scale) = (1.0 - u) * a + u * b;
}

// Every node's local matrix at `time` with all of the file's animations playing: a stored
// matrix as it is, else T · R · S of the (animated) properties.
std::vector<glm::dmat4> localsAt(const tinygltf::Model& model, double time) {
    std::vector<NodeTrs> trs(model.nodes.size());
    for (std::size_t n = 0; n < model.nodes.size(); ++n) {
        const tinygltf::Node& node = model.nodes[n];
        if (node.translation.size() == 3)
            trs[n].translation = glm::make_vec3(node.translation.data());
        if (node.rotation.size() == 4)
            trs[n].rotation =
                glm::dquat(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
        if (node.scale.size() == 3) trs[n].scale = glm::make_vec3(node.scale.data());
    }
    for (const tinygltf::Animation& animation : model.animations) {
        for (const tinygltf::AnimationChannel& channel : animation.channels) {
            const tinygltf::AnimationSampler& sampler =
                animation.samplers.at(static_cast<std::size_t>(channel.sampler));
            EXPECT_EQ(sampler.interpolation, "LINEAR") << "channel of node " << channel.target_node;
            applyLinearSampler(accessorValues(model, sampler.input),
                               accessorValues(model, sampler.output), channel.target_path, time,
                               trs.at(static_cast<std::size_t>(channel.target_node)));
        }
    }
    std::vector<glm::dmat4> locals(model.nodes.size());
    for (std::size_t n = 0; n < model.nodes.size(); ++n) {
        const tinygltf::Node& node = model.nodes[n];
        if (node.matrix.size() == 16) {
            locals[n] = glm::make_mat4(node.matrix.data()); // column-major, as glm
            continue;
        }
        locals[n] = glm::translate(glm::dmat4(1.0), trs[n].translation) *
                    glm::mat4_cast(trs[n].rotation) * glm::scale(glm::dmat4(1.0), trs[n].scale);
    }
    return locals;
}

// Each node's world matrix: its parents' locals from the root down, times its own.
std::vector<glm::dmat4> worldsOf(const tinygltf::Model& model,
                                 const std::vector<glm::dmat4>& locals) {
    std::vector<int> parent(model.nodes.size(), -1);
    for (std::size_t n = 0; n < model.nodes.size(); ++n)
        for (const int child : model.nodes[n].children)
            parent.at(static_cast<std::size_t>(child)) = static_cast<int>(n);
    std::vector<glm::dmat4> worlds(model.nodes.size());
    for (std::size_t n = 0; n < model.nodes.size(); ++n) {
        worlds[n] = locals[n];
        for (int p = parent[n]; p != -1; p = parent[static_cast<std::size_t>(p)])
            worlds[n] = locals[static_cast<std::size_t>(p)] * worlds[n];
    }
    return worlds;
}

TEST_F(GltfAnimatedSamples, CesiumManSkinMatchesAPoseComputedByHand) {
    const std::string path = kSharedScenesDir + "CesiumMan/CesiumMan.glb";
    if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " not found";
    constexpr double kTime = 0.5;
    const tinygltf::Model model = readGlbWithTinyGltf(path);
    ASSERT_EQ(model.skins.size(), 1u);
    ASSERT_EQ(model.meshes.size(), 1u);
    ASSERT_EQ(model.meshes[0].primitives.size(), 1u);
    const tinygltf::Skin& skin = model.skins[0];
    const tinygltf::Primitive& primitive = model.meshes[0].primitives[0];

    // Joint matrices (section 3.7.3): the joint's world matrix × its inverse bind matrix. The
    // skinned node's own transform (and its parents') plays no part.
    const std::vector<glm::dmat4> worlds = worldsOf(model, localsAt(model, kTime));
    const std::vector<double> inverseBinds = accessorValues(model, skin.inverseBindMatrices);
    ASSERT_EQ(inverseBinds.size(), 16 * skin.joints.size());
    std::vector<glm::dmat4> joints;
    for (std::size_t j = 0; j < skin.joints.size(); ++j)
        joints.push_back(worlds.at(static_cast<std::size_t>(skin.joints[j])) *
                         glm::make_mat4(&inverseBinds[16 * j]));

    const std::vector<double> indices = accessorValues(model, primitive.indices);
    const std::vector<double> positions =
        accessorValues(model, primitive.attributes.at("POSITION"));
    const std::vector<double> jointsOf = accessorValues(model, primitive.attributes.at("JOINTS_0"));
    const std::vector<double> weightsOf =
        accessorValues(model, primitive.attributes.at("WEIGHTS_0"));
    // Σ wᵢ Mᵢ v over the vertex's four joints (its float weights sum to one within 1e-7).
    const auto skinned = [&](std::size_t vertex) {
        const glm::dvec4 rest(positions[3 * vertex], positions[3 * vertex + 1],
                              positions[3 * vertex + 2], 1.0);
        glm::dvec4 sum(0.0);
        for (std::size_t i = 0; i < 4; ++i)
            sum += weightsOf[4 * vertex + i] *
                   (joints.at(static_cast<std::size_t>(jointsOf[4 * vertex + i])) * rest);
        return glm::dvec3(sum);
    };
    const auto heaviestJoint = [&](std::size_t vertex) {
        std::size_t heaviest = 0;
        for (std::size_t i = 1; i < 4; ++i)
            if (weightsOf[4 * vertex + i] > weightsOf[4 * vertex + heaviest]) heaviest = i;
        return static_cast<std::size_t>(jointsOf[4 * vertex + heaviest]);
    };

    // The loader keeps the index order, one corner after another; CesiumMan has no triangle
    // without area at this time, so triangle t is the scene's triangle t.
    const Scene scene = loadAt(path, kTime);
    ASSERT_EQ(scene.repairs.zeroAreaTriangles, 0u);
    ASSERT_EQ(3 * scene.triangleCount(), indices.size());
    // Positions are floats from the file, skinned in double and rounded to float: an error of a
    // few 2⁻²⁴ of the figure's 1.5 m (about 1e-7 m). 1e-5 m leaves a hundredfold margin, while
    // a wrong keyframe, interval or parent moves these vertices by millimetres or more.
    constexpr float kPoseTolerance = 1e-5f;
    // For each joint, the first triangle whose first corner that joint moves most: the three
    // corners of triangles all over the body, under every joint that carries a vertex.
    std::vector<bool> covered(skin.joints.size(), false);
    std::size_t checked = 0;
    for (std::size_t t = 0; 3 * t < indices.size(); ++t) {
        const std::size_t joint = heaviestJoint(static_cast<std::size_t>(indices[3 * t]));
        if (covered.at(joint)) continue;
        covered[joint] = true;
        for (std::size_t c = 0; c < 3; ++c) {
            const auto vertex = static_cast<std::size_t>(indices[3 * t + c]);
            SCOPED_TRACE("triangle " + std::to_string(t) + ", vertex " + std::to_string(vertex) +
                         ", joint " + std::to_string(joint));
            expectNear(scene.positions[3 * t + c], glm::vec3(skinned(vertex) - scene.worldOrigin),
                       kPoseTolerance);
            ++checked;
        }
    }
    // Most of the 19 joints carry vertices (the leaf joints of the toes may not).
    EXPECT_GE(checked, 3u * 12u);
}

class GltfAnimatedSampleLoads : public testing::TestWithParam<const char*> {};

TEST_P(GltfAnimatedSampleLoads, WithoutIgnoringAnything) {
    const std::string path = kSharedScenesDir + GetParam();
    if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " not found";
    for (const std::optional<double> time : {std::optional<double>(), std::optional<double>(0.7)}) {
        testing::internal::CaptureStderr();
        const Scene scene = loadAt(path, time);
        const std::string notes = testing::internal::GetCapturedStderr();
        EXPECT_EQ(notes.find("ignoring"), std::string::npos) << notes;
        EXPECT_GT(scene.triangleCount(), 0u);
    }
}

INSTANTIATE_TEST_SUITE_P(Samples, GltfAnimatedSampleLoads,
                         testing::Values("CesiumMan/CesiumMan.glb", "RiggedFigure/RiggedFigure.glb",
                                         "SimpleSkin/SimpleSkin.gltf",
                                         "AnimatedMorphCube/AnimatedMorphCube.glb",
                                         "MorphPrimitivesTest/MorphPrimitivesTest.glb",
                                         "BoxAnimated/BoxAnimated.glb",
                                         "InterpolationTest/InterpolationTest.glb"),
                         [](const testing::TestParamInfo<const char*>& test) {
                             std::string name = std::filesystem::path(test.param).stem().string();
                             return name;
                         });

} // namespace
} // namespace vkpt::gltf_animation_test
