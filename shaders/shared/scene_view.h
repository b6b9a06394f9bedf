// scene_view.h — how the shared surface, material, texture and light code (materials.h,
// surface.h, texture_sampling.h, environment.h, lights.h, light_connection.h) reaches the
// prepared scene, so that the kernels and the CPU reference run that very code: the pattern of
// wide_bvh.h.
//
// Every function of that code takes VKPT_SCENE_PARAM last. On the C++ side it is a SceneView,
// spans over the arrays of a PreparedScene (host/prepare/prepared_scene_view.h makes one), and the
// accessors below read them. On the GLSL side it is empty: the includer defines the same
// accessors over its texel fetches and storage buffers before including the shared code
// (lib/scene_view.glsl), and the sceneHas* switches return the kernel's specialisation constants
// (lib/features.glsl), so that code for a feature the scene lacks folds away. The shared code
// reads every array one element at a time through these accessors, never as a whole, so that
// the kernels may split any of them across several buffers (lib/scene_arrays.glsl).
//
//   Type accessor(uint i)  one per VIEW row of shared/scene_array_table.h, element i of the
//                          row's array: scenePrimitive, sceneNormals, sceneUv (3 per
//                          primitive), sceneTextureTexel (texture_sampling.h),
//                          sceneEnvironmentCdf (environment.h), ...
//   uint sceneEmitterCount()
//   EnvironmentParams sceneEnvironment()
//   bool sceneHasMetallicRoughness(), sceneHasTextures(), sceneHasSpheres(),
//        sceneHasPunctualLights(), sceneHasEnvironment(), sceneHasEmitterCdf(),
//        sceneHasDoubleSided(), sceneHasNormalMaps(), sceneHasTransmission(),
//        sceneHasClearcoat(), sceneHasSheen(), sceneHasSpecularTextures(),
//        sceneHasAnisotropy(), sceneHasIridescence(), sceneHasDiffuseTransmission(),
//        sceneHasDispersion(), sceneHasInstances(), sceneHasLightTree()
#ifndef VKPT_SCENE_VIEW_H
#define VKPT_SCENE_VIEW_H

#include "host_device.h"
#include "scene_array_table.h"

#ifdef __cplusplus
#include <array>
#include <span>

namespace vkpt::gpu {

template <class T> using ConstSpan = std::span<const T>;

// The scene as the shared code reads it on the CPU: a span over each array of the table (those
// with their own reader, the BVH nodes and the albedo tables, too, unread here). An array the
// scene's features do not need may be empty; the code reads it only behind the matching
// feature.
struct SceneView : SceneArrayMembers<ConstSpan> {
    EnvironmentParams environment;
    std::array<bool, FEATURE_COUNT> features; // FEATURE_*, as the kernels are specialised
};

#define VKPT_SCENE_PARAM , const SceneView& scene
#define VKPT_SCENE_PARAM_ONLY const SceneView& scene
#define VKPT_SCENE_ARG , scene
#define VKPT_SCENE_ARG_ONLY scene

// One accessor per VIEW row of the table, element i of its span; an OWN row has its own reader.
#define VKPT_SCENE_VIEW_ACCESSOR_VIEW(Type, member, accessor)                                      \
    VKPT_FN Type accessor(uint i VKPT_SCENE_PARAM) {                                               \
        return scene.member[i];                                                                    \
    }
#define VKPT_SCENE_VIEW_ACCESSOR_OWN(Type, member, accessor)
#define VKPT_SCENE_VIEW_ACCESSOR(name, Type, binding, number, access, split, member, reader,       \
                                 accessor)                                                         \
    VKPT_SCENE_VIEW_ACCESSOR_##reader(Type, member, accessor)
VKPT_SCENE_ARRAYS(VKPT_SCENE_VIEW_ACCESSOR)

// Two fields of material i alone, for the camera's culling test (shared/camera_culling.h): the
// kernels fetch their two texels rather than decode the whole record in the traversal kernel.
VKPT_FN uint sceneMaterialFlags(uint i VKPT_SCENE_PARAM) {
    return scene.materials[i].flags;
}
VKPT_FN float sceneMaterialTransmission(uint i VKPT_SCENE_PARAM) {
    return scene.materials[i].transmission;
}

VKPT_FN uint sceneEmitterCount(VKPT_SCENE_PARAM_ONLY) {
    return uint(scene.emitters.size());
}
VKPT_FN EnvironmentParams sceneEnvironment(VKPT_SCENE_PARAM_ONLY) {
    return scene.environment;
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
VKPT_FN bool sceneHasSpecularTextures(VKPT_SCENE_PARAM_ONLY) {
    return scene.features[FEATURE_SPECULAR_TEXTURES];
}
VKPT_FN bool sceneHasAnisotropy(VKPT_SCENE_PARAM_ONLY) {
    return scene.features[FEATURE_ANISOTROPY];
}
VKPT_FN bool sceneHasIridescence(VKPT_SCENE_PARAM_ONLY) {
    return scene.features[FEATURE_IRIDESCENCE];
}
VKPT_FN bool sceneHasDiffuseTransmission(VKPT_SCENE_PARAM_ONLY) {
    return scene.features[FEATURE_DIFFUSE_TRANSMISSION];
}
VKPT_FN bool sceneHasDispersion(VKPT_SCENE_PARAM_ONLY) {
    return scene.features[FEATURE_DISPERSION];
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
