// surface.glsl — a hit turned into what shading needs, as host/reference/surface.cpp does it:
// the point (from barycentrics on a triangle, put back on a sphere along its normal), the
// geometric and shading normals turned towards the incoming ray, the material with its textures
// applied, and the emission. Needs what lib/materials.glsl needs (and binds triangleNormals).
#ifndef VKPT_SURFACE_GLSL
#define VKPT_SURFACE_GLSL

#include "lib/materials.glsl"
#include "shared/bsdf.h"
#include "shared/intersect.h"
#include "shared/ray_offset.h"
#include "shared/sampling.h"
#include "shared/sphere.h"

struct SurfacePoint {
    vec3 position;
    vec3 geometricNormal;    // unit, on the side the ray came from
    vec3 shadingNormal;      // unit, interpolated, on the same side
    vec3 rawShadingNormal;   // as stored (a sphere's outward normal), for the normals integrator
    bool frontFace;          // triangle: the counter-clockwise side; sphere: outside
    bool doubleSided;        // the material emits from both sides
    float coordinateScale;   // of the primitive, for offsetFromSurface
    uint triangle;           // the primitive, BVH-ordered
    ShadingMaterial shading; // the BSDF's parameters, textures applied
    vec3 emission;           // emissive factor × texture, before the side test
    vec3 outgoing;           // unit, back along the incoming ray
};

void fillTriangle(inout SurfacePoint s, Triangle tri, HitRecord hit, vec3 direction) {
    TriangleNormals normals = fetchTriangleNormals(hit.triangle);
    // Barycentric interpolation keeps the point on the triangle's plane, unlike o + t·d.
    s.position = tri.v0 * (1.0 - hit.u - hit.v) + tri.v1 * hit.u + tri.v2 * hit.v;
    s.coordinateScale = triangleCoordinateScale(tri.v0, tri.v1, tri.v2);
    vec3 face = unitFaceNormal(tri.v0, tri.v1, tri.v2);
    s.frontFace = dot(face, direction) < 0.0;
    s.geometricNormal = s.frontFace ? face : -face;
    s.rawShadingNormal =
        normals.n0.xyz * (1.0 - hit.u - hit.v) + normals.n1.xyz * hit.u + normals.n2.xyz * hit.v;
    float rawLength = length(s.rawShadingNormal);
    vec3 shading = rawLength > 0.0 ? s.rawShadingNormal / rawLength : s.geometricNormal;
    s.shadingNormal = dot(shading, s.geometricNormal) < 0.0 ? -shading : shading;
}

// The point is put back on the sphere along its normal, so that its distance from the surface
// is the radius' rounding, not o + t·d's.
void fillSphere(inout SurfacePoint s, Triangle sphere, HitRecord hit, vec3 origin, vec3 direction) {
    vec3 outward = sphereNormalAt(origin + hit.t * direction, sphere.v0);
    s.position = sphere.v0 + sphere.v1.x * outward;
    s.coordinateScale = sphereCoordinateScale(sphere.v0, sphere.v1.x);
    s.frontFace = dot(outward, direction) < 0.0;
    s.geometricNormal = s.frontFace ? outward : -outward;
    s.rawShadingNormal = outward;
    s.shadingNormal = s.geometricNormal;
}

// The material at the point: factors times textures (each read only when present).
void fillMaterial(inout SurfacePoint s, Triangle primitive, HitRecord hit) {
    Material m = fetchMaterial(primitive.materialIndex);
    vec4 baseColor = m.baseColor;
    float metallic = m.metallic;
    float roughness = m.roughness;
    s.emission = m.emission;
    if (hasAnyTexture(m)) {
        vec2 uv = primitiveUv(hit.triangle, primitive, hit.u, hit.v, s.rawShadingNormal);
        baseColor = m.baseColor * sampleSlot(m.baseColorTexture, uv, true);
        vec4 metalRough = sampleSlot(m.metallicRoughnessTexture, uv, false);
        metallic = m.metallic * metalRough.b;
        roughness = m.roughness * metalRough.g;
        s.emission = emissionAt(m, uv);
    }
    bool metallicRoughness =
        featureMetallicRoughness && (m.flags & MATERIAL_METALLIC_ROUGHNESS) != 0u;
    s.shading = makeShadingMaterial(baseColor.rgb, metallic, roughness, m.specular, m.specularColor,
                                    metallicRoughness);
    s.doubleSided = featureDoubleSided && (m.flags & MATERIAL_DOUBLE_SIDED) != 0u;
}

// The hit of a ray from `origin` along `direction` (the query that found `hit`).
SurfacePoint makeSurfacePoint(HitRecord hit, vec3 origin, vec3 direction) {
    Triangle primitive = fetchTriangle(hit.triangle);
    SurfacePoint s;
    s.triangle = hit.triangle;
    if (featureSpheres && isSpherePrimitive(primitive)) {
        fillSphere(s, primitive, hit, origin, direction);
    } else {
        fillTriangle(s, primitive, hit, direction);
    }
    fillMaterial(s, primitive, hit);
    s.outgoing = -normalize(direction);
    return s;
}

// Emission leaves the front face only, unless the material is double-sided.
vec3 emittedRadiance(SurfacePoint s) {
    return (s.frontFace || s.doubleSided) ? s.emission : vec3(0.0);
}

// The BSDF at a surface point for a world direction: f (no cosine) and the solid-angle pdf with
// which sampleBsdf would choose wi, both in the shading normal's frame.
struct BsdfValue {
    vec3 f;
    float pdf;
};

BsdfValue evaluateSurfaceBsdf(SurfacePoint s, vec3 wi) {
    Basis basis = makeBasis(s.shadingNormal);
    vec3 wo = worldToBasis(basis, s.outgoing);
    vec3 wiLocal = worldToBasis(basis, wi);
    return BsdfValue(evaluateBsdf(s.shading, wo, wiLocal), bsdfPdf(s.shading, wo, wiLocal));
}

#endif // VKPT_SURFACE_GLSL
