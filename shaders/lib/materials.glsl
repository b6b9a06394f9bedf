// materials.glsl — shared/materials.h in the kernels: a material read at a point of a
// primitive, the alpha MASK test and the emission a hit sends back. Reads triangles,
// materials, textures, triangleUvs and textureTexels (its kernels' SCENE entries). A scene
// without textures has no triangleUvs: the shared code reads them only behind featureTextures.
#ifndef VKPT_MATERIALS_GLSL
#define VKPT_MATERIALS_GLSL

#include "lib/scene_view.glsl"

#include "shared/materials.h"

#endif // VKPT_MATERIALS_GLSL
