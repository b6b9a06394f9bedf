// surface.glsl — a hit turned into what shading needs, as host/reference/surface.cpp does it:
// the point from barycentrics, the geometric and shading normals turned towards the incoming
// ray, the material, and the emission towards the ray. Needs triangles, triangleNormals and
// materials declared.
#ifndef VKPT_SURFACE_GLSL
#define VKPT_SURFACE_GLSL

#include "shared/intersect.h"
#include "shared/ray_offset.h"

struct SurfacePoint {
    vec3 position;
    vec3 geometricNormal;  // unit, on the side the ray came from
    vec3 shadingNormal;    // unit, interpolated, on the same side
    vec3 rawShadingNormal; // interpolated as stored, for the normals integrator
    bool frontFace;        // the ray arrived on the counter-clockwise side
    float coordinateScale; // of the triangle's vertices, for offsetFromSurface
    uint triangle;
    uint materialIndex;
};

SurfacePoint makeSurfacePoint(HitRecord hit, vec3 rayDirection) {
    Triangle tri = triangles[hit.triangle];
    TriangleNormals normals = triangleNormals[hit.triangle];
    SurfacePoint s;
    s.triangle = hit.triangle;
    s.materialIndex = tri.materialIndex;
    // Barycentric interpolation keeps the point on the triangle's plane, unlike o + t·d.
    float w = 1.0 - hit.u - hit.v;
    s.position = tri.v0 * w + tri.v1 * hit.u + tri.v2 * hit.v;
    s.coordinateScale = triangleCoordinateScale(tri.v0, tri.v1, tri.v2);
    vec3 face = unitFaceNormal(tri.v0, tri.v1, tri.v2);
    s.frontFace = dot(face, rayDirection) < 0.0;
    s.geometricNormal = s.frontFace ? face : -face;
    s.rawShadingNormal = normals.n0.xyz * w + normals.n1.xyz * hit.u + normals.n2.xyz * hit.v;
    float rawLength = length(s.rawShadingNormal);
    vec3 shading = rawLength > 0.0 ? s.rawShadingNormal / rawLength : s.geometricNormal;
    s.shadingNormal = dot(shading, s.geometricNormal) < 0.0 ? -shading : shading;
    return s;
}

// Emission leaves the front face only, unless the material is double-sided.
vec3 emittedRadiance(SurfacePoint s) {
    Material material = materials[s.materialIndex];
    bool emitsHere = s.frontFace || (material.flags & MATERIAL_DOUBLE_SIDED) != 0u;
    return emitsHere ? material.emission : vec3(0.0);
}

vec3 lambertAlbedo(SurfacePoint s) {
    return materials[s.materialIndex].baseColor.rgb;
}

#endif // VKPT_SURFACE_GLSL
