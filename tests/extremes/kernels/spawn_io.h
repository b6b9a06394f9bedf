// spawn_io.h — the records of spawn_rays.comp, declared once for the C++ test and the kernel
// (vec4s only, so std430 and C++ agree).
#ifndef VKPT_SPAWN_IO_H
#define VKPT_SPAWN_IO_H

#include "shared/host_device.h"

#ifdef __cplusplus
namespace vkpt::gpu::test {
#endif

// A ray leaving a triangle: the point at the barycentrics, moved off the surface towards side
// (+1: the front, −1: the back) by offsetFromSurface, in the direction given.
struct SpawnInput {
    vec4 v0;
    vec4 v1;
    vec4 v2;
    vec4 barycentrics; // .xyz: weights of v0, v1, v2; .w: the side, +1 or −1
    vec4 direction;
};

struct SpawnOutput {
    vec4 origin; // the spawned ray's origin; .w: 1 when the ray hits its own triangle again
};

#ifdef __cplusplus
static_assert(sizeof(SpawnInput) == 80 && sizeof(SpawnOutput) == 16);
} // namespace vkpt::gpu::test
#endif

#endif // VKPT_SPAWN_IO_H
