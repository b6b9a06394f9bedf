// texture_sampling.h — reading a material's textures: the KHR_texture_transform of the
// coordinates, the glTF sampler's wrap modes, nearest or bilinear filtering and sRGB decoding.
// Texels are RGBA8 packed one per uint (R in the low byte) in one array, each texture a
// row-major block at texelOffset with row 0 at v = 0 (host_device.h, TextureInfo).
//
// Texels are read one at a time through sceneTextureTexel (scene_view.h): a span of the
// SceneView on the C++ side, the kernels' textureTexels array, which may be split across
// several buffers, on the GLSL side (lib/scene_view.glsl).
#ifndef VKPT_TEXTURE_SAMPLING_H
#define VKPT_TEXTURE_SAMPLING_H

#include "host_device.h"
#include "scene_view.h"

#ifdef __cplusplus
namespace vkpt::gpu {
#endif

// uv' = M·(u, v, 1) with M = T·R·S (KHR_texture_transform), of which the slot keeps the two
// rows that matter.
VKPT_FN vec2 transformUv(TextureSlot slot, vec2 uv) {
    vec3 homogeneous = vec3(uv, 1.0f);
    return vec2(dot(slot.transformRow0, homogeneous), dot(slot.transformRow1, homogeneous));
}

// As GLSL's unpackUnorm4x8: R from the low byte, each byte / 255.
VKPT_FN vec4 unpackTexel(uint packed) {
    return vec4(float(packed & 0xffu), float((packed >> 8u) & 0xffu),
                float((packed >> 16u) & 0xffu), float(packed >> 24u)) /
           255.0f;
}

// The sRGB EOTF (IEC 61966-2-1): linear below 0.04045, a 2.4 power above.
VKPT_FN float srgbChannelToLinear(float c) {
    return c <= 0.04045f ? c / 12.92f : pow((c + 0.055f) / 1.055f, 2.4f);
}

VKPT_FN vec3 srgbToLinear(vec3 c) {
    return vec3(srgbChannelToLinear(c.x), srgbChannelToLinear(c.y), srgbChannelToLinear(c.z));
}

// A texel index, any int, brought into [0, size) by a TEXTURE_WRAP_* mode (Vulkan's REPEAT,
// CLAMP_TO_EDGE and MIRRORED_REPEAT). GLSL leaves % of negative operands undefined, so a
// negative index is reflected first: i < 0 lies (−i − 1) mod p steps below p − 1.
VKPT_FN int wrapTexelIndex(int i, int size, uint wrap) {
    if (size <= 0) return 0;
    if (wrap == TEXTURE_WRAP_CLAMP) return clamp(i, 0, size - 1);
    int period = wrap == TEXTURE_WRAP_MIRROR ? 2 * size : size;
    int m = i >= 0 ? i % period : period - 1 - (-(i + 1)) % period;
    return m < size ? m : period - 1 - m;
}

// A coordinate brought within one wrap period of [0, 1] before it becomes a texel index, so
// that uv = 1e6 or −1e9 cannot overflow an int. x − floor(x) is exact wherever a float still
// resolves texels; beyond that the texel is as arbitrary as the coordinate.
VKPT_FN float reduceTextureCoordinate(float x, uint wrap) {
    if (wrap == TEXTURE_WRAP_REPEAT) return x - floor(x);
    if (wrap == TEXTURE_WRAP_MIRROR) return x - 2.0f * floor(0.5f * x);
    return clamp(x, -1.0f, 2.0f);
}

// TextureInfo's sampler word: wrapS | wrapT << 2 | TEXTURE_FILTER_NEAREST.
VKPT_FN uint textureSamplerBits(TextureInfo info) {
    return info.samplerBits;
}
VKPT_FN uint textureWrapS(TextureInfo info) {
    return textureSamplerBits(info) & 3u;
}
VKPT_FN uint textureWrapT(TextureInfo info) {
    return (textureSamplerBits(info) >> 2u) & 3u;
}
VKPT_FN bool textureNearest(TextureInfo info) {
    return (textureSamplerBits(info) & TEXTURE_FILTER_NEAREST) != 0u;
}

// One texel, decoded: sRGB colour channels to linear, alpha always linear (glTF 2.0, 3.9.2).
VKPT_FN vec4 fetchTexel(TextureInfo info, int x, int y, bool srgb VKPT_SCENE_PARAM) {
    vec4 c = unpackTexel(
        sceneTextureTexel(info.texelOffset + uint(y) * info.width + uint(x) VKPT_SCENE_ARG));
    return srgb ? vec4(srgbToLinear(vec3(c)), c.w) : c;
}

// Texel centres at ((i + 0.5)/width, (j + 0.5)/height); bilinear between the four nearest
// centres unless the sampler asks for TEXTURE_FILTER_NEAREST. sRGB texels are decoded before
// they are filtered, as a GPU's sRGB formats do. A NaN or infinite coordinate reads texel
// (0, 0); a texture without texels reads as white (the factor alone).
VKPT_FN vec4 sampleTexture(TextureInfo info, vec2 uv, bool srgb VKPT_SCENE_PARAM) {
    int width = int(info.width);
    int height = int(info.height);
    if (width <= 0 || height <= 0) return vec4(1.0f);
    if (isnan(uv.x) || isnan(uv.y) || isinf(uv.x) || isinf(uv.y))
        return fetchTexel(info, 0, 0, srgb VKPT_SCENE_ARG);
    uint wrapS = textureWrapS(info);
    uint wrapT = textureWrapT(info);
    float s = reduceTextureCoordinate(uv.x, wrapS) * float(width);
    float t = reduceTextureCoordinate(uv.y, wrapT) * float(height);
    if (textureNearest(info)) {
        int x = wrapTexelIndex(int(floor(s)), width, wrapS);
        int y = wrapTexelIndex(int(floor(t)), height, wrapT);
        return fetchTexel(info, x, y, srgb VKPT_SCENE_ARG);
    }
    float sLow = floor(s - 0.5f);
    float tLow = floor(t - 0.5f);
    float ws = s - 0.5f - sLow;
    float wt = t - 0.5f - tLow;
    int x0 = wrapTexelIndex(int(sLow), width, wrapS);
    int x1 = wrapTexelIndex(int(sLow) + 1, width, wrapS);
    int y0 = wrapTexelIndex(int(tLow), height, wrapT);
    int y1 = wrapTexelIndex(int(tLow) + 1, height, wrapT);
    vec4 top = mix(fetchTexel(info, x0, y0, srgb VKPT_SCENE_ARG),
                   fetchTexel(info, x1, y0, srgb VKPT_SCENE_ARG), ws);
    vec4 bottom = mix(fetchTexel(info, x0, y1, srgb VKPT_SCENE_ARG),
                      fetchTexel(info, x1, y1, srgb VKPT_SCENE_ARG), ws);
    return mix(top, bottom, wt);
}

#ifdef __cplusplus
} // namespace vkpt::gpu
#endif

#endif // VKPT_TEXTURE_SAMPLING_H
