// records.glsl — the read-only arrays the kernels fetch as 16-byte texels, and the records
// rebuilt from them. A texel fetch is one gather for 8 invocations on lavapipe, where a storage
// buffer read is a loop over the invocations with a bounds test per word (docs/gpu.md measured
// 2.3× for a vec4); GPUs serve texel fetches from the texture cache. Writes stay storage-buffer
// writes, so a work array a kernel also writes (rays, pathStates, shadowRays) has both a
// storage-buffer and a texel binding, and a kernel reads an element before it writes it.
// Every record here is a multiple of 16 bytes (shared/host_device.h, lib/wavefront.h).
//
// The texel views are declared here for every includer; a kernel binds those it fetches from
// (its TEXELS entries in lib/kernel_bindings.h), and one it never fetches from is not
// statically used.
#ifndef VKPT_RECORDS_GLSL
#define VKPT_RECORDS_GLSL

#include "lib/buffers.glsl"
#include "lib/wavefront.h"

VKPT_TEXEL_BUFFER(BINDING_BVH_NODES, bvhNodes)
VKPT_TEXEL_BUFFER(BINDING_TRIANGLES, triangleTexels)
VKPT_TEXEL_BUFFER(BINDING_TRIANGLE_NORMALS, triangleNormalTexels)
VKPT_TEXEL_BUFFER(BINDING_MATERIALS, materialTexels)
VKPT_TEXEL_BUFFER(BINDING_TEXTURES, textureInfoTexels)
VKPT_TEXEL_BUFFER(BINDING_EMITTERS, emitterTexels)
VKPT_TEXEL_BUFFER(BINDING_RAY_TEXELS, rayTexels)
VKPT_TEXEL_BUFFER(BINDING_HIT_TEXELS, hitTexels)
VKPT_TEXEL_BUFFER(BINDING_SHADOW_RAY_TEXELS, shadowRayTexels)
VKPT_TEXEL_BUFFER(BINDING_PATH_STATE_TEXELS, pathStateTexels)

vec3 texelVec3(uvec4 t) {
    return uintBitsToFloat(t.xyz);
}

vec4 texelVec4(uvec4 t) {
    return uintBitsToFloat(t);
}

// Texel k of record i of a record `texels` texels long.
#define RECORD_TEXEL(view, texels, i, k) texelFetch(view, int((texels) * (i) + (k)))

Triangle fetchTriangle(uint i) {
    uvec4 a = RECORD_TEXEL(triangleTexels, 3u, i, 0u);
    uvec4 b = RECORD_TEXEL(triangleTexels, 3u, i, 1u);
    uvec4 c = RECORD_TEXEL(triangleTexels, 3u, i, 2u);
    return Triangle(texelVec3(a), a.w, texelVec3(b), b.w, texelVec3(c), c.w);
}

TriangleNormals fetchTriangleNormals(uint i) {
    return TriangleNormals(texelVec4(RECORD_TEXEL(triangleNormalTexels, 3u, i, 0u)),
                           texelVec4(RECORD_TEXEL(triangleNormalTexels, 3u, i, 1u)),
                           texelVec4(RECORD_TEXEL(triangleNormalTexels, 3u, i, 2u)));
}

// A material is 20 texels (shared/host_device.h): the base's ten, then the layers' ten.
#define MATERIAL_TEXELS 20u

TextureSlot textureSlotFrom(uvec4 a, uvec4 b) {
    return TextureSlot(texelVec3(a), a.w, texelVec3(b), b.w);
}

TextureSlot fetchTextureSlot(uint material, uint first) {
    return textureSlotFrom(RECORD_TEXEL(materialTexels, MATERIAL_TEXELS, material, first),
                           RECORD_TEXEL(materialTexels, MATERIAL_TEXELS, material, first + 1u));
}

