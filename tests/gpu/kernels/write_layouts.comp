// write_layouts.comp — the reverse of read_layouts: takes 32-bit words in declaration order and
// stores them field by field through the GLSL declarations, so the host can compare the bytes
// with its C++ layout.
#version 460
#extension GL_GOOGLE_include_directive : require
#include "kernel_test_io.h"
#include "lib/buffers.glsl"
#include "shared/host_device.h"

layout(local_size_x = WORKGROUP_SIZE) in;

VKPT_WRITEONLY_BUFFER(0, WideBvhNode, bvhNodes)
VKPT_WRITEONLY_BUFFER(1, Triangle, triangles)
VKPT_WRITEONLY_BUFFER(2, TriangleNormals, triangleNormals)
VKPT_WRITEONLY_BUFFER(3, Material, materials)
VKPT_WRITEONLY_BUFFER(4, TextureInfo, textures)
VKPT_WRITEONLY_BUFFER(5, Emitter, emitters)
VKPT_WRITEONLY_BUFFER(6, EnvironmentParams, environments)
VKPT_WRITEONLY_BUFFER(7, Camera, cameras)
VKPT_READONLY_BUFFER(8, uint, words)
VKPT_WRITEONLY_BUFFER(9, FrameParams, frames)
VKPT_WRITEONLY_BUFFER(10, PathState, pathStates)
VKPT_WRITEONLY_BUFFER(11, ShadowRay, shadowRays)
VKPT_WRITEONLY_BUFFER(12, PixelState, pixelStates)
VKPT_WRITEONLY_BUFFER(13, LightTreeNode, lightTreeNodes)
VKPT_WRITEONLY_BUFFER(14, SpecularLobeParams, specularLobes)
VKPT_WRITEONLY_BUFFER(15, MaterialLobes, materialLobes)

uint cursor;

uint takeUint() {
    cursor += 1u;
    return words[cursor - 1u];
}
float takeFloat() {
    return uintBitsToFloat(takeUint());
}
vec3 takeVec3() {
    float x = takeFloat();
    float y = takeFloat();
    float z = takeFloat();
    return vec3(x, y, z);
}
vec4 takeVec4() {
    vec3 xyz = takeVec3();
    return vec4(xyz, takeFloat());
}

uvec4 takeUvec4() {
    uint x = takeUint();
    uint y = takeUint();
    uint z = takeUint();
    return uvec4(x, y, z, takeUint());
}

TextureSlot takeTextureSlot() {
    TextureSlot slot;
    slot.transformRow0 = takeVec3();
    slot.texture = takeUint();
    slot.transformRow1 = takeVec3();
    slot.unused0 = takeUint();
    return slot;
}

Camera takeCamera() {
    Camera camera;
    camera.position = takeVec3();
    camera.tanHalfFovY = takeFloat();
    camera.right = takeVec3();
    camera.aspect = takeFloat();
    camera.up = takeVec3();
    camera.width = takeUint();
    camera.forward = takeVec3();
    camera.height = takeUint();
    camera.projection = takeUint();
    camera.orthoHalfHeight = takeFloat();
    camera.unused0 = takeUint();
    camera.unused1 = takeUint();
    return camera;
}

EnvironmentParams takeEnvironment() {
    EnvironmentParams environment;
    environment.radiance = takeVec3();
    environment.width = takeUint();
    environment.height = takeUint();
    environment.emitterIndex = takeUint();
    environment.unused0 = takeUint();
    environment.unused1 = takeUint();
    return environment;
}

