// materials.glsl — a material read at a point of a primitive, as host/reference/surface.cpp
// reads it: TEXCOORD_0 interpolated over the triangle (a sphere's from its normal), each
// texture at its KHR_texture_transform'd coordinate, the alpha MASK test and the emission a hit
// sends back along the ray. Needs frame, triangleUvs and textureTexels declared (and binds
// the triangles, materials and textures texel views of lib/records.glsl). Texture coordinates are computed only for a material that has a
// texture: the factors alone need none, and a scene without textures has no triangleUvs.
#ifndef VKPT_MATERIALS_GLSL
#define VKPT_MATERIALS_GLSL

#include "lib/features.glsl"
#include "lib/records.glsl"
#include "shared/intersect.h"
#include "shared/sphere.h"
#include "shared/texture_sampling.h"

bool hasTexture(TextureSlot slot) {
    return featureTextures && slot.texture != NO_TEXTURE;
}

bool hasAnyTexture(Material m) {
    return hasTexture(m.baseColorTexture) || hasTexture(m.metallicRoughnessTexture) ||
           hasTexture(m.emissiveTexture);
}

// TEXCOORD_0 at barycentrics (u, v) of triangle `index`, or at the outward normal of a sphere.
vec2 primitiveUv(uint index, Triangle primitive, float u, float v, vec3 sphereNormal) {
    if (featureSpheres && isSpherePrimitive(primitive)) return sphereUv(sphereNormal);
    vec2 t0 = triangleUvs[3u * index];
    vec2 t1 = triangleUvs[3u * index + 1u];
    vec2 t2 = triangleUvs[3u * index + 2u];
    return t0 * (1.0 - u - v) + t1 * u + t2 * v;
}

// The texel value at uv, or 1 (the factor alone applies) without a texture.
vec4 sampleSlot(TextureSlot slot, vec2 uv, bool srgb) {
    if (!hasTexture(slot)) return vec4(1.0);
    return sampleTexture(fetchTextureInfo(slot.texture), transformUv(slot, uv), srgb);
}

// Alpha MASK: whether a ray crossing primitive `index` at (u, v) (a sphere: its outward normal
// there) passes through, alpha = baseColor.a × baseColorTexture.a below the cutoff.
bool alphaMasked(uint index, Triangle primitive, float u, float v, vec3 sphereNormal) {
    Material m = fetchMaterial(primitive.materialIndex);
    if (m.alphaMode != ALPHA_MODE_MASK) return false;
    float alpha = m.baseColor.a;
    if (hasTexture(m.baseColorTexture)) {
        vec2 uv = primitiveUv(index, primitive, u, v, sphereNormal);
        alpha *= sampleSlot(m.baseColorTexture, uv, true).a;
    }
    return alpha < m.alphaCutoff;
}

// Emission leaves the front face only, unless the material is double-sided.
bool emitsOnThisSide(Material m, bool frontFace) {
    return frontFace || (featureDoubleSided && (m.flags & MATERIAL_DOUBLE_SIDED) != 0u);
}

// The emissive factor times the emissive texture at uv (before the side test).
vec3 emissionAt(Material m, vec2 uv) {
    if (!hasTexture(m.emissiveTexture)) return m.emission;
    return m.emission * sampleSlot(m.emissiveTexture, uv, true).rgb;
}

// What the hit of a ray from `origin` along `direction` emits back along it (a probe's find):
// makeSurfacePoint's side test and emission, without the shading normals.
vec3 emissionTowards(HitRecord hit, vec3 origin, vec3 direction) {
    Triangle primitive = fetchTriangle(hit.triangle);
    Material m = fetchMaterial(primitive.materialIndex);
    bool frontFace;
    vec3 sphereNormal = vec3(0.0);
    if (featureSpheres && isSpherePrimitive(primitive)) {
        sphereNormal = sphereNormalAt(origin + hit.t * direction, primitive.v0);
        frontFace = dot(sphereNormal, direction) < 0.0;
    } else {
        vec3 face = unitFaceNormal(primitive.v0, primitive.v1, primitive.v2);
        frontFace = dot(face, direction) < 0.0;
    }
    if (!emitsOnThisSide(m, frontFace)) return vec3(0.0);
    if (!hasTexture(m.emissiveTexture)) return m.emission;
    return emissionAt(m, primitiveUv(hit.triangle, primitive, hit.u, hit.v, sphereNormal));
}

#endif // VKPT_MATERIALS_GLSL
