// environment.glsl — shared/scene_environment.h in the kernels that follow rays out of the
// scene: shade_hits (misses, light samples) and trace_shadow (probes). Needs frame,
// environmentTexels and environmentCdf declared.
#ifndef VKPT_ENVIRONMENT_GLSL
#define VKPT_ENVIRONMENT_GLSL

#include "lib/scene_view.glsl"

vec4 sceneEnvironmentTexel(uint i) {
    return environmentTexelsAt(i);
}

float sceneEnvironmentCdf(uint i) {
    return environmentCdfAt(i);
}

#include "shared/scene_environment.h"

#endif // VKPT_ENVIRONMENT_GLSL
