// grazing_and_slab_test.cpp — the ray offset at work in whole scenes, in both renderers:
// a finely split plane lit at grazing angles (85° to 89.9° from its normal) shows no acne, and a
// slab 1e-5 thick lit from above lets no light through to the floor below it.
#include <gtest/gtest.h>

#include <cmath>

#include "../support/ray_queries.h"
#include "bvh/bvh_traverse.h"
#include "extremes_support.h"
#include "shared/camera.h"
#include "shared/intersect.h"
#include "shared/ray_offset.h"
#include "shared/rng.h"
#include "shared/sampling.h"

namespace vkpt::grazing_and_slab_test {
namespace {

// ---------------------------------------------------------------------------------------------
// A plane of 32 × 32 cells (2,048 triangles) over [-1, 1]², facing +y, and a small square light
// 4 units from its centre at `theta` degrees from the plane's normal, facing the centre.

constexpr float kLightDistance = 4.0f;
constexpr float kLightSide = 0.004f; // at 89.9° its centre is 0.007 above the plane
constexpr float kLightRadiance = 25000.0f;
constexpr float kAlbedo = 0.5f;

struct GrazingScene {
    Scene scene;
    glm::vec3 lightCorners[4];
};

GrazingScene grazingScene(float thetaDegrees) {
    GrazingScene g;
    Scene& scene = g.scene;
    std::uint32_t white = test::addMaterial(scene, glm::vec3(kAlbedo));
    std::uint32_t light = test::addMaterial(scene, glm::vec3(0.0f), glm::vec3(kLightRadiance));
    test::addHorizontalGrid(scene, glm::vec2(-1.0f), glm::vec2(1.0f), 0.0f, true, 32, white);
    const float theta = glm::radians(thetaDegrees);
    const glm::vec3 centre = kLightDistance * glm::vec3(std::sin(theta), std::cos(theta), 0.0f);
    const glm::vec3 facing = -glm::normalize(centre); // the light's front faces the plane
    const glm::vec3 u = glm::vec3(0.0f, 0.0f, 1.0f) * (0.5f * kLightSide);
    const glm::vec3 v = glm::cross(facing, glm::vec3(0.0f, 0.0f, 1.0f)) * (0.5f * kLightSide);
    // Counter-clockwise seen from the plane: (b − a) × (c − a) ∝ u × v = `facing`.
    g.lightCorners[0] = centre - u - v;
    g.lightCorners[1] = centre + u - v;
    g.lightCorners[2] = centre + u + v;
    g.lightCorners[3] = centre - u + v;
    test::addQuad(scene, g.lightCorners[0], g.lightCorners[1], g.lightCorners[2], g.lightCorners[3],
                  light);
    // Looking straight down at the receiving patch [-0.5, 0.5]².
    scene.cameras.push_back(test::lookAt(glm::vec3(0.0f, 2.0f, 0.0f), glm::vec3(0.0f),
                                         glm::vec3(0.0f, 0.0f, -1.0f), 28.0f));
    return g;
}

// Irradiance at p (normal +y) from the uniform Lambertian polygon, exactly (Lambert's formula):
// E = L/2 · Σ_i angle(r_i, r_i+1) · n · unit(r_i × r_i+1), r_i the unit vectors to the corners.
double irradiance(const GrazingScene& g, glm::dvec3 p) {
    double sum = 0.0;
    for (int i = 0; i < 4; ++i) {
        glm::dvec3 a = glm::normalize(glm::dvec3(g.lightCorners[i]) - p);
        glm::dvec3 b = glm::normalize(glm::dvec3(g.lightCorners[(i + 1) % 4]) - p);
        glm::dvec3 c = glm::cross(a, b);
        sum += std::acos(glm::clamp(glm::dot(a, b), -1.0, 1.0)) * glm::normalize(c).y;
    }
    return 0.5 * double(kLightRadiance) * std::abs(sum);
}

// Shadow segments exactly as the renderers make them: from a point interpolated on a plane
// triangle of the receiving patch, offset along the normal, to a point on the light, offset
// towards the receiver.
std::vector<DeviceRay> shadowSegments(const PreparedScene& prepared, std::uint32_t count) {
    std::vector<DeviceRay> rays;
    const gpu::Triangle* lightTriangles[2] = {nullptr, nullptr};
    std::vector<const gpu::Triangle*> receivers;
    for (const gpu::Triangle& t : prepared.triangles) {
        if (t.emitterIndex != NO_EMITTER) {
            lightTriangles[lightTriangles[0] ? 1 : 0] = &t;
        } else if (glm::all(glm::lessThan(glm::abs(t.v0), glm::vec3(0.5f)))) {
            receivers.push_back(&t);
        }
    }
    for (std::uint32_t i = 0; i < count; ++i) {
        glm::vec4 a = gpu::randomFloats(41, i, 0, 0, 20), b = gpu::randomFloats(41, i, 0, 0, 21);
        const gpu::Triangle& r = *receivers[std::size_t(a.x * float(receivers.size()))];
        glm::vec3 w = gpu::sampleTriangleBarycentrics({a.y, a.z});
        glm::vec3 p = w.x * r.v0 + w.y * r.v1 + w.z * r.v2;
        const gpu::Triangle& l = *lightTriangles[a.w < 0.5f ? 0 : 1];
        glm::vec3 wl = gpu::sampleTriangleBarycentrics({b.x, b.y});
        glm::vec3 q = wl.x * l.v0 + wl.y * l.v1 + wl.z * l.v2;
        glm::vec3 origin = gpu::offsetFromSurface(p, glm::vec3(0.0f, 1.0f, 0.0f),
                                                  gpu::triangleCoordinateScale(r.v0, r.v1, r.v2));
        glm::vec3 lightNormal = gpu::unitFaceNormal(l.v0, l.v1, l.v2);
        glm::vec3 target =
            gpu::offsetFromSurface(q, lightNormal, gpu::triangleCoordinateScale(l.v0, l.v1, l.v2));
        rays.push_back({origin, target - origin, 1.0f});
    }
    return rays;
}

class GrazingLight : public test::GpuTest, public ::testing::WithParamInterface<float> {};

// 10^5 shadow segments from the plane to the light: none may be blocked, on the CPU or the
// device (the plane is the only other geometry, and every segment leaves it upwards).
TEST_P(GrazingLight, NoShadowRayIsBlockedByThePlaneItLeaves) {
    GrazingScene g = grazingScene(GetParam());
    test::LoadedTestScene scene = test::prepareTestScene(g.scene);
    std::vector<DeviceRay> rays = shadowSegments(scene.prepared, 100000);
    std::uint64_t blocked = 0;
    const StackBvh stackBvh = makeStackBvh(scene.prepared.tree, scene.prepared.triangles);
    for (const DeviceRay& ray : rays)
        blocked += anyHitStack(stackBvh, {ray.origin, ray.direction, 0.0f, 1.0f});
    EXPECT_EQ(blocked, 0u) << "vkpt-ref, theta " << GetParam();
    DeviceRayQueries queries(context(), scene.prepared);
    std::vector<bool> occluded = queries.occluded(rays);
    EXPECT_EQ(std::count(occluded.begin(), occluded.end(), true), 0)
        << "vkpt, theta " << GetParam();
}

// The rendered plane (direct lighting) has the exact irradiance's mean, within 1 %: acne would
// darken it by the share of blocked light samples.
TEST_P(GrazingLight, RenderedPlaneHasTheAnalyticBrightness) {
    GrazingScene g = grazingScene(GetParam());
    test::LoadedTestScene scene = test::prepareTestScene(g.scene);
    RenderSettings settings = test::testSettings(16, 64);
    settings.maxDepth = 1;
    test::BothRenders r = test::renderBoth(context(), scene, settings);
    // The expected image: albedo/π × E at each pixel's centre (the box filter's mean to first
    // order), where the camera ray meets the plane.
    gpu::Camera camera = makeGpuCamera(g.scene.cameras[0], 16, 16);
    double expected = 0.0;
    for (std::uint32_t y = 0; y < 16; ++y)
        for (std::uint32_t x = 0; x < 16; ++x) {
            glm::vec3 d =
                gpu::cameraRayDirection(camera, glm::vec2(float(x) + 0.5f, float(y) + 0.5f));
            glm::dvec3 p =
                glm::dvec3(camera.position) - double(camera.position.y / d.y) * glm::dvec3(d);
            expected += double(kAlbedo) / VKPT_PI * irradiance(g, p);
        }
    expected /= 256.0;
    for (const RenderOutput* out : {&r.cpu, &r.gpu}) {
        EXPECT_TRUE(test::outputIsFinite(*out));
        // Luminance of a grey image is its value.
        MeanEstimate mean = meanLuminance(*out);
        EXPECT_NEAR(mean.mean, expected, 0.01 * expected + 5.0 * mean.standardError)
            << (out == &r.cpu ? "vkpt-ref" : "vkpt") << ", theta " << GetParam();
    }
    EXPECT_TRUE(test::devicesAgree(r.gpu, r.cpu));
}

INSTANTIATE_TEST_SUITE_P(EightyFiveToAlmostNinety, GrazingLight,
                         ::testing::Values(85.0f, 88.0f, 89.0f, 89.9f));

// ---------------------------------------------------------------------------------------------
// A closed slab 1e-5 thick over [-4, 4]² (its faces split 16 × 16), a light above it, a floor
// 0.01 below it and the camera in the gap looking at the floor. No light can reach the floor:
// every pixel must be exactly 0 in both renderers. A leak through the slab would show.

Scene slabScene(float thickness) {
    Scene scene;
    std::uint32_t white = test::addMaterial(scene, glm::vec3(0.8f));
    std::uint32_t light = test::addMaterial(scene, glm::vec3(0.0f), glm::vec3(100.0f));
    test::addHorizontalGrid(scene, glm::vec2(-4.0f), glm::vec2(4.0f), thickness, true, 16, white);
    test::addHorizontalGrid(scene, glm::vec2(-4.0f), glm::vec2(4.0f), 0.0f, false, 16, white);
    const float e = 4.0f;
    for (int side = 0; side < 4; ++side) { // the slab's rims
        glm::vec3 a(-e, 0.0f, -e), b(e, 0.0f, -e);
        auto turn = [&](glm::vec3 p) {
            for (int k = 0; k < side; ++k)
                p = glm::vec3(-p.z, p.y, p.x);
            return p;
        };
        glm::vec3 up(0.0f, thickness, 0.0f);
        test::addQuad(scene, turn(a), turn(a) + up, turn(b) + up, turn(b), white);
    }
    test::addQuad(scene, {-0.25f, 1.0f, -0.25f}, {0.25f, 1.0f, -0.25f}, {0.25f, 1.0f, 0.25f},
                  {-0.25f, 1.0f, 0.25f}, light); // facing down
    test::addHorizontalGrid(scene, glm::vec2(-2.0f), glm::vec2(2.0f), -0.01f, true, 8, white);
    scene.cameras.push_back(test::lookAt(glm::vec3(0.0f, -0.005f, 0.0f),
                                         glm::vec3(0.0f, -0.01f, 0.0f),
                                         glm::vec3(0.0f, 0.0f, -1.0f), 60.0f));
    return scene;
}

class ThinSlab : public test::GpuTest {};

TEST_F(ThinSlab, LitFromAboveLetsNoLightThrough) {
    Scene scene = slabScene(1e-5f);
    // The light really shines on the slab: seen from above it is bright.
    ASSERT_GT(computeBounds(scene).max.y, 0.9f);
    RenderSettings settings = test::testSettings(24, 64);
    test::BothRenders r = test::renderBoth(context(), test::prepareTestScene(scene), settings);
    for (const RenderOutput* out : {&r.cpu, &r.gpu}) {
        std::uint32_t lit = 0;
        for (const glm::vec3& p : out->image.pixels)
            lit += p != glm::vec3(0.0f);
        EXPECT_EQ(lit, 0u) << (out == &r.cpu ? "vkpt-ref" : "vkpt") << ": pixels with light";
        EXPECT_TRUE(test::outputIsFinite(*out));
    }
}

TEST_F(ThinSlab, SeenFromAboveIsLit) {
    Scene scene = slabScene(1e-5f);
    scene.cameras[0] = test::lookAt(glm::vec3(0.0f, 0.5f, 1.0f), glm::vec3(0.0f),
                                    glm::vec3(0.0f, 1.0f, 0.0f), 60.0f);
    RenderSettings settings = test::testSettings(16, 16);
    test::BothRenders r = test::renderBoth(context(), test::prepareTestScene(scene), settings);
    EXPECT_GT(meanLuminance(r.cpu).mean, 0.1);
    EXPECT_TRUE(test::devicesAgree(r.gpu, r.cpu));
}

} // namespace
} // namespace vkpt::grazing_and_slab_test
