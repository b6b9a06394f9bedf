// records.glsl — the read-only arrays the kernels fetch as 16-byte texels, and the records
// rebuilt from them. A texel fetch is one gather for 8 invocations on lavapipe, where a storage
// buffer read is a loop over the invocations with a bounds test per word (docs/gpu.md measured
// 2.3× for a vec4); GPUs serve texel fetches from the texture cache. Writes stay storage-buffer
// writes, so a work array a kernel also writes (rays, pathStates, shadowRays) has both a
// storage-buffer and a texel binding, and a kernel reads an element before it writes it.
// Every record here is a multiple of 16 bytes (shared/host_device.h, lib/wavefront.h).
//
// The texel views are declared for every includer, the scene arrays' by lib/scene_arrays.glsl
// (named as in shared/scene_array_table.h: triangles, materials, ...) and the work arrays' here;
// a kernel binds those it fetches from (its SCENE and TEXELS entries in lib/kernel_bindings.h),
// and one it never fetches from is not statically used. A scene array's decoder is
// fetch<Type>, the name lib/scene_view.glsl's generated accessors call.
#ifndef VKPT_RECORDS_GLSL
#define VKPT_RECORDS_GLSL

#include "lib/buffers.glsl"
#include "lib/scene_arrays.glsl"
#include "lib/wavefront.h"

// A work array's texel view and its accessor, uvec4 name##At(uint texel), named like a scene
// array's so that RECORD_TEXEL reads both alike.
#define VKPT_WORK_TEXELS(bindingIndex, name)                                                       \
    VKPT_TEXEL_BUFFER(bindingIndex, name)                                                          \
    uvec4 name##At(uint texel) {                                                                   \
        return texelFetch(name, int(texel));                                                       \
    }

// Work arrays, sized by the host to fit one binding (host/render/work_buffers.cpp).
VKPT_WORK_TEXELS(BINDING_RAY_TEXELS, rayTexels)
VKPT_WORK_TEXELS(BINDING_HIT_TEXELS, hitTexels)
VKPT_WORK_TEXELS(BINDING_SHADOW_RAY_TEXELS, shadowRayTexels)
VKPT_WORK_TEXELS(BINDING_PATH_STATE_TEXELS, pathStateTexels)

vec3 texelVec3(uvec4 t) {
    return uintBitsToFloat(t.xyz);
}

vec4 texelVec4(uvec4 t) {
    return uintBitsToFloat(t);
}

// Texel k of record i of a record `texels` texels long.
#define RECORD_TEXEL(view, texels, i, k) view##At((texels) * (i) + (k))

Triangle fetchTriangle(uint i) {
    uvec4 a = RECORD_TEXEL(triangles, 3u, i, 0u);
    uvec4 b = RECORD_TEXEL(triangles, 3u, i, 1u);
    uvec4 c = RECORD_TEXEL(triangles, 3u, i, 2u);
    return Triangle(texelVec3(a), a.w, texelVec3(b), b.w, texelVec3(c), c.w);
}

TriangleNormals fetchTriangleNormals(uint i) {
    return TriangleNormals(texelVec4(RECORD_TEXEL(triangleNormals, 3u, i, 0u)),
                           texelVec4(RECORD_TEXEL(triangleNormals, 3u, i, 1u)),
                           texelVec4(RECORD_TEXEL(triangleNormals, 3u, i, 2u)));
}

TriangleTangents fetchTriangleTangents(uint i) {
    return TriangleTangents(texelVec4(RECORD_TEXEL(triangleTangents, 3u, i, 0u)),
                            texelVec4(RECORD_TEXEL(triangleTangents, 3u, i, 1u)),
                            texelVec4(RECORD_TEXEL(triangleTangents, 3u, i, 2u)));
}

#define MATERIAL_TEXELS 29u // sizeof(Material) / 16

TextureSlot textureSlotFrom(uvec4 a, uvec4 b) {
    return TextureSlot(texelVec3(a), a.w, texelVec3(b), b.w);
}

