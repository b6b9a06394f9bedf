// read_layouts.comp — reads every field of every shared struct and wavefront record through its
// GLSL (std430) declaration and writes it as 32-bit words in declaration order, so the host can
// compare the words with the bytes of its C++ layout.
#version 460
#extension GL_GOOGLE_include_directive : require
#include "kernel_test_io.h"
#include "lib/buffers.glsl"
#include "shared/host_device.h"

layout(local_size_x = WORKGROUP_SIZE) in;

VKPT_READONLY_BUFFER(0, WideBvhNode, bvhNodes)
VKPT_READONLY_BUFFER(1, Triangle, triangles)
VKPT_READONLY_BUFFER(2, TriangleNormals, triangleNormals)
VKPT_READONLY_BUFFER(3, Material, materials)
VKPT_READONLY_BUFFER(4, TextureInfo, textures)
VKPT_READONLY_BUFFER(5, Emitter, emitters)
VKPT_READONLY_BUFFER(6, EnvironmentParams, environments)
VKPT_READONLY_BUFFER(7, Camera, cameras)
VKPT_WRITEONLY_BUFFER(8, uint, words)
VKPT_READONLY_BUFFER(9, FrameParams, frames)
VKPT_READONLY_BUFFER(10, PathState, pathStates)
VKPT_READONLY_BUFFER(11, ShadowRay, shadowRays)
VKPT_READONLY_BUFFER(12, PixelState, pixelStates)
VKPT_READONLY_BUFFER(13, LightTreeNode, lightTreeNodes)
VKPT_READONLY_BUFFER(14, SpecularLobeParams, specularLobes)
VKPT_READONLY_BUFFER(15, MaterialLobes, materialLobes)

uint cursor;

void putUint(uint value) {
    words[cursor] = value;
    cursor += 1u;
}
void putFloat(float value) {
    putUint(floatBitsToUint(value));
}
void putVec3(vec3 value) {
    putFloat(value.x);
    putFloat(value.y);
    putFloat(value.z);
}
void putVec4(vec4 value) {
    putVec3(value.xyz);
    putFloat(value.w);
}

void putUvec4(uvec4 value) {
    putUint(value.x);
    putUint(value.y);
    putUint(value.z);
    putUint(value.w);
}

void putTextureSlot(TextureSlot slot) {
    putVec3(slot.transformRow0);
    putUint(slot.texture);
    putVec3(slot.transformRow1);
    putUint(slot.unused0);
}

void putCamera(Camera camera) {
    putVec3(camera.position);
    putFloat(camera.tanHalfFovY);
    putVec3(camera.right);
    putFloat(camera.aspect);
    putVec3(camera.up);
    putUint(camera.width);
    putVec3(camera.forward);
    putUint(camera.height);
    putUint(camera.projection);
    putFloat(camera.orthoHalfHeight);
    putUint(camera.unused0);
    putUint(camera.unused1);
}

void putEnvironment(EnvironmentParams environment) {
    putVec3(environment.radiance);
    putUint(environment.width);
    putUint(environment.height);
    putUint(environment.emitterIndex);
    putUint(environment.unused0);
    putUint(environment.unused1);
}

