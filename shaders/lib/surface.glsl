// surface.glsl — shared/surface.h in the kernels: a hit turned into what shading needs. Reads
// what lib/materials.glsl reads, and triangleNormals and triangleTangents.
#ifndef VKPT_SURFACE_GLSL
#define VKPT_SURFACE_GLSL

#include "lib/materials.glsl"
#include "shared/surface.h"

#endif // VKPT_SURFACE_GLSL
