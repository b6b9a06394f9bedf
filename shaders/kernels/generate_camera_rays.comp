// generate_camera_rays.comp — the first stage of a pass: one camera ray per path slot, slot =
// (active pixel of the chunk) · k + (sample j of the pass), into half 0 of the ray queue.
#version 460
#extension GL_GOOGLE_include_directive : require
#include "lib/aovs.glsl"
#include "lib/features.glsl"
#include "lib/frame.glsl"
#include "shared/camera.h"
#include "shared/sampler.h"

layout(local_size_x = WORKGROUP_SIZE) in;

#include "lib/kernel_bindings.h"

VKPT_DECLARE_BUFFERS(GENERATE_CAMERA_RAYS_BINDINGS)

uint activePixel(uint activeIndex) {
    if (passParams.useActiveList == 0u) return activeIndex;
    return activePixels[passParams.activeParity * frame.pixelCount + activeIndex];
}

void main() {
    uint slot = flatInvocationIndex();
    uint k = passParams.samplesPerPass;
    uint slots = passParams.chunkPixels * k;
    if (slot >= slots) return;
    uint pixel = activePixel(passParams.chunkStart + slot / k);
    uint sampleIndex = passParams.sampleBase + slot % k;
    uint x = pixel % frame.camera.width;
    uint y = pixel / frame.camera.width;
    // The reference's camera sample (docs/integrator.md): a one-pixel box filter.
    vec4 jitter = sampleFloats(frame.samplerSetup, frame.camera.width, frame.seed, pixel,
                               sampleIndex, 0u, DIM_CAMERA);
    vec2 film = vec2(float(x) + jitter.x, float(y) + jitter.y);
    vec3 direction = cameraRayDirection(frame.camera, film);
    pathStates[slot].throughput = vec3(1.0);
    pathStates[slot].pixel = pixel;
    pathStates[slot].radiance = vec3(0.0);
    pathStates[slot].sampleIndex = sampleIndex;
    pathStates[slot].lightScale = vec3(0.0);
    pathStates[slot].previousBsdfPdf = 0.0;
    // Paths start outside every volume (shared/volume.h).
    if (featureTransmission) pathStates[slot].mediumCoefficient = vec3(0.0);
    // Paths carry no wavelength until they meet dispersive glass (shared/dispersion.h).
    if (featureDispersion) pathStates[slot].wavelength = VKPT_NO_WAVELENGTH;
    // A sample whose camera ray misses keeps these; shade_hits overwrites them at a hit.
    if (renderAovs()) sampleFeatures[slot] = missFeatures();
    rays[slot] = RayRecord(cameraRayOrigin(frame.camera, film), slot, direction, 0u);
    if (slot == 0u) queueCounters[COUNTER_RAYS] = slots;
}