void putFrameParams(FrameParams frame) {
    putCamera(frame.camera);
    putUint(frame.seed);
    putUint(frame.maxDepth);
    putUint(frame.rrStartDepth);
    putUint(frame.lightSamples);
    putUint(frame.integrator);
    putUint(frame.pathFilter);
    putUint(frame.emitterCount);
    putUint(frame.adaptive);
    putUint(frame.adaptiveBatch);
    putUint(frame.adaptiveMinSamples);
    putFloat(frame.adaptiveTolerance);
    putFloat(frame.adaptiveDarkFloor);
    putUint(frame.slotCount);
    putUint(frame.pixelCount);
    putUint(frame.samplerSetup);
    putFloat(frame.sampleClamp);
    putEnvironment(frame.environment);
}

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= LAYOUT_COUNT) return;

    cursor = LAYOUT_OFFSET_BVH_NODES + i * LAYOUT_WORDS_BVH_NODE;
    putUint(bvhNodes[i].childBase);
    putUint(bvhNodes[i].parent);
    putUint(bvhNodes[i].slotsAndExponents);
    putUint(bvhNodes[i].primitiveBase);
    putVec3(bvhNodes[i].origin);
    putUint(bvhNodes[i].leafCounts);
    putUvec4(bvhNodes[i].quantised[0]);
    putUvec4(bvhNodes[i].quantised[1]);
    putUvec4(bvhNodes[i].quantised[2]);

    cursor = LAYOUT_OFFSET_TRIANGLES + i * LAYOUT_WORDS_TRIANGLE;
    putVec3(triangles[i].v0);
    putUint(triangles[i].materialIndex);
    putVec3(triangles[i].v1);
    putUint(triangles[i].emitterIndex);
    putVec3(triangles[i].v2);
    putUint(triangles[i].sourceIndex);

    cursor = LAYOUT_OFFSET_TRIANGLE_NORMALS + i * LAYOUT_WORDS_TRIANGLE_NORMALS;
    putVec4(triangleNormals[i].n0);
    putVec4(triangleNormals[i].n1);
    putVec4(triangleNormals[i].n2);

    cursor = LAYOUT_OFFSET_MATERIALS + i * LAYOUT_WORDS_MATERIAL;
    putVec4(materials[i].baseColor);
    putVec3(materials[i].emission);
    putUint(materials[i].flags);
    putFloat(materials[i].metallic);
    putFloat(materials[i].roughness);
    putFloat(materials[i].alphaCutoff);
    putUint(materials[i].alphaMode);
    putVec3(materials[i].specularColor);
    putFloat(materials[i].specular);
    putTextureSlot(materials[i].baseColorTexture);
    putTextureSlot(materials[i].metallicRoughnessTexture);
    putTextureSlot(materials[i].emissiveTexture);
    putTextureSlot(materials[i].normalTexture);
    putFloat(materials[i].normalScale);
    putUint(materials[i].normalUnused0);
    putUint(materials[i].normalUnused1);
    putUint(materials[i].normalUnused2);
    putFloat(materials[i].transmission);
    putFloat(materials[i].ior);
    putFloat(materials[i].iorF0);
    putFloat(materials[i].thickness);
    putVec3(materials[i].attenuationCoefficient);
    putUint(materials[i].unusedVolume);
    putTextureSlot(materials[i].transmissionTexture);
    putVec3(materials[i].sheenColor);
    putFloat(materials[i].sheenRoughness);
    putFloat(materials[i].clearcoat);
    putFloat(materials[i].clearcoatRoughness);
    putFloat(materials[i].clearcoatNormalScale);
    putUint(materials[i].layersUnused);
    putTextureSlot(materials[i].clearcoatTexture);
    putTextureSlot(materials[i].clearcoatRoughnessTexture);
    putTextureSlot(materials[i].clearcoatNormalTexture);
    putTextureSlot(materials[i].sheenColorTexture);
    putTextureSlot(materials[i].sheenRoughnessTexture);

    cursor = LAYOUT_OFFSET_TEXTURES + i * LAYOUT_WORDS_TEXTURE_INFO;
    putUint(textures[i].texelOffset);
    putUint(textures[i].width);
    putUint(textures[i].height);
    putUint(textures[i].samplerBits);

    cursor = LAYOUT_OFFSET_EMITTERS + i * LAYOUT_WORDS_EMITTER;
    putVec3(emitters[i].position);
    putUint(emitters[i].kind);
    putVec3(emitters[i].direction);
    putUint(emitters[i].primitive);
    putVec3(emitters[i].intensity);
    putFloat(emitters[i].range);
    putFloat(emitters[i].area);
    putFloat(emitters[i].selectProbability);
    putFloat(emitters[i].cosInnerCone);
    putFloat(emitters[i].cosOuterCone);

    cursor = LAYOUT_OFFSET_ENVIRONMENTS + i * LAYOUT_WORDS_ENVIRONMENT;
    putEnvironment(environments[i]);

    cursor = LAYOUT_OFFSET_CAMERAS + i * LAYOUT_WORDS_CAMERA;
    putCamera(cameras[i]);

    cursor = LAYOUT_OFFSET_FRAME_PARAMS + i * LAYOUT_WORDS_FRAME_PARAMS;
    putFrameParams(frames[i]);

    cursor = LAYOUT_OFFSET_PATH_STATES + i * LAYOUT_WORDS_PATH_STATE;
    putVec3(pathStates[i].throughput);
    putUint(pathStates[i].pixel);
    putVec3(pathStates[i].radiance);
    putUint(pathStates[i].sampleIndex);
    putVec3(pathStates[i].lightScale);
    putFloat(pathStates[i].previousBsdfPdf);
    putVec3(pathStates[i].mediumCoefficient);
    putFloat(pathStates[i].wavelength);

    cursor = LAYOUT_OFFSET_SHADOW_RAYS + i * LAYOUT_WORDS_SHADOW_RAY;
    putVec3(shadowRays[i].origin);
    putUint(shadowRays[i].flags);
    putVec3(shadowRays[i].direction);
    putFloat(shadowRays[i].tMax);
    putVec3(shadowRays[i].contribution);
    putFloat(shadowRays[i].factor);

    cursor = LAYOUT_OFFSET_PIXEL_STATES + i * LAYOUT_WORDS_PIXEL_STATE;
    putVec3(pixelStates[i].radianceSum);
    putUint(pixelStates[i].count);
    putVec3(pixelStates[i].compensation);
    putUint(pixelStates[i].samplesTaken);
    putFloat(pixelStates[i].luminanceMean);
    putFloat(pixelStates[i].luminanceM2);
    putUint(pixelStates[i].converged);
    putUint(pixelStates[i].unused0);
    putVec3(pixelStates[i].evenMean);
    putUint(pixelStates[i].evenCount);
    putVec3(pixelStates[i].oddMean);
    putUint(pixelStates[i].oddCount);

    cursor = LAYOUT_OFFSET_LIGHT_TREE_NODES + i * LAYOUT_WORDS_LIGHT_TREE_NODE;
    putVec3(lightTreeNodes[i].boundsMin);
    putFloat(lightTreeNodes[i].power);
    putVec3(lightTreeNodes[i].boundsMax);
    putFloat(lightTreeNodes[i].cosThetaO);
    putVec3(lightTreeNodes[i].axis);
    putFloat(lightTreeNodes[i].cosThetaE);
    putUint(lightTreeNodes[i].child0);
    putUint(lightTreeNodes[i].child1);
    putUint(lightTreeNodes[i].parent);
    putUint(lightTreeNodes[i].flags);

    cursor = LAYOUT_OFFSET_SPECULAR_LOBES + i * LAYOUT_WORDS_SPECULAR_LOBES;
    putTextureSlot(specularLobes[i].specularTexture);
    putTextureSlot(specularLobes[i].specularColorTexture);
    putFloat(specularLobes[i].anisotropyStrength);
    putFloat(specularLobes[i].anisotropyRotationCos);
    putFloat(specularLobes[i].anisotropyRotationSin);
    putUint(specularLobes[i].anisotropyUnused);
    putTextureSlot(specularLobes[i].anisotropyTexture);
    putFloat(specularLobes[i].iridescence);
    putFloat(specularLobes[i].iridescenceIor);
    putFloat(specularLobes[i].iridescenceThicknessMinimum);
    putFloat(specularLobes[i].iridescenceThicknessMaximum);
    putTextureSlot(specularLobes[i].iridescenceTexture);
    putTextureSlot(specularLobes[i].iridescenceThicknessTexture);
    cursor = LAYOUT_OFFSET_MATERIAL_LOBES + i * LAYOUT_WORDS_MATERIAL_LOBES;
    putVec3(materialLobes[i].diffuseTransmissionColor);
    putFloat(materialLobes[i].diffuseTransmission);
    putFloat(materialLobes[i].dispersion);
    putUint(materialLobes[i].unused0);
    putUint(materialLobes[i].unused1);
    putUint(materialLobes[i].unused2);
    putTextureSlot(materialLobes[i].diffuseTransmissionTexture);
    putTextureSlot(materialLobes[i].diffuseTransmissionColorTexture);
}
