// scene_view.h — how the shared surface, material, texture and light code (materials.h,
// surface.h, texture_sampling.h, environment.h, lights.h, light_connection.h) reaches the
// prepared scene, so that the kernels and the CPU reference run that very code: the pattern of
// wide_bvh.h.
//
// Every function of that code takes VKPT_SCENE_PARAM last. On the C++ side it is a SceneView,
// spans over the arrays of a PreparedScene (host/prepare/prepared_scene_view.h makes one), and the
// accessors below read them. On the GLSL side it is empty: the includer defines the same
// accessors over its texel fetches and storage buffers before including the shared code
// (lib/materials.glsl, lib/surface.glsl, lib/environment.glsl, lib/lights.glsl), and the
// sceneHas* switches return the kernel's specialisation constants (lib/features.glsl), so that
// code for a feature the scene lacks folds away. The shared code reads every array one element
// at a time through these accessors, never as a whole, so that the kernels may split any of
// them across several buffers (lib/scene_arrays.glsl).
//
//   Triangle scenePrimitive(uint i)         TriangleNormals sceneNormals(uint i)
//   TriangleTangents sceneTangents(uint i)  Instance sceneInstance(uint i)
//   vec2 sceneUv(uint k)  (3 per primitive) Material sceneMaterial(uint i)
//   TextureInfo sceneTexture(uint i)        uint sceneTextureTexel(uint i) (texture_sampling.h)
//   Emitter sceneEmitter(uint i)            uint sceneEmitterCount()
//   float sceneEmitterCdf(uint i)           LightTreeNode sceneLightTreeNode(uint i)
//   EnvironmentParams sceneEnvironment()
//   vec4 sceneEnvironmentTexel(uint i)      float sceneEnvironmentCdf(uint i) (environment.h)
//   bool sceneHasMetallicRoughness(), sceneHasTextures(), sceneHasSpheres(),
//        sceneHasPunctualLights(), sceneHasEnvironment(), sceneHasEmitterCdf(),
//        sceneHasDoubleSided(), sceneHasNormalMaps(), sceneHasTransmission(),
//        sceneHasClearcoat(), sceneHasSheen(), sceneHasInstances(), sceneHasLightTree()
#ifndef VKPT_SCENE_VIEW_H
#define VKPT_SCENE_VIEW_H

#include "host_device.h"

#ifdef __cplusplus
#include <array>
#include <span>

