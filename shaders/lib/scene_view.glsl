// scene_view.glsl — the kernels' side of shared/scene_view.h: the accessors through which the
// shared surface, material and light code reads the scene, as texel fetches of the scene
// records (lib/records.glsl) and the frame's parameters, and the sceneHas* switches as the
// kernel's specialisation constants (lib/features.glsl), so that code for a feature the scene
// lacks folds away. The arrays a kernel declares itself are read where they are needed:
// triangleUvs and textureTexels in lib/materials.glsl, environmentTexels and environmentCdf in
// lib/environment.glsl, emitterCdf in lib/lights.glsl.
#ifndef VKPT_SCENE_VIEW_GLSL
#define VKPT_SCENE_VIEW_GLSL

#include "lib/features.glsl"
#include "lib/records.glsl"
#include "shared/intersect.h"

Triangle scenePrimitive(uint i) {
    return fetchTriangle(i);
}

TriangleNormals sceneNormals(uint i) {
    return fetchTriangleNormals(i);
}

TriangleTangents sceneTangents(uint i) {
    return fetchTriangleTangents(i);
}

Material sceneMaterial(uint i) {
    return fetchMaterial(i);
}

Instance sceneInstance(uint i) {
    return fetchInstance(i);
}

TextureInfo sceneTexture(uint i) {
    return fetchTextureInfo(i);
}

Emitter sceneEmitter(uint i) {
    return fetchEmitter(i);
}

LightTreeNode sceneLightTreeNode(uint i) {
    return fetchLightTreeNode(i);
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
