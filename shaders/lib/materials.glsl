// materials.glsl — shared/materials.h in the kernels: a material read at a point of a
// primitive, the alpha MASK test and the emission a hit sends back. Needs frame, triangleUvs
// and textureTexels declared (and binds the triangles, materials and textures texel views of
// lib/records.glsl). A scene without textures has no triangleUvs: the shared code reads them
// only behind featureTextures.
#ifndef VKPT_MATERIALS_GLSL
#define VKPT_MATERIALS_GLSL

#include "lib/scene_view.glsl"

vec2 sceneUv(uint k) {
    return triangleUvsAt(k);
}

uint sceneTextureTexel(uint i) {
    return textureTexelsAt(i);
}

#include "shared/materials.h"

#endif // VKPT_MATERIALS_GLSL