namespace vkpt::gpu {

// The scene as the shared code reads it on the CPU. An array the scene's features do not need
// may be empty; the code reads it only behind the matching feature.
struct SceneView {
    std::span<const Triangle> primitives; // triangles and spheres, BVH order
    std::span<const TriangleNormals> normals;
    std::span<const TriangleTangents> tangents; // empty unless FEATURE_NORMAL_MAPS
    std::span<const Instance> instances;        // empty unless FEATURE_INSTANCES
    std::span<const vec2> uvs;                  // 3 per primitive
    std::span<const Material> materials;
    std::span<const TextureInfo> textures;
    std::span<const uint> textureTexels;
    std::span<const Emitter> emitters;
    std::span<const float> emitterCdf;
    std::span<const LightTreeNode> lightTree; // empty unless FEATURE_LIGHT_TREE
    EnvironmentParams environment;
    std::span<const vec4> environmentTexels;
    std::span<const float> environmentCdf;
    std::array<bool, FEATURE_COUNT> features; // FEATURE_*, as the kernels are specialised
};

#define VKPT_SCENE_PARAM , const SceneView& scene
#define VKPT_SCENE_PARAM_ONLY const SceneView& scene
#define VKPT_SCENE_ARG , scene
#define VKPT_SCENE_ARG_ONLY scene

VKPT_FN Triangle scenePrimitive(uint i VKPT_SCENE_PARAM) {
    return scene.primitives[i];
}
VKPT_FN TriangleNormals sceneNormals(uint i VKPT_SCENE_PARAM) {
    return scene.normals[i];
}
VKPT_FN TriangleTangents sceneTangents(uint i VKPT_SCENE_PARAM) {
    return scene.tangents[i];
}
VKPT_FN Instance sceneInstance(uint i VKPT_SCENE_PARAM) {
    return scene.instances[i];
}
VKPT_FN vec2 sceneUv(uint k VKPT_SCENE_PARAM) {
    return scene.uvs[k];
}
VKPT_FN Material sceneMaterial(uint i VKPT_SCENE_PARAM) {
    return scene.materials[i];
}
VKPT_FN TextureInfo sceneTexture(uint i VKPT_SCENE_PARAM) {
    return scene.textures[i];
}
VKPT_FN uint sceneTextureTexel(uint i VKPT_SCENE_PARAM) {
    return scene.textureTexels[i];
}
VKPT_FN Emitter sceneEmitter(uint i VKPT_SCENE_PARAM) {
    return scene.emitters[i];
}
VKPT_FN uint sceneEmitterCount(VKPT_SCENE_PARAM_ONLY) {
    return uint(scene.emitters.size());
}
VKPT_FN float sceneEmitterCdf(uint i VKPT_SCENE_PARAM) {
    return scene.emitterCdf[i];
}
VKPT_FN LightTreeNode sceneLightTreeNode(uint i VKPT_SCENE_PARAM) {
    return scene.lightTree[i];
}
VKPT_FN EnvironmentParams sceneEnvironment(VKPT_SCENE_PARAM_ONLY) {
    return scene.environment;
}
VKPT_FN vec4 sceneEnvironmentTexel(uint i VKPT_SCENE_PARAM) {
    return scene.environmentTexels[i];
}
VKPT_FN float sceneEnvironmentCdf(uint i VKPT_SCENE_PARAM) {
    return scene.environmentCdf[i];
}

VKPT_FN bool sceneHasMetallicRoughness(VKPT_SCENE_PARAM_ONLY) {
    return scene.features[FEATURE_METALLIC_ROUGHNESS];
}
VKPT_FN bool sceneHasTextures(VKPT_SCENE_PARAM_ONLY) {
    return scene.features[FEATURE_TEXTURES];
}
VKPT_FN bool sceneHasSpheres(VKPT_SCENE_PARAM_ONLY) {
    return scene.features[FEATURE_SPHERES];
}
VKPT_FN bool sceneHasPunctualLights(VKPT_SCENE_PARAM_ONLY) {
    return scene.features[FEATURE_PUNCTUAL_LIGHTS];
}
VKPT_FN bool sceneHasEnvironment(VKPT_SCENE_PARAM_ONLY) {
    return scene.features[FEATURE_ENVIRONMENT];
}
VKPT_FN bool sceneHasEmitterCdf(VKPT_SCENE_PARAM_ONLY) {
    return scene.features[FEATURE_EMITTER_CDF];
}
VKPT_FN bool sceneHasDoubleSided(VKPT_SCENE_PARAM_ONLY) {
    return scene.features[FEATURE_DOUBLE_SIDED];
}
VKPT_FN bool sceneHasNormalMaps(VKPT_SCENE_PARAM_ONLY) {
    return scene.features[FEATURE_NORMAL_MAPS];
}
VKPT_FN bool sceneHasTransmission(VKPT_SCENE_PARAM_ONLY) {
    return scene.features[FEATURE_TRANSMISSION];
}
VKPT_FN bool sceneHasClearcoat(VKPT_SCENE_PARAM_ONLY) {
    return scene.features[FEATURE_CLEARCOAT];
}
VKPT_FN bool sceneHasSheen(VKPT_SCENE_PARAM_ONLY) {
    return scene.features[FEATURE_SHEEN];
}
VKPT_FN bool sceneHasInstances(VKPT_SCENE_PARAM_ONLY) {
    return scene.features[FEATURE_INSTANCES];
}
VKPT_FN bool sceneHasLightTree(VKPT_SCENE_PARAM_ONLY) {
    return scene.features[FEATURE_LIGHT_TREE];
}

} // namespace vkpt::gpu
#else
#define VKPT_SCENE_PARAM
#define VKPT_SCENE_PARAM_ONLY
#define VKPT_SCENE_ARG
#define VKPT_SCENE_ARG_ONLY
#endif

#endif // VKPT_SCENE_VIEW_H
