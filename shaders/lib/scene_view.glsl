// scene_view.glsl — the kernels' side of shared/scene_view.h: the accessors through which the
// shared surface, material and light code reads the scene, and the sceneHas* switches as the
// kernel's specialisation constants (lib/features.glsl), so that code for a feature the scene
// lacks folds away. Each array's accessor is generated from its row of
// shared/scene_array_table.h: a texel array's decodes element i (fetch<Type> of
// lib/records.glsl), a storage array's reads it through name##At (lib/scene_arrays.glsl).
#ifndef VKPT_SCENE_VIEW_GLSL
#define VKPT_SCENE_VIEW_GLSL

#include "lib/features.glsl"
#include "lib/records.glsl"
#include "shared/intersect.h"

// One accessor per VIEW row, `Type accessor(uint i)`; an OWN row has its own reader.
#define VKPT_READ_TEXELS(Type, name, accessor)                                                     \
    Type accessor(uint i) {                                                                        \
        return fetch##Type(i);                                                                     \
    }
#define VKPT_READ_STORAGE(Type, name, accessor)                                                    \
    Type accessor(uint i) {                                                                        \
        return name##At(i);                                                                        \
    }
#define VKPT_KERNEL_ACCESSOR_VIEW(access, Type, name, accessor)                                    \
    VKPT_READ_##access(Type, name, accessor)
#define VKPT_KERNEL_ACCESSOR_OWN(access, Type, name, accessor)
#define VKPT_KERNEL_SCENE_ACCESSOR(name, Type, binding, number, access, split, member, reader,     \
                                   accessor)                                                       \
    VKPT_KERNEL_ACCESSOR_##reader(access, Type, name, accessor)

VKPT_SCENE_ARRAYS(VKPT_KERNEL_SCENE_ACCESSOR)

// shared/scene_view.h's two-field reads of a material: texel 1's w (flags) and texel 13's x
// (transmission), host_device.h's offsets 28 and 208.
uint sceneMaterialFlags(uint i) {
    return RECORD_TEXEL(materials, MATERIAL_TEXELS, i, 1u).w;
}
float sceneMaterialTransmission(uint i) {
    return uintBitsToFloat(RECORD_TEXEL(materials, MATERIAL_TEXELS, i, 13u).x);
}

uint sceneEmitterCount() {
    return frame.emitterCount;
}

// The scene's environment; without a map in the features, width 0 lets the compiler fold the
// map's code away (environment.h tests width == 0 first).
EnvironmentParams sceneEnvironment() {
    EnvironmentParams env = frame.environment;
    if (!featureEnvironmentMap) env.width = 0u;
    return env;
}

bool sceneHasMetallicRoughness() {
    return featureMetallicRoughness;
}

bool sceneHasTextures() {
    return featureTextures;
}

bool sceneHasSpheres() {
    return featureSpheres;
}

bool sceneHasPunctualLights() {
    return featurePunctualLights;
}

bool sceneHasEnvironment() {
    return featureEnvironment;
}

bool sceneHasEmitterCdf() {
    return featureEmitterCdf;
}

bool sceneHasDoubleSided() {
    return featureDoubleSided;
}

bool sceneHasNormalMaps() {
    return featureNormalMaps;
}

bool sceneHasTransmission() {
    return featureTransmission;
}

bool sceneHasClearcoat() {
    return featureClearcoat;
}

bool sceneHasSheen() {
    return featureSheen;
}

// The features added since: macros rather than functions, so that the condition a guard tests
// is the specialisation constant itself, which the driver folds as it reads the SPIR-V, and
// the guarded calls never reach its inliner in a scene without the feature. (One parameter, for
// the shared code's empty VKPT_SCENE_ARG_ONLY.)
#define sceneHasSpecularTextures(noSceneArgument) featureSpecularTextures
#define sceneHasAnisotropy(noSceneArgument) featureAnisotropy
#define sceneHasIridescence(noSceneArgument) featureIridescence
#define sceneHasDiffuseTransmission(noSceneArgument) featureDiffuseTransmission
#define sceneHasDispersion(noSceneArgument) featureDispersion

bool sceneHasInstances() {
    return featureInstances;
}

bool sceneHasLightTree() {
    return featureLightTree;
}

// trace_closest's record of a hit as the shared code takes it.
TriangleHit triangleHitOf(HitRecord hit) {
    return TriangleHit(hit.t, hit.u, hit.v, true);
}

#include "shared/scene_view.h"

#endif // VKPT_SCENE_VIEW_GLSL