TextureSlot fetchTextureSlot(uint material, uint first) {
    return textureSlotFrom(RECORD_TEXEL(materials, MATERIAL_TEXELS, material, first),
                           RECORD_TEXEL(materials, MATERIAL_TEXELS, material, first + 1u));
}

// Twenty-nine texels, of which the compiler keeps the fetches of the fields a kernel reads.
// Texels 10–12: the normal texture; 13–16: transmission, ior and volume; 17–28: clearcoat and
// sheen (read only where FEATURE_CLEARCOAT or FEATURE_SHEEN keeps the code that reads them).
Material fetchMaterial(uint i) {
    uvec4 colour = RECORD_TEXEL(materials, MATERIAL_TEXELS, i, 0u);
    uvec4 emission = RECORD_TEXEL(materials, MATERIAL_TEXELS, i, 1u);
    uvec4 factors = RECORD_TEXEL(materials, MATERIAL_TEXELS, i, 2u);
    uvec4 specular = RECORD_TEXEL(materials, MATERIAL_TEXELS, i, 3u);
    vec4 glass = texelVec4(RECORD_TEXEL(materials, MATERIAL_TEXELS, i, 13u));
    uvec4 volume = RECORD_TEXEL(materials, MATERIAL_TEXELS, i, 14u);
    uvec4 sheen = RECORD_TEXEL(materials, MATERIAL_TEXELS, i, 17u);
    uvec4 clearcoat = RECORD_TEXEL(materials, MATERIAL_TEXELS, i, 18u);
    return Material(texelVec4(colour), texelVec3(emission), emission.w, uintBitsToFloat(factors.x),
                    uintBitsToFloat(factors.y), uintBitsToFloat(factors.z), factors.w,
                    texelVec3(specular), uintBitsToFloat(specular.w), fetchTextureSlot(i, 4u),
                    fetchTextureSlot(i, 6u), fetchTextureSlot(i, 8u), fetchTextureSlot(i, 10u),
                    uintBitsToFloat(RECORD_TEXEL(materials, MATERIAL_TEXELS, i, 12u).x), 0u, 0u, 0u,
                    glass.x, glass.y, glass.z, glass.w, texelVec3(volume), volume.w,
                    fetchTextureSlot(i, 15u), texelVec3(sheen), uintBitsToFloat(sheen.w),
                    uintBitsToFloat(clearcoat.x), uintBitsToFloat(clearcoat.y),
                    uintBitsToFloat(clearcoat.z), clearcoat.w, fetchTextureSlot(i, 19u),
                    fetchTextureSlot(i, 21u), fetchTextureSlot(i, 23u), fetchTextureSlot(i, 25u),
                    fetchTextureSlot(i, 27u));
}

#define SPECULAR_LOBE_TEXELS 12u // sizeof(SpecularLobeParams) / 16

TextureSlot fetchSpecularLobeSlot(uint i, uint first) {
    return textureSlotFrom(RECORD_TEXEL(specularLobes, SPECULAR_LOBE_TEXELS, i, first),
                           RECORD_TEXEL(specularLobes, SPECULAR_LOBE_TEXELS, i, first + 1u));
}

// Material i's specular textures (texels 0–3), anisotropy (4–6) and iridescence (7–11); read
// only by code behind FEATURE_SPECULAR_TEXTURES, FEATURE_ANISOTROPY or FEATURE_IRIDESCENCE.
SpecularLobeParams fetchSpecularLobeParams(uint i) {
    uvec4 anisotropy = RECORD_TEXEL(specularLobes, SPECULAR_LOBE_TEXELS, i, 4u);
    vec4 iridescence = texelVec4(RECORD_TEXEL(specularLobes, SPECULAR_LOBE_TEXELS, i, 7u));
    return SpecularLobeParams(
        fetchSpecularLobeSlot(i, 0u), fetchSpecularLobeSlot(i, 2u), uintBitsToFloat(anisotropy.x),
        uintBitsToFloat(anisotropy.y), uintBitsToFloat(anisotropy.z), anisotropy.w,
        fetchSpecularLobeSlot(i, 5u), iridescence.x, iridescence.y, iridescence.z, iridescence.w,
        fetchSpecularLobeSlot(i, 8u), fetchSpecularLobeSlot(i, 10u));
}

