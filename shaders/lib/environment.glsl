// environment.glsl — what rays that leave the scene see (shared/environment.h on the frame's
// EnvironmentParams), for the kernels that follow such rays: shade_hits (misses, light
// samples) and trace_shadow (probes). Needs frame, environmentTexels and environmentCdf
// declared.
#ifndef VKPT_ENVIRONMENT_GLSL
#define VKPT_ENVIRONMENT_GLSL

#include "lib/features.glsl"
#include "shared/environment.h"

bool hasEnvironment() {
    return featureEnvironment && frame.environment.emitterIndex != NO_EMITTER;
}

// The scene's environment; without a map in the features, width 0 lets the compiler fold the
// map's code away (environment.h tests width == 0 first).
EnvironmentParams sceneEnvironment() {
    EnvironmentParams env = frame.environment;
    if (!featureEnvironmentMap) env.width = 0u;
    return env;
}

// The environment's radiance along a unit direction (0 without one).
vec3 environmentRadianceAlong(vec3 direction) {
    if (!hasEnvironment()) return vec3(0.0);
    return environmentRadiance(sceneEnvironment(), direction);
}

#endif // VKPT_ENVIRONMENT_GLSL
