// surface.h — a hit turned into what shading needs, for both executors: the point (from
// barycentrics on a triangle, put back on a sphere along its normal), the geometric and shading
// normals turned towards the incoming ray, the material with its textures applied, the
// emission, and the BSDF at the point for a world direction. Reaches the scene through
// scene_view.h.
#ifndef VKPT_SURFACE_H
#define VKPT_SURFACE_H

#include "bsdf.h"
#include "host_device.h"
#include "instance.h"
#include "intersect.h"
#include "materials.h"
#include "normal_mapping.h"
#include "ray_offset.h"
#include "sampling.h"
#include "scene_view.h"
#include "sphere.h"

#ifdef __cplusplus
namespace vkpt::gpu {
#endif

struct SurfacePoint {
    vec3 position;
    vec3 geometricNormal;    // unit, on the side the ray came from
    vec3 shadingNormal;      // unit, interpolated (normal-mapped and bent), on the same side
    vec3 rawShadingNormal;   // as stored (a sphere's outward normal), for the normals integrator
    bool frontFace;          // triangle: the counter-clockwise side; sphere: outside
    bool doubleSided;        // the material emits from both sides
    float coordinateScale;   // of the primitive, for offsetFromSurface
    uint triangle;           // the primitive, BVH-ordered
    uint instance;           // the instance whose mesh holds it; NO_INSTANCE in one-level scenes
    ShadingMaterial shading; // the BSDF's parameters, textures applied
    vec3 emission;           // emissive factor × texture, before the side test
    vec3 outgoing;           // unit, back along the incoming ray
};

// Whether the point lies in an instance's mesh, whose data is in the mesh's own space.
VKPT_FN bool isInstanced(SurfacePoint s VKPT_SCENE_PARAM) {
    return VKPT_INSTANCES != 0 && sceneHasInstances(VKPT_SCENE_ARG_ONLY) &&
           s.instance != NO_INSTANCE;
}

VKPT_FN void fillTriangle(VKPT_INOUT(SurfacePoint) s, Triangle tri, TriangleHit hit,
                          vec3 direction VKPT_SCENE_PARAM) {
    TriangleNormals normals = sceneNormals(s.triangle VKPT_SCENE_ARG);
    bool mirrored = false;
#if VKPT_INSTANCES
    if (isInstanced(s VKPT_SCENE_ARG)) {
        // The corners and their normals in world space, then on as for a flattened triangle
        // (which the loader transformed the same way, in double).
        Instance x = sceneInstance(s.instance VKPT_SCENE_ARG);
        tri.v0 = instancePointToWorld(x, tri.v0);
        tri.v1 = instancePointToWorld(x, tri.v1);
        tri.v2 = instancePointToWorld(x, tri.v2);
        normals.n0 = vec4(instanceNormalToWorld(x, vec3(normals.n0)), 0.0f);
        normals.n1 = vec4(instanceNormalToWorld(x, vec3(normals.n1)), 0.0f);
        normals.n2 = vec4(instanceNormalToWorld(x, vec3(normals.n2)), 0.0f);
        mirrored = (x.flags & INSTANCE_MIRRORED) != 0u;
    }
#endif
    // Barycentric interpolation keeps the point on the triangle's plane, unlike o + t·d.
    s.position = tri.v0 * (1.0f - hit.u - hit.v) + tri.v1 * hit.u + tri.v2 * hit.v;
    s.coordinateScale = triangleCoordinateScale(tri.v0, tri.v1, tri.v2);
    // A mirroring placement turns the corners' winding over (the loader swaps two corners of a
    // flattened one instead), so the front face is the other side of the placed corners.
    vec3 face = unitFaceNormal(tri.v0, tri.v1, tri.v2);
    if (mirrored) face = -face;
    s.frontFace = dot(face, direction) < 0.0f;
    s.geometricNormal = s.frontFace ? face : -face;
    s.rawShadingNormal = vec3(normals.n0) * (1.0f - hit.u - hit.v) + vec3(normals.n1) * hit.u +
                         vec3(normals.n2) * hit.v;
    float rawLength = length(s.rawShadingNormal);
    vec3 shading = rawLength > 0.0f ? s.rawShadingNormal / rawLength : s.geometricNormal;
    s.shadingNormal = dot(shading, s.geometricNormal) < 0.0f ? -shading : shading;
}

// The point is put back on the sphere along its normal, so that its distance from the surface
// is the radius' rounding, not o + t·d's.
VKPT_FN void fillSphere(VKPT_INOUT(SurfacePoint) s, Triangle sphere, TriangleHit hit, vec3 origin,
                        vec3 direction) {
    vec3 outward = sphereNormalAt(origin + hit.t * direction, sphere.v0);
    s.position = sphere.v0 + sphere.v1.x * outward;
    s.coordinateScale = sphereCoordinateScale(sphere.v0, sphere.v1.x);
    s.frontFace = dot(outward, direction) < 0.0f;
    s.geometricNormal = s.frontFace ? outward : -outward;
    s.rawShadingNormal = outward;
    s.shadingNormal = s.geometricNormal;
}

// The tangent frame at the hit (normal_mapping.h, interpolatedTangent), in world space.
VKPT_FN vec4 surfaceTangent(SurfacePoint s, TriangleHit hit VKPT_SCENE_PARAM) {
#if VKPT_INSTANCES
    if (!isInstanced(s VKPT_SCENE_ARG))
        return interpolatedTangent(s.triangle, hit.u, hit.v VKPT_SCENE_ARG);
    Instance x = sceneInstance(s.instance VKPT_SCENE_ARG);
    TriangleTangents t = sceneTangents(s.triangle VKPT_SCENE_ARG);
    return instanceTangentToWorld(x, t.t0) * (1.0f - hit.u - hit.v) +
           instanceTangentToWorld(x, t.t1) * hit.u + instanceTangentToWorld(x, t.t2) * hit.v;
#else
    return interpolatedTangent(s.triangle, hit.u, hit.v VKPT_SCENE_ARG);
#endif
}

// The normal texture's shading normal: mapped in the interpolated normal's tangent frame, turned
// to the side the shading normal was turned to, and bent towards s.outgoing (normal_mapping.h).
VKPT_FN vec3 normalMappedShadingNormal(SurfacePoint s, Material m, TriangleHit hit,
                                       vec2 uv VKPT_SCENE_PARAM) {
    vec3 n = normalize(s.rawShadingNormal);
    vec4 tangent = surfaceTangent(s, hit VKPT_SCENE_ARG);
    vec3 mapped = mappedNormal(m.normalTexture, m.normalScale, uv, n, tangent VKPT_SCENE_ARG);
    if (dot(n, s.shadingNormal) < 0.0f) mapped = -mapped;
    return bendTowardsViewer(mapped, s.geometricNormal, s.outgoing);
}

// KHR_materials_transmission, _ior and _volume at the point: the glass share (factor × texture
// R), F0 from the ior, and the ratio of indices a refraction crosses: ior entering a volume
// through its front face, 1/ior leaving through its back face (outside every volume is ior 1:
// docs/integrator.md, the nesting limitation); a thin wall's Fresnel term takes the ior.
VKPT_FN void applyDielectricExtensions(VKPT_INOUT(ShadingMaterial) shading, Material m,
                                       bool frontFace, vec2 uv VKPT_SCENE_PARAM) {
    shading.transmission =
        m.transmission * sampleSlot(m.transmissionTexture, uv, false VKPT_SCENE_ARG).x;
    shading.iorF0 = m.iorF0;
    shading.thinWalled = !(m.thickness > 0.0f);
    shading.eta = (shading.thinWalled || frontFace) ? m.ior : 1.0f / m.ior;
}

// KHR_materials_clearcoat and KHR_materials_sheen over the base, each factor times its
// texture, read only in scenes that have the layer (FEATURE_CLEARCOAT, FEATURE_SHEEN) and only
// for a material that has it.
VKPT_FN ShadingMaterial withMaterialLayers(ShadingMaterial shading, Material m,
                                           vec2 uv VKPT_SCENE_PARAM) {
    if (sceneHasClearcoat(VKPT_SCENE_ARG_ONLY) && m.clearcoat > 0.0f) {
        float factor = m.clearcoat * sampleSlot(m.clearcoatTexture, uv, false VKPT_SCENE_ARG).x;
        float roughness = m.clearcoatRoughness *
                          sampleSlot(m.clearcoatRoughnessTexture, uv, false VKPT_SCENE_ARG).y;
        shading = withClearcoat(shading, factor, roughness);
    }
    if (sceneHasSheen(VKPT_SCENE_ARG_ONLY) && maxComponent(m.sheenColor) > 0.0f) {
        vec3 color = m.sheenColor * vec3(sampleSlot(m.sheenColorTexture, uv, true VKPT_SCENE_ARG));
        float roughness =
            m.sheenRoughness * sampleSlot(m.sheenRoughnessTexture, uv, false VKPT_SCENE_ARG).w;
        shading = withSheen(shading, color, roughness);
    }
    return shading;
}

// The clearcoat's normal (KHR_materials_clearcoat): its own normal texture's, mapped and bent
// like the base's; without one, the unmapped normal `interpolated`, even where the base is
// normal-mapped (the extension's rule). Returned in the frame of s.shadingNormal, where bsdf.h
// works.
VKPT_FN vec3 clearcoatLocalNormal(SurfacePoint s, Material m, TriangleHit hit, vec2 uv,
                                  vec3 interpolated VKPT_SCENE_PARAM) {
    vec3 normal = interpolated;
    if (hasTexture(m.clearcoatNormalTexture VKPT_SCENE_ARG)) {
        vec3 n = normalize(s.rawShadingNormal);
        vec4 tangent = surfaceTangent(s, hit VKPT_SCENE_ARG);
        normal = mappedNormal(m.clearcoatNormalTexture, m.clearcoatNormalScale, uv, n,
                              tangent VKPT_SCENE_ARG);
        if (dot(n, interpolated) < 0.0f) normal = -normal;
        normal = bendTowardsViewer(normal, s.geometricNormal, s.outgoing);
    }
    return normalize(worldToBasis(makeBasis(s.shadingNormal), normal));
}

// KHR_materials_specular's strength (A of specularTexture) and colour (RGB of the sRGB
// specularColorTexture), each factor times its texture, read only in scenes that have them.
VKPT_FN void applySpecularTextures(VKPT_INOUT(ShadingMaterial) shading, SpecularLobeParams x,
                                   vec2 uv VKPT_SCENE_PARAM) {
    shading.specular *= sampleSlot(x.specularTexture, uv, false VKPT_SCENE_ARG).w;
    shading.specularColor *= vec3(sampleSlot(x.specularColorTexture, uv, true VKPT_SCENE_ARG));
}

// KHR_materials_anisotropy at the point: the direction (1, 0), or anisotropyTexture.rg·2 − 1,
// turned counter-clockwise by anisotropyRotation in the tangent frame of the mesh's TANGENT
// (bitangent w·cross(n, t)), the strength times anisotropyTexture.b (the extension's formulas);
// then projected into the shading normal's plane and expressed in the frame of
// makeBasis(shadingNormal), where bsdf.h works. A primitive without a tangent frame (a sphere)
// or a direction along the normal stays isotropic.
VKPT_FN ShadingMaterial withSurfaceAnisotropy(ShadingMaterial shading, SurfacePoint s,
                                              SpecularLobeParams lobes, TriangleHit hit,
                                              vec2 uv VKPT_SCENE_PARAM) {
    vec4 tangent = surfaceTangent(s, hit VKPT_SCENE_ARG);
    if (tangent.w == 0.0f) return shading;
    float strength = lobes.anisotropyStrength;
    vec2 d = vec2(1.0f, 0.0f);
    if (hasTexture(lobes.anisotropyTexture VKPT_SCENE_ARG)) {
        vec4 texel = sampleSlot(lobes.anisotropyTexture, uv, false VKPT_SCENE_ARG);
        d = vec2(texel.x, texel.y) * 2.0f - vec2(1.0f);
        strength *= texel.z;
    }
    float c = lobes.anisotropyRotationCos;
    float sn = lobes.anisotropyRotationSin;
    vec2 turned = vec2(c * d.x - sn * d.y, sn * d.x + c * d.y);
    vec3 n = normalize(s.rawShadingNormal);
    vec3 t = vec3(tangent) - dot(vec3(tangent), n) * n;
    float handedness = tangent.w < 0.0f ? -1.0f : 1.0f;
    vec3 direction = turned.x * t + turned.y * (handedness * cross(n, t));
    Basis basis = makeBasis(s.shadingNormal);
    vec2 local = vec2(dot(direction, basis.tangent), dot(direction, basis.bitangent));
    float length2 = dot(local, local);
    if (!(length2 > 0.0f) || !(strength > 0.0f)) return shading;
    return withAnisotropy(shading, strength, local / sqrt(length2));
}

// KHR_materials_iridescence at the point: the factor times iridescenceTexture.r, the thickness
// mix(minimum, maximum, iridescenceThicknessTexture.g), or the maximum without the texture.
VKPT_FN ShadingMaterial withSurfaceIridescence(ShadingMaterial shading, SpecularLobeParams lobes,
                                               vec2 uv VKPT_SCENE_PARAM) {
    float factor =
        lobes.iridescence * sampleSlot(lobes.iridescenceTexture, uv, false VKPT_SCENE_ARG).x;
    float thickness = lobes.iridescenceThicknessMaximum;
    if (hasTexture(lobes.iridescenceThicknessTexture VKPT_SCENE_ARG))
        thickness = mix(lobes.iridescenceThicknessMinimum, lobes.iridescenceThicknessMaximum,
                        sampleSlot(lobes.iridescenceThicknessTexture, uv, false VKPT_SCENE_ARG).y);
    return withIridescence(shading, factor, lobes.iridescenceIor, thickness);
}

// Whether the material's diffuse transmission reads a texture (and so needs TEXCOORD_0).
VKPT_FN bool hasLobeTexture(uint material VKPT_SCENE_PARAM) {
    if (!sceneHasDiffuseTransmission(VKPT_SCENE_ARG_ONLY) ||
        (sceneMaterialFlags(material VKPT_SCENE_ARG) & MATERIAL_LOBES) == 0u)
        return false;
    MaterialLobes lobes = sceneMaterialLobes(material VKPT_SCENE_ARG);
    return lobes.diffuseTransmission > 0.0f &&
           (hasTexture(lobes.diffuseTransmissionTexture VKPT_SCENE_ARG) ||
            hasTexture(lobes.diffuseTransmissionColorTexture VKPT_SCENE_ARG));
}

// KHR_materials_diffuse_transmission and KHR_materials_dispersion at the point, from the
// material's record of materialLobes (read only in scenes with either): the transmitted share,
// factor × diffuseTransmissionTexture.a, its colour, factor × diffuseTransmissionColorTexture.rgb
// (sRGB), and the glass's dispersion.
VKPT_FN ShadingMaterial withMaterialLobes(ShadingMaterial shading, uint material,
                                          vec2 uv VKPT_SCENE_PARAM) {
    MaterialLobes lobes = sceneMaterialLobes(material VKPT_SCENE_ARG);
    if (sceneHasDiffuseTransmission(VKPT_SCENE_ARG_ONLY) && lobes.diffuseTransmission > 0.0f) {
        float factor = lobes.diffuseTransmission *
                       sampleSlot(lobes.diffuseTransmissionTexture, uv, false VKPT_SCENE_ARG).w;
        vec3 color =
            lobes.diffuseTransmissionColor *
            vec3(sampleSlot(lobes.diffuseTransmissionColorTexture, uv, true VKPT_SCENE_ARG));
        shading = withDiffuseTransmission(shading, factor, color);
    }
    if (sceneHasDispersion(VKPT_SCENE_ARG_ONLY)) shading.dispersion = lobes.dispersion;
    return shading;
}

// The material at the point: factors times textures (each read only when present). Needs
// s.outgoing for the normal texture's bend.
VKPT_FN void fillMaterial(VKPT_INOUT(SurfacePoint) s, Triangle primitive,
                          TriangleHit hit VKPT_SCENE_PARAM) {
    uint materialIndex = placedMaterialIndex(s.instance, primitive VKPT_SCENE_ARG);
    Material m = sceneMaterial(materialIndex VKPT_SCENE_ARG);
    SpecularLobeParams lobes = specularLobesOf(materialIndex VKPT_SCENE_ARG);
    vec4 baseColor = m.baseColor;
    float metallic = m.metallic;
    float roughness = m.roughness;
    s.emission = m.emission;
    vec2 uv = vec2(0.0f);
    if (hasAnyTexture(m VKPT_SCENE_ARG) || hasSpecularLobeTexture(lobes VKPT_SCENE_ARG) ||
        hasLobeTexture(materialIndex VKPT_SCENE_ARG)) {
        uv = primitiveUv(s.triangle, primitive, hit.u, hit.v, s.rawShadingNormal VKPT_SCENE_ARG);
        baseColor = m.baseColor * sampleSlot(m.baseColorTexture, uv, true VKPT_SCENE_ARG);
        vec4 metalRough = sampleSlot(m.metallicRoughnessTexture, uv, false VKPT_SCENE_ARG);
        metallic = m.metallic * metalRough.z;
        roughness = m.roughness * metalRough.y;
        s.emission = emissionAt(m, uv VKPT_SCENE_ARG);
    }
    vec3 interpolated = s.shadingNormal;
    bool normalMapped =
        sceneHasNormalMaps(VKPT_SCENE_ARG_ONLY) && length(s.rawShadingNormal) > 0.0f;
    if (normalMapped && hasTexture(m.normalTexture VKPT_SCENE_ARG)) {
        s.shadingNormal = normalMappedShadingNormal(s, m, hit, uv VKPT_SCENE_ARG);
    }
    bool metallicRoughness = sceneHasMetallicRoughness(VKPT_SCENE_ARG_ONLY) &&
                             (m.flags & MATERIAL_METALLIC_ROUGHNESS) != 0u;
    s.shading = makeShadingMaterial(vec3(baseColor), metallic, roughness, m.specular,
                                    m.specularColor, metallicRoughness);
    if (sceneHasSpecularTextures(VKPT_SCENE_ARG_ONLY) && metallicRoughness)
        applySpecularTextures(s.shading, lobes, uv VKPT_SCENE_ARG);
    if (sceneHasTransmission(VKPT_SCENE_ARG_ONLY))
        applyDielectricExtensions(s.shading, m, s.frontFace, uv VKPT_SCENE_ARG);
    if (metallicRoughness) s.shading = withMaterialLayers(s.shading, m, uv VKPT_SCENE_ARG);
    if (sceneHasIridescence(VKPT_SCENE_ARG_ONLY) && metallicRoughness && lobes.iridescence > 0.0f)
        s.shading = withSurfaceIridescence(s.shading, lobes, uv VKPT_SCENE_ARG);
    if ((sceneHasDiffuseTransmission(VKPT_SCENE_ARG_ONLY) ||
         sceneHasDispersion(VKPT_SCENE_ARG_ONLY)) &&
        metallicRoughness && (m.flags & MATERIAL_LOBES) != 0u)
        s.shading = withMaterialLobes(s.shading, materialIndex, uv VKPT_SCENE_ARG);
    if (sceneHasAnisotropy(VKPT_SCENE_ARG_ONLY) && metallicRoughness &&
        lobes.anisotropyStrength > 0.0f && length(s.rawShadingNormal) > 0.0f)
        s.shading = withSurfaceAnisotropy(s.shading, s, lobes, hit, uv VKPT_SCENE_ARG);
    if (normalMapped && hasClearcoat(s.shading) &&
        (hasTexture(m.normalTexture VKPT_SCENE_ARG) ||
         hasTexture(m.clearcoatNormalTexture VKPT_SCENE_ARG))) {
        s.shading.clearcoatNormal =
            clearcoatLocalNormal(s, m, hit, uv, interpolated VKPT_SCENE_ARG);
    }
    s.doubleSided =
        sceneHasDoubleSided(VKPT_SCENE_ARG_ONLY) && (m.flags & MATERIAL_DOUBLE_SIDED) != 0u;
}

// Hit `hit` of primitive `index` (of `instance`'s mesh in a two-level scene, else NO_INSTANCE)
// by a world-space ray from `origin` along `direction` (the query that found it). Spheres lie in
// the world's own geometry, whose instance (if any) places it unmoved.
VKPT_FN SurfacePoint makeSurfacePoint(uint index, uint instance, TriangleHit hit, vec3 origin,
                                      vec3 direction VKPT_SCENE_PARAM) {
    Triangle primitive = scenePrimitive(index VKPT_SCENE_ARG);
    SurfacePoint s;
    s.triangle = index;
    s.instance = instance;
    s.outgoing = -normalize(direction);
    if (sceneHasSpheres(VKPT_SCENE_ARG_ONLY) && isSpherePrimitive(primitive)) {
        fillSphere(s, primitive, hit, origin, direction);
    } else {
        fillTriangle(s, primitive, hit, direction VKPT_SCENE_ARG);
    }
    fillMaterial(s, primitive, hit VKPT_SCENE_ARG);
    return s;
}

// Emission leaves the front face only, unless the material is double-sided.
VKPT_FN vec3 emittedRadiance(SurfacePoint s) {
    return (s.frontFace || s.doubleSided) ? s.emission : vec3(0.0f);
}

// The BSDF at a surface point for a world direction (bsdf.h's evaluateBsdfValue in the shading
// normal's frame).
VKPT_FN BsdfValue evaluateSurfaceBsdf(SurfacePoint s, vec3 wi) {
    Basis basis = makeBasis(s.shadingNormal);
    return evaluateBsdfValue(s.shading, worldToBasis(basis, s.outgoing), worldToBasis(basis, wi));
}

#ifdef __cplusplus
} // namespace vkpt::gpu
#endif

#endif // VKPT_SURFACE_H
