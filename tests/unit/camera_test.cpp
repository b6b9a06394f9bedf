// camera_test.cpp — camera selection, the framing camera, the GPU camera basis, and cameras
// placed by rotated nodes in a glTF file.
#include <cmath>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "common/errors.h"
#include "scene/camera.h"
#include "scene/gltf_loader.h"
#include "shared/camera.h"

namespace vkpt::camera_test {
namespace {

const std::string kLoaderDir = VKPT_SCENES_DIR "/loader/";

void expectNear(const glm::vec3& actual, const glm::vec3& expected, float tolerance = 1e-6f) {
    EXPECT_NEAR(actual.x, expected.x, tolerance) << "component x";
    EXPECT_NEAR(actual.y, expected.y, tolerance) << "component y";
    EXPECT_NEAR(actual.z, expected.z, tolerance) << "component z";
}

SceneCamera namedCamera(const std::string& name, const glm::vec3& position) {
    SceneCamera camera;
    camera.name = name;
    camera.position = position;
    return camera;
}

// One triangle spanning (0, 0, 0) to (2, 1, 0), with the given cameras.
Scene sceneWithCameras(int cameraCount) {
    Scene scene;
    scene.sourcePath = "scenes/test.gltf";
    scene.positions = {{0, 0, 0}, {2, 0, 0}, {0, 1, 0}};
    scene.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    scene.materialIndices = {0};
    scene.materials = {SceneMaterial{}};
    for (int i = 0; i < cameraCount; ++i) {
        scene.cameras.push_back(namedCamera("camera " + std::to_string(i), glm::vec3(float(i))));
    }
    return scene;
}

// --- Selection -----------------------------------------------------------------------------

TEST(CameraSelection, PicksTheRequestedCamera) {
    const Scene scene = sceneWithCameras(3);
    EXPECT_EQ(selectCamera(scene, 2).name, "camera 2");
    EXPECT_EQ(selectCamera(scene, 0).name, "camera 0");
}

TEST(CameraSelection, DefaultsToTheFirstCamera) {
    EXPECT_EQ(selectCamera(sceneWithCameras(3), std::nullopt).name, "camera 0");
}

TEST(CameraSelection, RejectsAnIndexOutOfRangeWithOneLine) {
    const Scene scene = sceneWithCameras(2);
    for (int index : {2, 7, -1}) {
        try {
            selectCamera(scene, index);
            ADD_FAILURE() << "camera " << index << " was accepted";
        } catch (const InputError& error) {
            EXPECT_EQ(std::string(error.what()), "scenes/test.gltf: camera " +
                                                     std::to_string(index) +
                                                     " requested but the scene has 2 cameras");
        }
    }
}

TEST(CameraSelection, RejectsAnyIndexWhenTheSceneHasNoCamera) {
    EXPECT_THROW(selectCamera(sceneWithCameras(0), 0), InputError);
}

TEST(CameraSelection, FramesTheBoundsAndSaysSoWhenTheSceneHasNoCamera) {
    const Scene scene = sceneWithCameras(0);
    testing::internal::CaptureStderr();
    const SceneCamera camera = selectCamera(scene, std::nullopt, 2.0f);
    EXPECT_EQ(testing::internal::GetCapturedStderr(),
              "scenes/test.gltf: no camera in the scene; framing its bounds from +Z\n");
    const SceneCamera framing = makeFramingCamera(computeBounds(scene), 2.0f);
    EXPECT_EQ(camera.position, framing.position);
    EXPECT_EQ(camera.forward, framing.forward);
    EXPECT_EQ(camera.yfov, framing.yfov);
}

// --- The framing camera --------------------------------------------------------------------

// Whether a point is inside the camera's view frustum for an image of the given aspect.
bool seesPoint(const SceneCamera& camera, float aspect, const glm::vec3& point) {
    const glm::vec3 right = glm::normalize(glm::cross(camera.forward, camera.up));
    const glm::vec3 d = point - camera.position;
    const float depth = glm::dot(d, camera.forward);
    const float tanHalfY = std::tan(0.5f * camera.yfov) * (1.0f + 1e-5f); // rounding slack
    return depth > 0.0f && std::abs(glm::dot(d, right)) <= depth * tanHalfY * aspect &&
           std::abs(glm::dot(d, camera.up)) <= depth * tanHalfY;
}

struct FramingCase {
    Bounds bounds;
    float aspect;
};

class FramingCamera : public testing::TestWithParam<FramingCase> {};

TEST_P(FramingCamera, SeesEveryCornerOfTheBoundsFromPlusZ) {
    const auto& [bounds, aspect] = GetParam();
    const SceneCamera camera = makeFramingCamera(bounds, aspect);
    EXPECT_EQ(camera.forward, glm::vec3(0, 0, -1));
    EXPECT_EQ(camera.up, glm::vec3(0, 1, 0));
    EXPECT_NEAR(camera.yfov, std::numbers::pi_v<float> / 4.0f, 1e-7f);
    EXPECT_GT(camera.position.z, bounds.max.z);
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 point((corner & 1) ? bounds.max.x : bounds.min.x,
                              (corner & 2) ? bounds.max.y : bounds.min.y,
                              (corner & 4) ? bounds.max.z : bounds.min.z);
        EXPECT_TRUE(seesPoint(camera, aspect, point)) << "corner " << corner;
    }
}

TEST_P(FramingCamera, FitsTheBoundingSphereTightly) {
    // The sphere touches the narrower field of view: distance * sin(half angle) = radius.
    const auto& [bounds, aspect] = GetParam();
    const SceneCamera camera = makeFramingCamera(bounds, aspect);
    const glm::vec3 center = 0.5f * (bounds.min + bounds.max);
    const float radius = 0.5f * glm::length(bounds.max - bounds.min);
    const float tanHalfY = std::tan(0.5f * camera.yfov);
    const float halfMin = std::atan(std::min(tanHalfY, tanHalfY * aspect));
    EXPECT_NEAR(glm::length(camera.position - center) * std::sin(halfMin), radius, 1e-4f * radius);
    expectNear(glm::vec3(camera.position.x, camera.position.y, 0.0f),
               glm::vec3(center.x, center.y, 0.0f), 1e-5f);
}

INSTANTIATE_TEST_SUITE_P(
    BoundsAndAspects, FramingCamera,
    testing::Values(FramingCase{{{-1, -1, -1}, {1, 1, 1}}, 1.0f},
                    FramingCase{{{-1, -1, -1}, {1, 1, 1}}, 0.5f},
                    FramingCase{{{0, 0, 0}, {10, 1, 1}}, 2.0f},
                    FramingCase{{{0, 0, 0}, {10, 1, 1}}, 0.25f},
                    FramingCase{{{-0.035f, -0.016f, -0.037f}, {0.038f, 0.013f, 0.037f}}, 1.5f},
                    FramingCase{{{100, 200, -300}, {101, 230, -290}}, 1.0f}));

// --- The GPU camera ------------------------------------------------------------------------

TEST(GpuCamera, BasisIsOrthonormalAndRightHanded) {
    SceneCamera camera;
    camera.position = {1, 2, 3};
    camera.forward = glm::normalize(glm::vec3(1, -0.5f, -2));
    camera.up = glm::normalize(glm::vec3(0.1f, 1, 0)); // not quite orthogonal to forward
    camera.yfov = 0.7f;
    const gpu::Camera gpuCamera = makeGpuCamera(camera, 640, 480);
    EXPECT_NEAR(glm::length(gpuCamera.right), 1.0f, 1e-6f);
    EXPECT_NEAR(glm::length(gpuCamera.up), 1.0f, 1e-6f);
    EXPECT_NEAR(glm::length(gpuCamera.forward), 1.0f, 1e-6f);
    EXPECT_NEAR(glm::dot(gpuCamera.right, gpuCamera.up), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::dot(gpuCamera.right, gpuCamera.forward), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::dot(gpuCamera.up, gpuCamera.forward), 0.0f, 1e-6f);
    expectNear(gpuCamera.right, glm::normalize(glm::cross(camera.forward, camera.up)));
    expectNear(gpuCamera.forward, camera.forward);
    // up is the given up with its component along forward removed (Gram-Schmidt)
    const glm::vec3 projectedUp = camera.up - glm::dot(camera.up, camera.forward) * camera.forward;
    expectNear(gpuCamera.up, glm::normalize(projectedUp));
}

TEST(GpuCamera, CarriesFieldOfViewAspectAndImageSize) {
    SceneCamera camera;
    camera.yfov = 0.8f;
    const gpu::Camera gpuCamera = makeGpuCamera(camera, 640, 480);
    EXPECT_EQ(gpuCamera.position, camera.position);
    EXPECT_FLOAT_EQ(gpuCamera.tanHalfFovY, std::tan(0.4f));
    EXPECT_FLOAT_EQ(gpuCamera.aspect, 640.0f / 480.0f);
    EXPECT_EQ(gpuCamera.width, 640u);
    EXPECT_EQ(gpuCamera.height, 480u);
    expectNear(gpuCamera.right, {1, 0, 0}); // the default camera looks down -Z with +Y up
}

TEST(GpuCamera, PerspectiveRaysStartAtThePositionThroughThePinholesPlane) {
    SceneCamera camera;
    camera.position = {1, 2, 3};
    camera.yfov = 0.8f;
    const gpu::Camera gpuCamera = makeGpuCamera(camera, 200, 100);
    EXPECT_EQ(gpuCamera.projection, CAMERA_PERSPECTIVE);
    EXPECT_EQ(gpu::cameraRayOrigin(gpuCamera, {0.0f, 0.0f}), camera.position);
    // The top-left corner: tan(yfov/2) up and twice that (the aspect) to the left.
    const float t = std::tan(0.4f);
    expectNear(gpu::cameraRayDirection(gpuCamera, {0.0f, 0.0f}),
               glm::normalize(glm::vec3(-2.0f * t, t, -1.0f)));
}

// glTF orthographic camera: ymag is the half-height; the image's aspect sets the half-width.
TEST(GpuCamera, OrthographicRaysAreParallelFromTheImagePlane) {
    SceneCamera camera;
    camera.position = {1, 2, 3};
    camera.projection = CameraProjection::Orthographic;
    camera.ymag = 0.5f;
    camera.xmag = 7.0f;                     // not used: the image's aspect decides the width
    camera.forward = {-0.0f, -0.0f, -1.0f}; // as a node transform gives it
    const gpu::Camera gpuCamera = makeGpuCamera(camera, 200, 100);
    EXPECT_EQ(gpuCamera.projection, CAMERA_ORTHOGRAPHIC);
    EXPECT_FLOAT_EQ(gpuCamera.orthoHalfHeight, 0.5f);
    const glm::vec2 corners[] = {{0, 0}, {200, 0}, {0, 100}, {200, 100}, {100, 50}};
    const glm::vec3 origins[] = {{0, 2.5f, 3}, {2, 2.5f, 3}, {0, 1.5f, 3}, {2, 1.5f, 3}, {1, 2, 3}};
    for (std::size_t i = 0; i < 5; ++i) {
        expectNear(gpu::cameraRayOrigin(gpuCamera, corners[i]), origins[i], 1e-6f);
        EXPECT_EQ(gpu::cameraRayDirection(gpuCamera, corners[i]), glm::vec3(0, 0, -1));
    }
}

// --- Cameras placed by glTF nodes ----------------------------------------------------------

TEST(GltfCameras, RotatedScaledNodeMapsMinusZAndKeepsUnitVectors) {
    // Node: translation (1, 2, 3), 90 degrees about +Y, scale 2: local -Z becomes world -X.
    const Scene scene = loadGltfScene(kLoaderDir + "cameras.gltf");
    ASSERT_EQ(scene.cameras.size(), 3u);
    const SceneCamera& camera = scene.cameras[0];
    EXPECT_EQ(camera.name, "rotated");
    expectNear(camera.position, {1, 2, 3});
    expectNear(camera.forward, {-1, 0, 0});
    expectNear(camera.up, {0, 1, 0});
    EXPECT_FLOAT_EQ(camera.yfov, 0.5f);
}

TEST(GltfCameras, ChildCameraInheritsItsParentsRotation) {
    // Parent: translation (0, 0, 10), 90 degrees about +X: -Z becomes +Y, +Y becomes +Z.
    const Scene scene = loadGltfScene(kLoaderDir + "cameras.gltf");
    ASSERT_EQ(scene.cameras.size(), 3u);
    const SceneCamera& camera = scene.cameras[2];
    EXPECT_EQ(camera.name, "child");
    expectNear(camera.position, {0, 0, 10});
    expectNear(camera.forward, {0, 1, 0});
    expectNear(camera.up, {0, 0, 1});
    EXPECT_FLOAT_EQ(camera.yfov, 1.0f);
}

TEST(GltfCameras, LoadsOrthographicCamerasSilently) {
    const std::string path = kLoaderDir + "cameras.gltf";
    testing::internal::CaptureStderr();
    const Scene scene = loadGltfScene(path);
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
    ASSERT_EQ(scene.cameras.size(), 3u);
    const SceneCamera& camera = scene.cameras[1]; // node 2, in walk order between the others
    EXPECT_EQ(camera.name, "ortho");
    EXPECT_EQ(camera.projection, CameraProjection::Orthographic);
    EXPECT_FLOAT_EQ(camera.xmag, 1.0f);
    EXPECT_FLOAT_EQ(camera.ymag, 1.0f);
    expectNear(camera.forward, {0, 0, -1});
}

} // namespace
} // namespace vkpt::camera_test
