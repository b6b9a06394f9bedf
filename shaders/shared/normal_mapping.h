// normal_mapping.h — a shading normal from a tangent-space normal texture (glTF normalTexture;
// clearcoat's normal texture takes the same path with its own slot and scale), and the bend
// that keeps a mapped normal from blackening or leaking a surface. Shared by both executors;
// reaches the scene through scene_view.h.
//
// glTF 2.0 (section 3.9.3, material.normalTexture): the texel's RGB maps to [-1, 1], X and Y are
// scaled by `scale`, and the result is normalised; X runs along the tangent, Y along the
// bitangent w·cross(n, t) (the texture's "up", towards smaller v), Z along the normal.
#ifndef VKPT_NORMAL_MAPPING_H
#define VKPT_NORMAL_MAPPING_H

#include "host_device.h"
#include "materials.h"
#include "scene_view.h"

#ifdef __cplusplus
namespace vkpt::gpu {
#endif

// The least cosine between the geometric normal and the reflection of the outgoing direction
// about a bent shading normal (bendTowardsViewer).
#define VKPT_NORMAL_BEND_MIN_COS 0.01f

// normalize((texel·2 − 1) · (scale, scale, 1)); a texel that decodes to zero gives +Z.
VKPT_FN vec3 decodeTangentSpaceNormal(vec4 texel, float scale) {
    vec3 n = vec3(texel) * 2.0f - vec3(1.0f);
    n = vec3(n.x * scale, n.y * scale, n.z);
    float len = length(n);
    return len > 0.0f ? n / len : vec3(0.0f, 0.0f, 1.0f);
}

// A tangent-space normal in the world frame of the unit normal n and the tangent (xyz, handedness
// w). The interpolated tangent is made orthogonal to n first (Gram–Schmidt), as MikkTSpace's
// consumers do; a tangent parallel to n leaves n unchanged.
VKPT_FN vec3 tangentToWorld(vec3 tangentSpace, vec3 n, vec4 tangent) {
    vec3 t = vec3(tangent) - n * dot(n, vec3(tangent));
    float len = length(t);
    if (!(len > 0.0f)) return n;
    t = t / len;
    vec3 b = (tangent.w < 0.0f ? -1.0f : 1.0f) * cross(n, t);
    vec3 mapped = t * tangentSpace.x + b * tangentSpace.y + n * tangentSpace.z;
    float mappedLength = length(mapped);
    return mappedLength > 0.0f ? mapped / mappedLength : n;
}

// The normal a tangent-space normal texture gives at uv, for any texture slot and scale
// (normalTexture, clearcoatNormalTexture); n itself without a texture or a tangent frame
// (tangent.w == 0: a sphere, or a primitive prepared without tangents).
VKPT_FN vec3 mappedNormal(TextureSlot slot, float scale, vec2 uv, vec3 n,
                          vec4 tangent VKPT_SCENE_PARAM) {
    if (!hasTexture(slot VKPT_SCENE_ARG) || tangent.w == 0.0f) return n;
    vec4 texel = sampleSlot(slot, uv, false VKPT_SCENE_ARG);
    return tangentToWorld(decodeTangentSpaceNormal(texel, scale), n, tangent);
}

// The tangent of primitive `index` at barycentrics (u, v): xyz interpolated, w the corners'
// handedness (all three corners of a generated frame share it; a file's TANGENT may not, and the
// interpolated sign decides).
VKPT_FN vec4 interpolatedTangent(uint index, float u, float v VKPT_SCENE_PARAM) {
    TriangleTangents t = sceneTangents(index VKPT_SCENE_ARG);
    return t.t0 * (1.0f - u - v) + t.t1 * u + t.t2 * v;
}

// A mapped normal bent so that the outgoing direction wo reflects about it to a direction at
// least VKPT_NORMAL_BEND_MIN_COS above the geometric surface (ng and wo on the same side): the
// "local shading normal adaption" of Keller et al., "The Iray Light Transport Simulation and
// Rendering System" (arXiv:1705.01263, 2017, appendix A.3). Left alone, a normal facing away
// from wo makes the GGX lobe return 0 (a black surface) and one whose mirror direction lies
// below the surface sends specular samples into it. The bent normal is the half vector of wo
// and the reflection r pushed up to the bound, r' = r + (VKPT_NORMAL_BEND_MIN_COS − r·ng)·ng,
// whose component along ng is wo·ng + VKPT_NORMAL_BEND_MIN_COS > 0: it always lies above the
// surface and faces wo. Energy: the Lambertian lobe about any normal above the surface
// integrates to at most 1 over the geometric hemisphere (tests/render/normal_map_test.cpp
// measures the furnace), and light sampling keeps rejecting directions below ng.
VKPT_FN vec3 bendTowardsViewer(vec3 n, vec3 ng, vec3 wo) {
    float cosOut = dot(wo, n);
    vec3 r = 2.0f * cosOut * n - wo;
    float rise = dot(r, ng);
    if (cosOut > 0.0f && rise >= VKPT_NORMAL_BEND_MIN_COS) return n;
    vec3 lifted = r + (VKPT_NORMAL_BEND_MIN_COS - rise) * ng;
    return normalize(wo + normalize(lifted));
}

#ifdef __cplusplus
} // namespace vkpt::gpu
#endif

#endif // VKPT_NORMAL_MAPPING_H
