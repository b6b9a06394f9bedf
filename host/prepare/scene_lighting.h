// scene_lighting.h — whether a scene brings light that can reach the image, and so whether it
// gets the built-in studio (studio_environment.h). One function decides for vkpt and vkpt-ref
// alike; what it decides reaches the render's identity through the environment it sets, which
// the scene hash covers (docs/scene-model.md, "Default lighting").
#pragma once

#include <cstddef>
#include <string>

#include "scene/scene.h"

namespace vkpt {

// Emitting surfaces whose power is below this fraction of what the studio would pour into the
// scene's bounding sphere leave the image black but for the emitters themselves (ToyCar's
// headlight glints at 1.9e-4, DamagedHelmet's panels at 1.4e-3: mean luminance 0.0025), so the
// scene counts as unlit; TransmissionTest's labels (1.5e-2, mean 0.09) and the Cornell box
// (0.57) light their scenes. The threshold sits between those, a factor 3 from each; the
// figures are in docs/scene-model.md.
inline constexpr double kNegligibleEmitterFraction = 5e-3;

struct SceneLightingMeasure {
    std::size_t punctualLights = 0; // KHR_lights_punctual lights of non-zero intensity
    // Σ over emitting triangles and spheres of π·A·L (per emitting side): L the luminance of the
    // emissive factor times the emissive texture averaged over the triangle (so a texture black
    // almost everywhere counts by what it emits, not by its factor); a sphere by its factor.
    double emittedPower = 0.0;
    // What the studio would pour into the scene's bounding sphere of radius R: 4π²R²·L̄, with L̄
    // the studio's mean luminance (environment_map.h's power of an environment).
    double studioPower = 0.0;

    double emitterFraction() const { return studioPower > 0.0 ? emittedPower / studioPower : 0.0; }
};

SceneLightingMeasure measureSceneLighting(const Scene& scene);

// What the command line said about the environment and the default light.
struct LightingRequest {
    bool environmentGiven = false;   // --env or --env-color, black included
    bool defaultLightAllowed = true; // false: --default-light off
    bool lightMatters = true;        // false: the normals integrator, which sees no light
};

struct LightingDecision {
    bool useStudio = false;
    SceneLightingMeasure measure;
};

// The studio lights a scene when the request allows it, no environment was given, and the scene
// has no punctual light and emitters below kNegligibleEmitterFraction of the studio's power.
// The measure is taken in every case (for --verbose).
LightingDecision decideSceneLighting(const Scene& scene, const LightingRequest& request);

// decideSceneLighting, and when it says so, the studio set as the scene's environment: what
// vkpt and vkpt-ref do to every scene they load (app/scene_setup.cpp).
LightingDecision applyDefaultLighting(Scene& scene, const LightingRequest& request);

// "no light of its own (emitters 3.1e-05 of the studio's power)" — for the log line.
std::string describeLightingReason(const SceneLightingMeasure& measure);

// "0 punctual lights, emitted power 0.0123, the studio's 45.6 (fraction 0.00027)" (--verbose).
std::string describeLightingMeasure(const SceneLightingMeasure& measure);

} // namespace vkpt
