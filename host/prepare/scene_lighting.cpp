// scene_lighting.cpp — the scene's emitted power, its emissive textures integrated over each
// triangle, against the studio's; and the decision that follows.
#include "prepare/scene_lighting.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "common/math_constants.h"
#include "prepare/emission_mean.h"
#include "prepare/environment_map.h"
#include "prepare/prepared_scene.h"
#include "prepare/studio_environment.h"
#include "shared/sampling.h"
#include "shared/texture_sampling.h"

namespace vkpt {

namespace {

double luminanceOf(const glm::vec3& c) {
    return double(gpu::luminance(c));
}

double sides(const SceneMaterial& material) {
    return material.doubleSided ? 2.0 : 1.0;
}

double triangleArea(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2) {
    return 0.5 * glm::length(
                     glm::cross(glm::dvec3(p1) - glm::dvec3(p0), glm::dvec3(p2) - glm::dvec3(p0)));
}

double emittedPowerOfTriangles(const Scene& scene) {
    double power = 0.0;
    for (std::size_t t = 0; t < scene.triangleCount(); ++t) {
        const SceneMaterial& material = scene.materials[scene.materialIndices[t]];
        if (!material.emits()) continue;
        const glm::vec3 radiance = meanTriangleEmission(scene, t);
        const double area = triangleArea(scene.positions[3 * t], scene.positions[3 * t + 1],
                                         scene.positions[3 * t + 2]);
        power += kPi * area * luminanceOf(radiance) * sides(material);
    }
    return power;
}

double emittedPowerOfSpheres(const Scene& scene) {
    double power = 0.0;
    for (const SceneSphere& sphere : scene.spheres) {
        const SceneMaterial& material = scene.materials[sphere.material];
        const double area = 4.0 * kPi * double(sphere.radius) * double(sphere.radius);
        power += kPi * area * luminanceOf(material.emission) * sides(material);
    }
    return power;
}

} // namespace

SceneLightingMeasure measureSceneLighting(const Scene& scene) {
    SceneLightingMeasure measure;
    for (const SceneLight& light : scene.lights)
        if (luminanceOf(light.intensity) > 0.0) ++measure.punctualLights;
    measure.emittedPower = emittedPowerOfTriangles(scene) + emittedPowerOfSpheres(scene);
    const double radius = sceneBoundingRadius(scene);
    measure.studioPower = 4.0 * kPi * kPi * radius * radius * kStudioMeanLuminance;
    return measure;
}

LightingDecision decideSceneLighting(const Scene& scene, const LightingRequest& request) {
    LightingDecision decision;
    decision.measure = measureSceneLighting(scene);
    decision.useStudio = !request.environmentGiven && request.defaultLightAllowed &&
                         request.lightMatters && decision.measure.punctualLights == 0 &&
                         decision.measure.emitterFraction() < kNegligibleEmitterFraction;
    return decision;
}

// The map is made once per process (60 ms) and copied: an animation's frames each need it.
LightingDecision applyDefaultLighting(Scene& scene, const LightingRequest& request) {
    const LightingDecision decision = decideSceneLighting(scene, request);
    if (!decision.useStudio) return decision;
    static const SceneEnvironment studio = makeStudioEnvironment();
    scene.environment = studio;
    return decision;
}

std::string describeLightingReason(const SceneLightingMeasure& measure) {
    if (!(measure.emittedPower > 0.0)) return "no lights or emitters";
    char text[96];
    std::snprintf(text, sizeof(text), "emitters at %.2g of the studio's power",
                  measure.emitterFraction());
    return text;
}

std::string describeLightingMeasure(const SceneLightingMeasure& measure) {
    char text[160];
    std::snprintf(text, sizeof(text),
                  "%zu punctual lights, emitted power %.4g, the studio's %.4g (fraction %.3g)",
                  measure.punctualLights, measure.emittedPower, measure.studioPower,
                  measure.emitterFraction());
    return text;
}

} // namespace vkpt