FrameParams takeFrameParams() {
    FrameParams frame;
    frame.camera = takeCamera();
    frame.seed = takeUint();
    frame.maxDepth = takeUint();
    frame.rrStartDepth = takeUint();
    frame.lightSamples = takeUint();
    frame.integrator = takeUint();
    frame.pathFilter = takeUint();
    frame.emitterCount = takeUint();
    frame.adaptive = takeUint();
    frame.adaptiveBatch = takeUint();
    frame.adaptiveMinSamples = takeUint();
    frame.adaptiveTolerance = takeFloat();
    frame.adaptiveDarkFloor = takeFloat();
    frame.slotCount = takeUint();
    frame.pixelCount = takeUint();
    frame.samplerSetup = takeUint();
    frame.sampleClamp = takeFloat();
    frame.environment = takeEnvironment();
    return frame;
}

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= LAYOUT_COUNT) return;

    cursor = LAYOUT_OFFSET_BVH_NODES + i * LAYOUT_WORDS_BVH_NODE;
    bvhNodes[i].childBase = takeUint();
    bvhNodes[i].parent = takeUint();
    bvhNodes[i].slotsAndExponents = takeUint();
    bvhNodes[i].primitiveBase = takeUint();
    bvhNodes[i].origin = takeVec3();
    bvhNodes[i].leafCounts = takeUint();
    bvhNodes[i].quantised[0] = takeUvec4();
    bvhNodes[i].quantised[1] = takeUvec4();
    bvhNodes[i].quantised[2] = takeUvec4();

    cursor = LAYOUT_OFFSET_TRIANGLES + i * LAYOUT_WORDS_TRIANGLE;
    triangles[i].v0 = takeVec3();
    triangles[i].materialIndex = takeUint();
    triangles[i].v1 = takeVec3();
    triangles[i].emitterIndex = takeUint();
    triangles[i].v2 = takeVec3();
    triangles[i].sourceIndex = takeUint();

    cursor = LAYOUT_OFFSET_TRIANGLE_NORMALS + i * LAYOUT_WORDS_TRIANGLE_NORMALS;
    triangleNormals[i].n0 = takeVec4();
    triangleNormals[i].n1 = takeVec4();
    triangleNormals[i].n2 = takeVec4();

    cursor = LAYOUT_OFFSET_MATERIALS + i * LAYOUT_WORDS_MATERIAL;
    materials[i].baseColor = takeVec4();
    materials[i].emission = takeVec3();
    materials[i].flags = takeUint();
    materials[i].metallic = takeFloat();
    materials[i].roughness = takeFloat();
    materials[i].alphaCutoff = takeFloat();
    materials[i].alphaMode = takeUint();
    materials[i].specularColor = takeVec3();
    materials[i].specular = takeFloat();
    materials[i].baseColorTexture = takeTextureSlot();
    materials[i].metallicRoughnessTexture = takeTextureSlot();
    materials[i].emissiveTexture = takeTextureSlot();
    materials[i].normalTexture = takeTextureSlot();
    materials[i].normalScale = takeFloat();
    materials[i].normalUnused0 = takeUint();
    materials[i].normalUnused1 = takeUint();
    materials[i].normalUnused2 = takeUint();
    materials[i].transmission = takeFloat();
    materials[i].ior = takeFloat();
    materials[i].iorF0 = takeFloat();
    materials[i].thickness = takeFloat();
    materials[i].attenuationCoefficient = takeVec3();
    materials[i].unusedVolume = takeUint();
    materials[i].transmissionTexture = takeTextureSlot();
    materials[i].sheenColor = takeVec3();
    materials[i].sheenRoughness = takeFloat();
    materials[i].clearcoat = takeFloat();
    materials[i].clearcoatRoughness = takeFloat();
    materials[i].clearcoatNormalScale = takeFloat();
    materials[i].layersUnused = takeUint();
    materials[i].clearcoatTexture = takeTextureSlot();
    materials[i].clearcoatRoughnessTexture = takeTextureSlot();
    materials[i].clearcoatNormalTexture = takeTextureSlot();
    materials[i].sheenColorTexture = takeTextureSlot();
    materials[i].sheenRoughnessTexture = takeTextureSlot();

    cursor = LAYOUT_OFFSET_TEXTURES + i * LAYOUT_WORDS_TEXTURE_INFO;
    textures[i].texelOffset = takeUint();
    textures[i].width = takeUint();
    textures[i].height = takeUint();
    textures[i].samplerBits = takeUint();

    cursor = LAYOUT_OFFSET_EMITTERS + i * LAYOUT_WORDS_EMITTER;
    emitters[i].position = takeVec3();
    emitters[i].kind = takeUint();
    emitters[i].direction = takeVec3();
    emitters[i].primitive = takeUint();
    emitters[i].intensity = takeVec3();
    emitters[i].range = takeFloat();
    emitters[i].area = takeFloat();
    emitters[i].selectProbability = takeFloat();
    emitters[i].cosInnerCone = takeFloat();
    emitters[i].cosOuterCone = takeFloat();

    cursor = LAYOUT_OFFSET_ENVIRONMENTS + i * LAYOUT_WORDS_ENVIRONMENT;
    environments[i] = takeEnvironment();

    cursor = LAYOUT_OFFSET_CAMERAS + i * LAYOUT_WORDS_CAMERA;
    cameras[i] = takeCamera();

    cursor = LAYOUT_OFFSET_FRAME_PARAMS + i * LAYOUT_WORDS_FRAME_PARAMS;
    frames[i] = takeFrameParams();

    cursor = LAYOUT_OFFSET_PATH_STATES + i * LAYOUT_WORDS_PATH_STATE;
    pathStates[i].throughput = takeVec3();
    pathStates[i].pixel = takeUint();
    pathStates[i].radiance = takeVec3();
    pathStates[i].sampleIndex = takeUint();
    pathStates[i].lightScale = takeVec3();
    pathStates[i].previousBsdfPdf = takeFloat();
    pathStates[i].mediumCoefficient = takeVec3();
    pathStates[i].wavelength = takeFloat();

    cursor = LAYOUT_OFFSET_SHADOW_RAYS + i * LAYOUT_WORDS_SHADOW_RAY;
    shadowRays[i].origin = takeVec3();
    shadowRays[i].flags = takeUint();
    shadowRays[i].direction = takeVec3();
    shadowRays[i].tMax = takeFloat();
    shadowRays[i].contribution = takeVec3();
    shadowRays[i].factor = takeFloat();

    cursor = LAYOUT_OFFSET_PIXEL_STATES + i * LAYOUT_WORDS_PIXEL_STATE;
    pixelStates[i].radianceSum = takeVec3();
    pixelStates[i].count = takeUint();
    pixelStates[i].compensation = takeVec3();
    pixelStates[i].samplesTaken = takeUint();
    pixelStates[i].luminanceMean = takeFloat();
    pixelStates[i].luminanceM2 = takeFloat();
    pixelStates[i].converged = takeUint();
    pixelStates[i].unused0 = takeUint();
    pixelStates[i].evenMean = takeVec3();
    pixelStates[i].evenCount = takeUint();
    pixelStates[i].oddMean = takeVec3();
    pixelStates[i].oddCount = takeUint();

    cursor = LAYOUT_OFFSET_LIGHT_TREE_NODES + i * LAYOUT_WORDS_LIGHT_TREE_NODE;
    lightTreeNodes[i].boundsMin = takeVec3();
    lightTreeNodes[i].power = takeFloat();
    lightTreeNodes[i].boundsMax = takeVec3();
    lightTreeNodes[i].cosThetaO = takeFloat();
    lightTreeNodes[i].axis = takeVec3();
    lightTreeNodes[i].cosThetaE = takeFloat();
    lightTreeNodes[i].child0 = takeUint();
    lightTreeNodes[i].child1 = takeUint();
    lightTreeNodes[i].parent = takeUint();
    lightTreeNodes[i].flags = takeUint();

    cursor = LAYOUT_OFFSET_SPECULAR_LOBES + i * LAYOUT_WORDS_SPECULAR_LOBES;
    specularLobes[i].specularTexture = takeTextureSlot();
    specularLobes[i].specularColorTexture = takeTextureSlot();
    specularLobes[i].anisotropyStrength = takeFloat();
    specularLobes[i].anisotropyRotationCos = takeFloat();
    specularLobes[i].anisotropyRotationSin = takeFloat();
    specularLobes[i].anisotropyUnused = takeUint();
    specularLobes[i].anisotropyTexture = takeTextureSlot();
    specularLobes[i].iridescence = takeFloat();
    specularLobes[i].iridescenceIor = takeFloat();
    specularLobes[i].iridescenceThicknessMinimum = takeFloat();
    specularLobes[i].iridescenceThicknessMaximum = takeFloat();
    specularLobes[i].iridescenceTexture = takeTextureSlot();
    specularLobes[i].iridescenceThicknessTexture = takeTextureSlot();
    cursor = LAYOUT_OFFSET_MATERIAL_LOBES + i * LAYOUT_WORDS_MATERIAL_LOBES;
    materialLobes[i].diffuseTransmissionColor = takeVec3();
    materialLobes[i].diffuseTransmission = takeFloat();
    materialLobes[i].dispersion = takeFloat();
    materialLobes[i].unused0 = takeUint();
    materialLobes[i].unused1 = takeUint();
    materialLobes[i].unused2 = takeUint();
    materialLobes[i].diffuseTransmissionTexture = takeTextureSlot();
    materialLobes[i].diffuseTransmissionColorTexture = takeTextureSlot();
}
