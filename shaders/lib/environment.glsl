// environment.glsl — shared/scene_environment.h in the kernels that follow rays out of the
// scene: shade_hits (misses, light samples) and trace_shadow (probes). Reads frame,
// environmentTexels and environmentCdf (its kernels' SCENE entries).
#ifndef VKPT_ENVIRONMENT_GLSL
#define VKPT_ENVIRONMENT_GLSL

#include "lib/scene_view.glsl"

#include "shared/scene_environment.h"

#endif // VKPT_ENVIRONMENT_GLSL