#define INSTANCE_TEXELS 7u // sizeof(Instance) / 16

// What a walk reads of an instance: the inverse transform and the mesh's root (texels 0–3); the
// compiler drops the rest.
Instance fetchWalkInstance(uint i) {
    uvec4 flags = RECORD_TEXEL(instances, INSTANCE_TEXELS, i, 3u);
    return Instance(texelVec4(RECORD_TEXEL(instances, INSTANCE_TEXELS, i, 0u)),
                    texelVec4(RECORD_TEXEL(instances, INSTANCE_TEXELS, i, 1u)),
                    texelVec4(RECORD_TEXEL(instances, INSTANCE_TEXELS, i, 2u)), flags.x, flags.y,
                    flags.z, flags.w, vec4(0.0), vec4(0.0), vec4(0.0));
}

Instance fetchInstance(uint i) {
    Instance x = fetchWalkInstance(i);
    x.objectToWorld0 = texelVec4(RECORD_TEXEL(instances, INSTANCE_TEXELS, i, 4u));
    x.objectToWorld1 = texelVec4(RECORD_TEXEL(instances, INSTANCE_TEXELS, i, 5u));
    x.objectToWorld2 = texelVec4(RECORD_TEXEL(instances, INSTANCE_TEXELS, i, 6u));
    return x;
}

TextureInfo fetchTextureInfo(uint i) {
    uvec4 t = texturesAt(i);
    return TextureInfo(t.x, t.y, t.z, t.w);
}

Emitter fetchEmitter(uint i) {
    uvec4 a = RECORD_TEXEL(emitters, 4u, i, 0u);
    uvec4 b = RECORD_TEXEL(emitters, 4u, i, 1u);
    uvec4 c = RECORD_TEXEL(emitters, 4u, i, 2u);
    vec4 d = texelVec4(RECORD_TEXEL(emitters, 4u, i, 3u));
    return Emitter(texelVec3(a), a.w, texelVec3(b), b.w, texelVec3(c), uintBitsToFloat(c.w), d.x,
                   d.y, d.z, d.w);
}

LightTreeNode fetchLightTreeNode(uint i) {
    uvec4 a = RECORD_TEXEL(lightTree, 4u, i, 0u);
    uvec4 b = RECORD_TEXEL(lightTree, 4u, i, 1u);
    uvec4 c = RECORD_TEXEL(lightTree, 4u, i, 2u);
    uvec4 d = RECORD_TEXEL(lightTree, 4u, i, 3u);
    return LightTreeNode(texelVec3(a), uintBitsToFloat(a.w), texelVec3(b), uintBitsToFloat(b.w),
                         texelVec3(c), uintBitsToFloat(c.w), d.x, d.y, d.z, d.w);
}

RayRecord fetchRay(uint i) {
    uvec4 a = RECORD_TEXEL(rayTexels, 2u, i, 0u);
    uvec4 b = RECORD_TEXEL(rayTexels, 2u, i, 1u);
    return RayRecord(texelVec3(a), a.w, texelVec3(b), b.w);
}

HitRecord fetchHit(uint i) {
    uvec4 t = hitTexelsAt(i);
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
    uvec4 a = RECORD_TEXEL(pathStateTexels, 4u, slot, 0u);
    uvec4 b = RECORD_TEXEL(pathStateTexels, 4u, slot, 1u);
    uvec4 c = RECORD_TEXEL(pathStateTexels, 4u, slot, 2u);
    uvec4 d = RECORD_TEXEL(pathStateTexels, 4u, slot, 3u);
    return PathState(texelVec3(a), a.w, texelVec3(b), b.w, texelVec3(c), uintBitsToFloat(c.w),
                     texelVec3(d), uintBitsToFloat(d.w));
}

#endif // VKPT_RECORDS_GLSL
