// scene_environment.h — what rays that leave the scene see, for both executors:
// environment.h's radiance and pdf on the scene's EnvironmentParams, or nothing without an
// environment, and the pdf with which light sampling chooses it. Reaches the scene through
// scene_view.h; a kernel that follows rays out of the scene (shade_hits, trace_shadow)
// includes it without the rest of the light code.
#ifndef VKPT_SCENE_ENVIRONMENT_H
#define VKPT_SCENE_ENVIRONMENT_H

#include "environment.h"
#include "host_device.h"
#include "scene_view.h"

#ifdef __cplusplus
namespace vkpt::gpu {
#endif

// Whether rays that leave the scene see an environment.
VKPT_FN bool hasEnvironment(VKPT_SCENE_PARAM_ONLY) {
    return sceneHasEnvironment(VKPT_SCENE_ARG_ONLY) &&
           sceneEnvironment(VKPT_SCENE_ARG_ONLY).emitterIndex != NO_EMITTER;
}

// The environment's radiance along a unit direction (0 without one).
VKPT_FN vec3 environmentRadianceAlong(vec3 direction VKPT_SCENE_PARAM) {
    if (!hasEnvironment(VKPT_SCENE_ARG_ONLY)) return vec3(0.0f);
    return environmentRadiance(sceneEnvironment(VKPT_SCENE_ARG_ONLY), direction VKPT_SCENE_ARG);
}

// Solid-angle pdf with which light sampling chooses the environment along a unit direction.
VKPT_FN float environmentLightPdf(vec3 direction VKPT_SCENE_PARAM) {
    if (!hasEnvironment(VKPT_SCENE_ARG_ONLY)) return 0.0f;
    EnvironmentParams env = sceneEnvironment(VKPT_SCENE_ARG_ONLY);
    return sceneEmitter(env.emitterIndex VKPT_SCENE_ARG).selectProbability *
           environmentPdf(env, direction VKPT_SCENE_ARG);
}

#ifdef __cplusplus
} // namespace vkpt::gpu
#endif

#endif // VKPT_SCENE_ENVIRONMENT_H
