// materials.h — a material read at a point of a primitive, for both executors: TEXCOORD_0
// interpolated over the triangle (a sphere's from its normal), each texture at its
// KHR_texture_transform'd coordinate, the alpha MASK test at a crossing and the emission a hit
// sends back along the ray. Reaches the scene through scene_view.h. Texture coordinates are
// computed only for a material that has a texture: the factors alone need none, and a scene
// without textures has no uvs.
#ifndef VKPT_MATERIALS_H
#define VKPT_MATERIALS_H

#include "host_device.h"
#include "intersect.h"
#include "scene_view.h"
#include "sphere.h"
#include "texture_sampling.h"

#ifdef __cplusplus
namespace vkpt::gpu {
#endif

VKPT_FN bool hasTexture(TextureSlot slot VKPT_SCENE_PARAM) {
    return sceneHasTextures(VKPT_SCENE_ARG_ONLY) && slot.texture != NO_TEXTURE;
}

// The layers' textures count only in scenes with the layer (FEATURE_CLEARCOAT, FEATURE_SHEEN).
VKPT_FN bool hasLayerTexture(Material m VKPT_SCENE_PARAM) {
    bool clearcoat = sceneHasClearcoat(VKPT_SCENE_ARG_ONLY) &&
                     (hasTexture(m.clearcoatTexture VKPT_SCENE_ARG) ||
                      hasTexture(m.clearcoatRoughnessTexture VKPT_SCENE_ARG));
    bool sheen =
        sceneHasSheen(VKPT_SCENE_ARG_ONLY) && (hasTexture(m.sheenColorTexture VKPT_SCENE_ARG) ||
                                               hasTexture(m.sheenRoughnessTexture VKPT_SCENE_ARG));
    return clearcoat || sheen;
}

// Whether the scene has the specularLobes array: some GGX material with a specular texture,
// anisotropy or iridescence.
VKPT_FN bool sceneHasSpecularLobes(VKPT_SCENE_PARAM_ONLY) {
    return sceneHasSpecularTextures(VKPT_SCENE_ARG_ONLY) ||
           sceneHasAnisotropy(VKPT_SCENE_ARG_ONLY) || sceneHasIridescence(VKPT_SCENE_ARG_ONLY);
}

// The record of a material without those extensions: no texture, no anisotropy, no film.
VKPT_FN SpecularLobeParams noSpecularLobes() {
    TextureSlot none;
    none.transformRow0 = vec3(1.0f, 0.0f, 0.0f);
    none.texture = NO_TEXTURE;
    none.transformRow1 = vec3(0.0f, 1.0f, 0.0f);
    none.unused0 = 0u;
    SpecularLobeParams x;
    x.specularTexture = none;
    x.specularColorTexture = none;
    x.anisotropyStrength = 0.0f;
    x.anisotropyRotationCos = 1.0f;
    x.anisotropyRotationSin = 0.0f;
    x.anisotropyUnused = 0u;
    x.anisotropyTexture = none;
    x.iridescence = 0.0f;
    x.iridescenceIor = 1.3f;
    x.iridescenceThicknessMinimum = 100.0f;
    x.iridescenceThicknessMaximum = 400.0f;
    x.iridescenceTexture = none;
    x.iridescenceThicknessTexture = none;
    return x;
}

// Material `material`'s specular lobe extensions; none in a scene without them (whose array is
// empty, and whose kernels fold this to constants) or for a material without them (its flag).
VKPT_FN SpecularLobeParams specularLobesOf(uint material VKPT_SCENE_PARAM) {
    if (!sceneHasSpecularLobes(VKPT_SCENE_ARG_ONLY) ||
        (sceneMaterialFlags(material VKPT_SCENE_ARG) & MATERIAL_SPECULAR_LOBES) == 0u)
        return noSpecularLobes();
    return sceneSpecularLobes(material VKPT_SCENE_ARG);
}

// The specular textures count only in scenes with them (FEATURE_SPECULAR_TEXTURES), the
// anisotropy texture only with anisotropy (FEATURE_ANISOTROPY), the film's only with
// iridescence (FEATURE_IRIDESCENCE).
VKPT_FN bool hasSpecularLobeTexture(SpecularLobeParams x VKPT_SCENE_PARAM) {
    bool specular = sceneHasSpecularTextures(VKPT_SCENE_ARG_ONLY) &&
                    (hasTexture(x.specularTexture VKPT_SCENE_ARG) ||
                     hasTexture(x.specularColorTexture VKPT_SCENE_ARG));
    bool anisotropy =
        sceneHasAnisotropy(VKPT_SCENE_ARG_ONLY) && hasTexture(x.anisotropyTexture VKPT_SCENE_ARG);
    bool iridescence = sceneHasIridescence(VKPT_SCENE_ARG_ONLY) &&
                       (hasTexture(x.iridescenceTexture VKPT_SCENE_ARG) ||
                        hasTexture(x.iridescenceThicknessTexture VKPT_SCENE_ARG));
    return specular || anisotropy || iridescence;
}

VKPT_FN bool hasAnyTexture(Material m VKPT_SCENE_PARAM) {
    return hasTexture(m.baseColorTexture VKPT_SCENE_ARG) ||
           hasTexture(m.metallicRoughnessTexture VKPT_SCENE_ARG) ||
           hasTexture(m.emissiveTexture VKPT_SCENE_ARG) ||
           (sceneHasNormalMaps(VKPT_SCENE_ARG_ONLY) &&
            hasTexture(m.normalTexture VKPT_SCENE_ARG)) ||
           (sceneHasTransmission(VKPT_SCENE_ARG_ONLY) &&
            hasTexture(m.transmissionTexture VKPT_SCENE_ARG)) ||
           hasLayerTexture(m VKPT_SCENE_ARG);
}

// TEXCOORD_0 at barycentrics (u, v) of primitive `index`, or at the outward normal of a sphere.
VKPT_FN vec2 primitiveUv(uint index, Triangle primitive, float u, float v,
                         vec3 sphereNormal VKPT_SCENE_PARAM) {
    if (sceneHasSpheres(VKPT_SCENE_ARG_ONLY) && isSpherePrimitive(primitive))
        return sphereUv(sphereNormal);
    vec2 t0 = sceneUv(3u * index VKPT_SCENE_ARG);
    vec2 t1 = sceneUv(3u * index + 1u VKPT_SCENE_ARG);
    vec2 t2 = sceneUv(3u * index + 2u VKPT_SCENE_ARG);
    return t0 * (1.0f - u - v) + t1 * u + t2 * v;
}

// The texel value at uv, or 1 (the factor alone applies) without a texture.
VKPT_FN vec4 sampleSlot(TextureSlot slot, vec2 uv, bool srgb VKPT_SCENE_PARAM) {
    if (!hasTexture(slot VKPT_SCENE_ARG)) return vec4(1.0f);
    return sampleTexture(sceneTexture(slot.texture VKPT_SCENE_ARG), transformUv(slot, uv),
                         srgb VKPT_SCENE_ARG);
}

// A primitive's material as `instance` places it: the instance's where it carries one (geometry
// that meshes of other materials share, docs/scene-model.md), else the primitive's own.
// NO_INSTANCE: the primitive's own.
VKPT_FN uint placedMaterialIndex(uint instance, Triangle primitive VKPT_SCENE_PARAM) {
#if VKPT_INSTANCES
    if (sceneHasInstances(VKPT_SCENE_ARG_ONLY) && instance != NO_INSTANCE) {
        uint material = sceneInstance(instance VKPT_SCENE_ARG).material;
        if (material != INSTANCE_OWN_MATERIALS) return material;
    }
#endif
    return primitive.materialIndex;
}

// Alpha MASK: whether a ray crossing primitive `index` of material `material` at (u, v) (a
// sphere: its outward normal there) passes through, alpha = baseColor.a × baseColorTexture.a
// below the cutoff.
VKPT_FN bool alphaMasked(uint index, Triangle primitive, uint material, float u, float v,
                         vec3 sphereNormal VKPT_SCENE_PARAM) {
    Material m = sceneMaterial(material VKPT_SCENE_ARG);
    if (m.alphaMode != ALPHA_MODE_MASK) return false;
    float alpha = m.baseColor.w;
    if (hasTexture(m.baseColorTexture VKPT_SCENE_ARG)) {
        vec2 uv = primitiveUv(index, primitive, u, v, sphereNormal VKPT_SCENE_ARG);
        alpha *= sampleSlot(m.baseColorTexture, uv, true VKPT_SCENE_ARG).w;
    }
    return alpha < m.alphaCutoff;
}

// Whether crossing `h` of primitive `index` (placed by `instance`, NO_INSTANCE in the world's
// own geometry) by the ray from `origin` along `direction` lies in an alpha-masked material's
// cut-out: the question every BVH walk asks of such a crossing.
VKPT_FN bool isCutOut(uint index, uint instance, TriangleHit h, vec3 origin,
                      vec3 direction VKPT_SCENE_PARAM) {
    Triangle primitive = scenePrimitive(index VKPT_SCENE_ARG);
    bool sphere = sceneHasSpheres(VKPT_SCENE_ARG_ONLY) && isSpherePrimitive(primitive);
    vec3 sphereNormal =
        sphere ? sphereNormalAt(origin + h.t * direction, primitive.v0) : vec3(0.0f);
    return alphaMasked(index, primitive, placedMaterialIndex(instance, primitive VKPT_SCENE_ARG),
                       h.u, h.v, sphereNormal VKPT_SCENE_ARG);
}

// Emission leaves the front face only, unless the material is double-sided.
VKPT_FN bool emitsOnThisSide(Material m, bool frontFace VKPT_SCENE_PARAM) {
    return frontFace ||
           (sceneHasDoubleSided(VKPT_SCENE_ARG_ONLY) && (m.flags & MATERIAL_DOUBLE_SIDED) != 0u);
}

// The emissive factor times the emissive texture at uv (before the side test).
VKPT_FN vec3 emissionAt(Material m, vec2 uv VKPT_SCENE_PARAM) {
    if (!hasTexture(m.emissiveTexture VKPT_SCENE_ARG)) return m.emission;
    return m.emission * vec3(sampleSlot(m.emissiveTexture, uv, true VKPT_SCENE_ARG));
}

// What hit `h` of primitive `index` by a ray from `origin` along `direction` emits back along
// it (a probe's find): the side test and emission of makeSurfacePoint, without the normals.
VKPT_FN vec3 emissionTowards(uint index, TriangleHit h, vec3 origin,
                             vec3 direction VKPT_SCENE_PARAM) {
    Triangle primitive = scenePrimitive(index VKPT_SCENE_ARG);
    Material m = sceneMaterial(primitive.materialIndex VKPT_SCENE_ARG);
    bool frontFace;
    vec3 sphereNormal = vec3(0.0f);
    if (sceneHasSpheres(VKPT_SCENE_ARG_ONLY) && isSpherePrimitive(primitive)) {
        sphereNormal = sphereNormalAt(origin + h.t * direction, primitive.v0);
        frontFace = dot(sphereNormal, direction) < 0.0f;
    } else {
        vec3 face = unitFaceNormal(primitive.v0, primitive.v1, primitive.v2);
        frontFace = dot(face, direction) < 0.0f;
    }
    if (!emitsOnThisSide(m, frontFace VKPT_SCENE_ARG)) return vec3(0.0f);
    if (!hasTexture(m.emissiveTexture VKPT_SCENE_ARG)) return m.emission;
    return emissionAt(m, primitiveUv(index, primitive, h.u, h.v, sphereNormal VKPT_SCENE_ARG)
                             VKPT_SCENE_ARG);
}

#ifdef __cplusplus
} // namespace vkpt::gpu
#endif

#endif // VKPT_MATERIALS_H
