// surface.glsl — shared/surface.h in the kernels: a hit turned into what shading needs. Needs
// what lib/materials.glsl needs (and binds triangleNormals).
#ifndef VKPT_SURFACE_GLSL
#define VKPT_SURFACE_GLSL

#include "lib/materials.glsl"
#include "shared/surface.h"

#endif // VKPT_SURFACE_GLSL
