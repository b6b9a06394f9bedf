// emitters_test.cpp — the light list: selection in proportion to power (chi-square), and a
// light-sampling pdf that integrates to 1 over the directions that reach an emitter.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "../support/chi_square.h"
#include "common/math_constants.h"
#include "prepare/emitters.h"
#include "prepare/prepared_scene.h"
#include "prepare/prepared_scene_view.h"
#include "reference/scene_tracer.h"
#include "reference/stack_intersector.h"
#include "shared/lights.h"
#include "shared/rng.h"
#include "shared/sampling.h"

namespace vkpt::emitters_test {
namespace {

void addQuad(Scene& scene, glm::vec3 corner, glm::vec3 edgeA, glm::vec3 edgeB,
             std::uint32_t material) {
    glm::vec3 p[4] = {corner, corner + edgeA, corner + edgeA + edgeB, corner + edgeB};
    glm::vec3 n = glm::normalize(glm::cross(edgeA, edgeB));
    for (int t : {0, 2}) {
        glm::vec3 tri[3] = {p[0], p[1 + t / 2], p[2 + t / 2]};
        for (const glm::vec3& v : tri) {
            scene.positions.push_back(v);
            scene.normals.push_back(n);
        }
        scene.materialIndices.push_back(material);
    }
}

SceneMaterial emitter(glm::vec3 radiance, bool doubleSided) {
    SceneMaterial m;
    m.emission = radiance;
    m.doubleSided = doubleSided;
    m.baseColor = glm::vec4(0.5f, 0.5f, 0.5f, 1.0f);
    return m;
}

// Three emitters of different power: a dim large quad, a bright small one, a double-sided
// one, plus a non-emitting quad that must not enter the list.
Scene threeEmitterScene() {
    Scene scene;
    scene.materials = {emitter(glm::vec3(1.0f), false), emitter(glm::vec3(8.0f), false),
                       emitter(glm::vec3(2.0f), true), emitter(glm::vec3(0.0f), false)};
    addQuad(scene, {-1, -1, -2}, {2, 0, 0}, {0, 2, 0}, 0); // faces +z, towards the origin
    addQuad(scene, {-0.2f, 1.5f, -0.2f}, {0, 0, 0.4f}, {0.4f, 0, 0}, 1); // faces −y
    addQuad(scene, {2, -0.5f, -0.5f}, {0, 1, 0}, {0, 0, 1}, 2);
    addQuad(scene, {-3, -3, 3}, {6, 0, 0}, {0, 6, 0}, 3);
    return scene;
}

// The three emitters plus an emitting sphere (radius 0.3, radiance 3) and a point light of
// 5 cd: every kind of area emitter and a delta light in one list.
Scene mixedEmitterScene() {
    Scene scene = threeEmitterScene();
    scene.materials.push_back(emitter(glm::vec3(3.0f), false));
    scene.spheres.push_back(
        {glm::vec3(-1.5f, 0.2f, 0.4f), 0.3f, std::uint32_t(scene.materials.size() - 1)});
    SceneLight point;
    point.kind = LightKind::Point;
    point.position = glm::vec3(0.0f, -1.0f, 1.0f);
    point.intensity = glm::vec3(5.0f);
    scene.lights.push_back(point);
    return scene;
}

TEST(Emitters, ListHoldsEmittingTrianglesWithPowerProportionalProbabilities) {
    PreparedScene prepared = prepareScene(threeEmitterScene());
    ASSERT_EQ(prepared.emitters.size(), 6u);
    double total = 0.0;
    for (const gpu::Emitter& e : prepared.emitters) {
        ASSERT_EQ(e.kind, EMITTER_TRIANGLE);
        const gpu::Triangle& t = prepared.triangles[e.primitive];
        const gpu::Material& m = prepared.materials[t.materialIndex];
        double sides = (m.flags & MATERIAL_DOUBLE_SIDED) ? 2.0 : 1.0;
        double power = kPi * gpu::luminance(m.emission) * triangleArea(t) * sides;
        total += power;
        EXPECT_NEAR(e.selectProbability, power / prepared.totalEmittedPower, 1e-6);
        EXPECT_EQ(&prepared.emitters[t.emitterIndex], &e);
    }
    EXPECT_NEAR(total, prepared.totalEmittedPower, 1e-9 * total);
    ASSERT_EQ(prepared.emitterCdf.size(), prepared.emitters.size());
    EXPECT_EQ(prepared.emitterCdf.back(), 1.0f);
}

TEST(Emitters, SelectionFrequenciesMatchProbabilitiesByChiSquare) {
    PreparedScene prepared = prepareScene(threeEmitterScene());
    const gpu::SceneView view = makeSceneView(prepared);
    const int n = 100000;
    std::vector<double> observed(prepared.emitters.size(), 0.0), expected(observed.size());
    for (uint32_t i = 0; i < uint32_t(n); ++i)
        observed[gpu::selectEmitter(gpu::randomFloats(9, i, 0, 0, DIM_LIGHT_FIRST).x, view)] += 1;
    for (std::size_t i = 0; i < expected.size(); ++i)
        expected[i] = n * double(prepared.emitters[i].selectProbability);
    test::ChiSquareResult r = test::chiSquareTest(observed, expected);
    EXPECT_GT(r.pValue, 0.01) << "chi2 " << r.statistic;
}

TEST(Emitters, SelectionCoversTheUnitIntervalEnds) {
    PreparedScene prepared = prepareScene(threeEmitterScene());
    const gpu::SceneView view = makeSceneView(prepared);
    EXPECT_EQ(gpu::selectEmitter(0.0f, view), 0u);
    EXPECT_EQ(gpu::selectEmitter(std::nextafter(1.0f, 0.0f), view), prepared.emitters.size() - 1);
    EXPECT_EQ(gpu::selectEmitter(1.0f, view), prepared.emitters.size() - 1);
}

struct PdfMean {
    double mean = 0.0;
    double standardError = 0.0;
};

// 4π·E[p_light(ω)] over uniform directions from `origin`: ∫ p_light dω over the directions
// that reach an area emitter.
PdfMean integrateLightPdf(const PreparedScene& prepared, const glm::vec3& origin,
                          std::uint32_t seed) {
    StackIntersectors intersectors(prepared);
    SceneTracer tracer(prepared, intersectors);
    const int n = 400000;
    double sum = 0.0, sumSq = 0.0;
    for (uint32_t i = 0; i < uint32_t(n); ++i) {
        glm::vec4 u = gpu::randomFloats(seed, i, 0, 0, DIM_BSDF);
        float z = 1.0f - 2.0f * u.x, r = std::sqrt(std::max(0.0f, 1.0f - z * z));
        float phi = 2.0f * float(kPi) * u.y;
        glm::vec3 d(r * std::cos(phi), r * std::sin(phi), z);
        ClosestHit hit = tracer.closest(origin, d, RayKind::Extension);
        if (!hit.hit) continue;
        gpu::SurfacePoint s = tracer.surfaceAt(hit, origin, d);
        double value = 4.0 * kPi * gpu::lightPdf(s, origin, tracer.view());
        sum += value;
        sumSq += value * value;
    }
    double mean = sum / n, variance = sumSq / n - mean * mean;
    return {mean, std::sqrt(variance / n)};
}

// ∫ p_light(ω) dω over the sphere = 1 when every emitter point is visible, within 4.42
// standard errors (p = 1e-5).
TEST(Emitters, LightPdfIntegratesToOneOverDirections) {
    PdfMean m = integrateLightPdf(prepareScene(threeEmitterScene()), {0.1f, 0.05f, -0.3f}, 5);
    EXPECT_NEAR(m.mean, 1.0, 4.42 * m.standardError);
}

// Sphere power π·L·4πr², point power 4π·I, and the selection probabilities in their ratio.
TEST(Emitters, SpheresAndPunctualLightsJoinTheListByPower) {
    PreparedScene prepared = prepareScene(mixedEmitterScene());
    ASSERT_EQ(prepared.emitters.size(), 8u);
    // Surfaces come in BVH order, then the punctual lights.
    auto sphereAt = std::find_if(prepared.emitters.begin(), prepared.emitters.end(),
                                 [](const gpu::Emitter& e) { return e.kind == EMITTER_SPHERE; });
    ASSERT_NE(sphereAt, prepared.emitters.end());
    const gpu::Emitter& sphere = *sphereAt;
    const gpu::Emitter& point = prepared.emitters[7];
    ASSERT_EQ(point.kind, EMITTER_POINT);
    EXPECT_TRUE(gpu::isSpherePrimitive(prepared.triangles[sphere.primitive]));
    EXPECT_EQ(prepared.triangles[sphere.primitive].emitterIndex,
              std::uint32_t(sphereAt - prepared.emitters.begin()));
    double spherePower = kPi * 3.0 * 4.0 * kPi * 0.3 * 0.3;
    double pointPower = 4.0 * kPi * 5.0;
    EXPECT_NEAR(sphere.selectProbability, spherePower / prepared.totalEmittedPower, 1e-6);
    EXPECT_NEAR(point.selectProbability, pointPower / prepared.totalEmittedPower, 1e-6);
    EXPECT_TRUE(prepared.usedFeatures.emissiveSpheres);
    EXPECT_TRUE(prepared.usedFeatures.pointLights);
    EXPECT_EQ(prepared.usedFeatures.emitterCount, 8u);
}

// One emitter: no CDF is built, and light sampling takes it without reading one.
TEST(Emitters, SingleEmitterHasNoCdf) {
    Scene scene;
    scene.materials = {emitter(glm::vec3(1.0f), false)};
    addQuad(scene, {-1, -1, -2}, {2, 0, 0}, {0, 2, 0}, 0);
    scene.materialIndices.pop_back(); // one triangle of the quad
    scene.positions.resize(3);
    scene.normals.resize(3);
    PreparedScene prepared = prepareScene(scene);
    ASSERT_EQ(prepared.emitters.size(), 1u);
    EXPECT_TRUE(prepared.emitterCdf.empty());
    gpu::LightSample light = gpu::sampleLight(glm::vec3(0.0f), glm::vec4(0.9f, 0.3f, 0.3f, 0.0f),
                                              makeSceneView(prepared));
    EXPECT_TRUE(light.valid);
    PreparedScene general = prepareScene(scene, {{}, true});
    EXPECT_EQ(general.emitterCdf.size(), 1u);
}

// With an emitting sphere among the triangles, ∫ p_light dω over the directions that reach an
// area emitter is their share of the selection probability from the point (the point light
// takes the rest), by either sampler.
TEST(Emitters, LightPdfWithASphereIntegratesToTheAreaEmittersShare) {
    for (LightSampler sampler : {LightSampler::Power, LightSampler::Bvh}) {
        PreparedScene prepared = prepareScene(mixedEmitterScene(), {{}, false, sampler});
        const glm::vec3 origin(0.1f, 0.05f, -0.3f);
        const gpu::SceneView view = makeSceneView(prepared);
        double areaShare = 0.0;
        for (std::uint32_t e = 0; e < prepared.emitters.size(); ++e)
            if (prepared.emitters[e].kind != EMITTER_POINT)
                areaShare += gpu::emitterSelectProbability(e, prepared.emitters[e], origin, view);
        PdfMean m = integrateLightPdf(prepared, origin, 15);
        EXPECT_NEAR(m.mean, areaShare, 4.42 * m.standardError)
            << "light BVH " << prepared.features.lightTree;
    }
}

// A light sample's pdf must equal lightPdf() for the same point: the two halves of MIS.
TEST(Emitters, SampledPdfEqualsEvaluatedPdf) {
    PreparedScene prepared = prepareScene(mixedEmitterScene());
    StackIntersectors intersectors(prepared);
    SceneTracer tracer(prepared, intersectors);
    const glm::vec3 origin(0.1f, 0.05f, -0.3f);
    for (uint32_t i = 0; i < 2000; ++i) {
        gpu::LightSample light =
            gpu::sampleLight(origin, gpu::randomFloats(6, i, 0, 0, DIM_LIGHT_FIRST), tracer.view());
        ASSERT_TRUE(light.valid);
        if (light.delta) continue;
        ClosestHit hit = tracer.closest(origin, light.direction, RayKind::Extension);
        ASSERT_TRUE(hit.hit);
        gpu::SurfacePoint s = tracer.surfaceAt(hit, origin, light.direction);
        EXPECT_NEAR(gpu::lightPdf(s, origin, tracer.view()), light.pdfSolidAngle,
                    1e-3f * light.pdfSolidAngle);
    }
}

} // namespace
} // namespace vkpt::emitters_test