// Twenty texels, of which the compiler keeps the fetches of the fields a kernel reads (the
// layers' only where FEATURE_CLEARCOAT or FEATURE_SHEEN keeps the code that reads them).
Material fetchMaterial(uint i) {
    uvec4 colour = RECORD_TEXEL(materialTexels, MATERIAL_TEXELS, i, 0u);
    uvec4 emission = RECORD_TEXEL(materialTexels, MATERIAL_TEXELS, i, 1u);
    uvec4 factors = RECORD_TEXEL(materialTexels, MATERIAL_TEXELS, i, 2u);
    uvec4 specular = RECORD_TEXEL(materialTexels, MATERIAL_TEXELS, i, 3u);
    uvec4 sheen = RECORD_TEXEL(materialTexels, MATERIAL_TEXELS, i, 10u);
    uvec4 clearcoat = RECORD_TEXEL(materialTexels, MATERIAL_TEXELS, i, 11u);
    return Material(texelVec4(colour), texelVec3(emission), emission.w,
                    uintBitsToFloat(factors.x), uintBitsToFloat(factors.y),
                    uintBitsToFloat(factors.z), factors.w, texelVec3(specular),
                    uintBitsToFloat(specular.w), fetchTextureSlot(i, 4u), fetchTextureSlot(i, 6u),
                    fetchTextureSlot(i, 8u), texelVec3(sheen), uintBitsToFloat(sheen.w),
                    uintBitsToFloat(clearcoat.x), uintBitsToFloat(clearcoat.y), clearcoat.z,
                    clearcoat.w, fetchTextureSlot(i, 12u), fetchTextureSlot(i, 14u),
                    fetchTextureSlot(i, 16u), fetchTextureSlot(i, 18u));
}

TextureInfo fetchTextureInfo(uint i) {
    uvec4 t = texelFetch(textureInfoTexels, int(i));
    return TextureInfo(t.x, t.y, t.z, t.w);
}

Emitter fetchEmitter(uint i) {
    uvec4 a = RECORD_TEXEL(emitterTexels, 4u, i, 0u);
    uvec4 b = RECORD_TEXEL(emitterTexels, 4u, i, 1u);
    uvec4 c = RECORD_TEXEL(emitterTexels, 4u, i, 2u);
    vec4 d = texelVec4(RECORD_TEXEL(emitterTexels, 4u, i, 3u));
    return Emitter(texelVec3(a), a.w, texelVec3(b), b.w, texelVec3(c), uintBitsToFloat(c.w), d.x,
                   d.y, d.z, d.w);
}

RayRecord fetchRay(uint i) {
    uvec4 a = RECORD_TEXEL(rayTexels, 2u, i, 0u);
    uvec4 b = RECORD_TEXEL(rayTexels, 2u, i, 1u);
    return RayRecord(texelVec3(a), a.w, texelVec3(b), b.w);
}

HitRecord fetchHit(uint i) {
    uvec4 t = texelFetch(hitTexels, int(i));
    return HitRecord(uintBitsToFloat(t.x), uintBitsToFloat(t.y), uintBitsToFloat(t.z), t.w);
}

ShadowRay fetchShadowRay(uint i) {
    uvec4 a = RECORD_TEXEL(shadowRayTexels, 3u, i, 0u);
    uvec4 b = RECORD_TEXEL(shadowRayTexels, 3u, i, 1u);
    uvec4 c = RECORD_TEXEL(shadowRayTexels, 3u, i, 2u);
    return ShadowRay(texelVec3(a), a.w, texelVec3(b), uintBitsToFloat(b.w), texelVec3(c),
                     uintBitsToFloat(c.w));
}

PathState fetchPathState(uint slot) {
    uvec4 a = RECORD_TEXEL(pathStateTexels, 3u, slot, 0u);
    uvec4 b = RECORD_TEXEL(pathStateTexels, 3u, slot, 1u);
    uvec4 c = RECORD_TEXEL(pathStateTexels, 3u, slot, 2u);
    return PathState(texelVec3(a), a.w, texelVec3(b), b.w, texelVec3(c), uintBitsToFloat(c.w));
}

#endif // VKPT_RECORDS_GLSL
