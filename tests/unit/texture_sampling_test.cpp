// texture_sampling_test.cpp — shared/texture_sampling.h: texel unpacking, the sRGB curve, wrap
// modes, nearest and bilinear filtering against hand-computed values, coordinates far outside
// [0, 1] or not finite, and the KHR_texture_transform rows.
#include <climits>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "shared/texture_sampling.h"

namespace vkpt::texture_sampling_test {
namespace {

using glm::vec2;
using glm::vec3;
using glm::vec4;

std::uint32_t packTexel(unsigned r, unsigned g, unsigned b, unsigned a) {
    return r | (g << 8u) | (b << 16u) | (a << 24u);
}

gpu::TextureInfo textureInfo(std::uint32_t offset, std::uint32_t width, std::uint32_t height,
                             std::uint32_t wrapS, std::uint32_t wrapT, bool nearest) {
    return {offset, width, height, wrapS | (wrapT << 2u) | (nearest ? TEXTURE_FILTER_NEAREST : 0u)};
}

// The shared code reads texels through a SceneView; these tests need nothing else in it.
gpu::SceneView texelView(const std::vector<std::uint32_t>& texels) {
    gpu::SceneView view{};
    view.texels = texels;
    return view;
}

void expectColour(vec4 actual, vec4 expected, float tolerance = 1e-6f) {
    for (int c = 0; c < 4; ++c)
        EXPECT_NEAR(actual[c], expected[c], tolerance) << "channel " << c;
}

TEST(TextureSampling, UnpacksRedFromTheLowByte) {
    expectColour(gpu::unpackTexel(0x04030201u), vec4(1.0f, 2.0f, 3.0f, 4.0f) / 255.0f, 0.0f);
    EXPECT_EQ(gpu::unpackTexel(0xff000000u), vec4(0.0f, 0.0f, 0.0f, 1.0f));
    EXPECT_EQ(gpu::unpackTexel(0x000000ffu), vec4(1.0f, 0.0f, 0.0f, 0.0f));
}

// IEC 61966-2-1: the two pieces meet at 0.04045 (0.04045 / 12.92 = 0.0031308).
TEST(TextureSampling, SrgbDecodesKnownPoints) {
    EXPECT_EQ(gpu::srgbChannelToLinear(0.0f), 0.0f);
    EXPECT_NEAR(gpu::srgbChannelToLinear(0.04045f), 0.0031308f, 1e-7f);
    EXPECT_NEAR(gpu::srgbChannelToLinear(0.5f), 0.21404f, 1e-5f);
    EXPECT_NEAR(gpu::srgbChannelToLinear(1.0f), 1.0f, 1e-6f);
    EXPECT_NEAR(gpu::srgbChannelToLinear(0.04046f), gpu::srgbChannelToLinear(0.04045f), 1e-6f);
    vec3 c = gpu::srgbToLinear(vec3(0.0f, 0.5f, 1.0f));
    EXPECT_NEAR(c.y, 0.21404f, 1e-5f);
    EXPECT_NEAR(c.z, 1.0f, 1e-6f);
}

// The reference: floor modulo in 64-bit arithmetic.
int referenceWrap(long long i, long long size, std::uint32_t wrap) {
    if (wrap == TEXTURE_WRAP_CLAMP) return int(std::min(std::max(i, 0ll), size - 1));
    long long period = wrap == TEXTURE_WRAP_MIRROR ? 2 * size : size;
    long long m = ((i % period) + period) % period;
    return int(m < size ? m : period - 1 - m);
}

TEST(TextureSampling, WrapModesMatchVulkanIncludingNegativeIndices) {
    // Hand-written: size 4.
    EXPECT_EQ(gpu::wrapTexelIndex(-1, 4, TEXTURE_WRAP_REPEAT), 3);
    EXPECT_EQ(gpu::wrapTexelIndex(-4, 4, TEXTURE_WRAP_REPEAT), 0);
    EXPECT_EQ(gpu::wrapTexelIndex(-5, 4, TEXTURE_WRAP_REPEAT), 3);
    EXPECT_EQ(gpu::wrapTexelIndex(9, 4, TEXTURE_WRAP_REPEAT), 1);
    EXPECT_EQ(gpu::wrapTexelIndex(-3, 4, TEXTURE_WRAP_CLAMP), 0);
    EXPECT_EQ(gpu::wrapTexelIndex(7, 4, TEXTURE_WRAP_CLAMP), 3);
    const int mirrored[] = {0, 1, 2, 3, 3, 2, 1, 0, 0, 1}; // i = 0 .. 9
    for (int i = 0; i < 10; ++i)
        EXPECT_EQ(gpu::wrapTexelIndex(i, 4, TEXTURE_WRAP_MIRROR), mirrored[i]);
    const int mirroredBelow[] = {0, 1, 2, 3, 3, 2}; // i = −1 .. −6
    for (int i = 0; i < 6; ++i)
        EXPECT_EQ(gpu::wrapTexelIndex(-1 - i, 4, TEXTURE_WRAP_MIRROR), mirroredBelow[i]);
    for (std::uint32_t wrap : {TEXTURE_WRAP_REPEAT, TEXTURE_WRAP_CLAMP, TEXTURE_WRAP_MIRROR})
        for (int size : {1, 3, 4, 1000})
            for (long long i : {-100000ll, -2001ll, -7ll, -1ll, 0ll, 5ll, 1999ll, 100001ll,
                                (long long)INT_MAX, (long long)INT_MIN})
                EXPECT_EQ(gpu::wrapTexelIndex(int(i), size, wrap), referenceWrap(i, size, wrap))
                    << "i " << i << " size " << size << " wrap " << wrap;
}

// A 2 × 2 linear texture with red values 0, 40 / 80, 120 (row 0 at v = 0), alpha 255.
class TwoByTwo : public ::testing::Test {
protected:
    std::vector<std::uint32_t> texels{packTexel(0, 0, 0, 255), packTexel(40, 0, 0, 255),
                                      packTexel(80, 0, 0, 255), packTexel(120, 0, 0, 255)};

    float red(vec2 uv, std::uint32_t wrap, bool nearest) {
        return gpu::sampleTexture(textureInfo(0, 2, 2, wrap, wrap, nearest), uv, false,
                                  texelView(texels))
                   .x *
               255.0f;
    }
};

TEST_F(TwoByTwo, NearestReadsTheTexelContainingTheCoordinate) {
    EXPECT_NEAR(red(vec2(0.25f, 0.25f), TEXTURE_WRAP_REPEAT, true), 0.0f, 1e-4f);
    EXPECT_NEAR(red(vec2(0.74f, 0.1f), TEXTURE_WRAP_REPEAT, true), 40.0f, 1e-4f);
    EXPECT_NEAR(red(vec2(0.1f, 0.9f), TEXTURE_WRAP_REPEAT, true), 80.0f, 1e-4f);
    EXPECT_NEAR(red(vec2(0.6f, 0.6f), TEXTURE_WRAP_REPEAT, true), 120.0f, 1e-4f);
    EXPECT_NEAR(red(vec2(1.25f, -0.75f), TEXTURE_WRAP_REPEAT, true), 0.0f, 1e-4f);
    EXPECT_NEAR(red(vec2(-0.25f, 0.25f), TEXTURE_WRAP_MIRROR, true), 0.0f, 1e-4f);
    EXPECT_NEAR(red(vec2(-0.75f, 0.25f), TEXTURE_WRAP_MIRROR, true), 40.0f, 1e-4f);
    EXPECT_NEAR(red(vec2(5.0f, 0.25f), TEXTURE_WRAP_CLAMP, true), 40.0f, 1e-4f);
}

TEST_F(TwoByTwo, BilinearInterpolatesBetweenTexelCentres) {
    // Texel centres at 0.25 and 0.75.
    EXPECT_NEAR(red(vec2(0.25f, 0.25f), TEXTURE_WRAP_REPEAT, false), 0.0f, 1e-4f);
    EXPECT_NEAR(red(vec2(0.75f, 0.75f), TEXTURE_WRAP_REPEAT, false), 120.0f, 1e-4f);
    EXPECT_NEAR(red(vec2(0.5f, 0.25f), TEXTURE_WRAP_REPEAT, false), 20.0f, 1e-4f);
    EXPECT_NEAR(red(vec2(0.5f, 0.5f), TEXTURE_WRAP_REPEAT, false), 60.0f, 1e-4f);
    // (0.375, 0.625): a quarter of the way from centre 0 to centre 1 in s, three quarters in t:
    // rows 0.75·0 + 0.25·40 = 10 and 0.75·80 + 0.25·120 = 90, then 0.25·10 + 0.75·90.
    EXPECT_NEAR(red(vec2(0.375f, 0.625f), TEXTURE_WRAP_REPEAT, false),
                0.25f * 10.0f + 0.75f * 90.0f, 1e-4f);
    // At u = 0 repeat blends the last column with the first; clamp keeps the first.
    EXPECT_NEAR(red(vec2(0.0f, 0.25f), TEXTURE_WRAP_REPEAT, false), 20.0f, 1e-4f);
    EXPECT_NEAR(red(vec2(0.0f, 0.25f), TEXTURE_WRAP_CLAMP, false), 0.0f, 1e-4f);
    // Mirror: u = 0 reflects the first column onto itself.
    EXPECT_NEAR(red(vec2(0.0f, 0.25f), TEXTURE_WRAP_MIRROR, false), 0.0f, 1e-4f);
    EXPECT_NEAR(red(vec2(1.0f, 0.25f), TEXTURE_WRAP_MIRROR, false), 40.0f, 1e-4f);
}

TEST_F(TwoByTwo, CoordinatesFarOutsideTheUnitSquareWrapWithoutOverflow) {
    EXPECT_NEAR(red(vec2(1e6f + 0.25f, 0.25f), TEXTURE_WRAP_REPEAT, true), 0.0f, 1e-4f);
    EXPECT_NEAR(red(vec2(-1e6f + 0.75f, 0.25f), TEXTURE_WRAP_REPEAT, true), 40.0f, 1e-4f);
    EXPECT_NEAR(red(vec2(1e6f + 0.5f, 0.25f), TEXTURE_WRAP_REPEAT, false), 20.0f, 1e-4f);
    EXPECT_NEAR(red(vec2(-1e6f + 0.75f, 0.25f), TEXTURE_WRAP_MIRROR, true), 40.0f, 1e-4f);
    EXPECT_NEAR(red(vec2(3e9f, -3e9f), TEXTURE_WRAP_CLAMP, true), 40.0f, 1e-4f);
    for (std::uint32_t wrap : {TEXTURE_WRAP_REPEAT, TEXTURE_WRAP_CLAMP, TEXTURE_WRAP_MIRROR})
        for (float x : {1e30f, -1e30f, 3e38f, -1e-30f, 16777217.0f}) {
            float r = red(vec2(x, -x), wrap, false);
            EXPECT_TRUE(r >= 0.0f && r <= 120.0f) << x << " wrap " << wrap;
        }
}

TEST_F(TwoByTwo, NanOrInfiniteCoordinatesReadTexelZero) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    texels[0] = packTexel(7, 0, 0, 255);
    for (bool nearest : {true, false}) {
        EXPECT_NEAR(red(vec2(nan, 0.75f), TEXTURE_WRAP_REPEAT, nearest), 7.0f, 1e-4f);
        EXPECT_NEAR(red(vec2(0.75f, nan), TEXTURE_WRAP_MIRROR, nearest), 7.0f, 1e-4f);
        EXPECT_NEAR(red(vec2(inf, 0.75f), TEXTURE_WRAP_CLAMP, nearest), 7.0f, 1e-4f);
        EXPECT_NEAR(red(vec2(0.75f, -inf), TEXTURE_WRAP_REPEAT, nearest), 7.0f, 1e-4f);
    }
}

// Texels are decoded before filtering: halfway between sRGB 0 and 255 is linear 0.5, not the
// decoded 0.5 (0.214); alpha is linear and unaffected by srgb.
TEST(TextureSampling, SrgbTexelsAreDecodedBeforeFiltering) {
    const std::vector<std::uint32_t> texels{packTexel(0, 128, 0, 0), packTexel(255, 128, 0, 255)};
    gpu::TextureInfo info = textureInfo(0, 2, 1, TEXTURE_WRAP_CLAMP, TEXTURE_WRAP_CLAMP, false);
    vec4 middle = gpu::sampleTexture(info, vec2(0.5f, 0.5f), true, texelView(texels));
    EXPECT_NEAR(middle.x, 0.5f, 1e-6f);
    EXPECT_NEAR(middle.y, gpu::srgbChannelToLinear(128.0f / 255.0f), 1e-6f);
    EXPECT_NEAR(middle.w, 0.5f, 1e-6f);
    vec4 linear = gpu::sampleTexture(info, vec2(0.25f, 0.5f), false, texelView(texels));
    EXPECT_NEAR(linear.y, 128.0f / 255.0f, 1e-6f);
    vec4 alphaOnly = gpu::sampleTexture(info, vec2(0.25f, 0.5f), true, texelView(texels));
    EXPECT_EQ(alphaOnly.w, 0.0f);
}

// A texture at an offset in the shared buffer, wider than tall: rows are width apart.
TEST(TextureSampling, ReadsItsOwnBlockOfTheSharedBuffer) {
    std::vector<std::uint32_t> texels(5, packTexel(255, 255, 255, 255));
    for (unsigned i = 0; i < 6; ++i)
        texels.push_back(packTexel(i * 10, 0, 0, 255)); // 3 × 2
    gpu::TextureInfo info = textureInfo(5, 3, 2, TEXTURE_WRAP_REPEAT, TEXTURE_WRAP_REPEAT, true);
    EXPECT_NEAR(gpu::sampleTexture(info, vec2(0.9f, 0.2f), false, texelView(texels)).x * 255.0f,
                20.0f, 1e-4f);
    EXPECT_NEAR(gpu::sampleTexture(info, vec2(0.5f, 0.7f), false, texelView(texels)).x * 255.0f,
                40.0f, 1e-4f);
    EXPECT_EQ(
        gpu::sampleTexture(textureInfo(0, 0, 0, 0, 0, false), vec2(0.5f), true, gpu::SceneView{}),
        vec4(1.0f));
}

// KHR_texture_transform: M = T·R·S with, in GLSL's column-major mat3 constructor,
//   T = mat3(1,0,0, 0,1,0, offset.x,offset.y,1)
//   R = mat3(cos r, sin r, 0, −sin r, cos r, 0, 0,0,1)
//   S = mat3(scale.x,0,0, 0,scale.y,0, 0,0,1);
// the slot keeps M's first two rows and transformUv applies them to (u, v, 1).
gpu::TextureSlot slotOf(vec2 offset, float rotation, vec2 scale) {
    glm::mat3 t(1, 0, 0, 0, 1, 0, offset.x, offset.y, 1);
    glm::mat3 r(std::cos(rotation), std::sin(rotation), 0, -std::sin(rotation), std::cos(rotation),
                0, 0, 0, 1);
    glm::mat3 s(scale.x, 0, 0, 0, scale.y, 0, 0, 0, 1);
    glm::mat3 m = t * r * s;
    gpu::TextureSlot slot{};
    slot.transformRow0 = vec3(m[0][0], m[1][0], m[2][0]);
    slot.transformRow1 = vec3(m[0][1], m[1][1], m[2][1]);
    slot.texture = 0;
    return slot;
}

TEST(TextureSampling, TransformAppliesTheTextureTransformRows) {
    vec2 uv(0.3f, 0.7f);
    vec2 same = gpu::transformUv(slotOf(vec2(0.0f), 0.0f, vec2(1.0f)), uv);
    EXPECT_EQ(same, uv);
    vec2 shifted = gpu::transformUv(slotOf(vec2(0.5f, -1.0f), 0.0f, vec2(1.0f)), uv);
    EXPECT_NEAR(shifted.x, 0.8f, 1e-6f);
    EXPECT_NEAR(shifted.y, -0.3f, 1e-6f);
    vec2 scaled = gpu::transformUv(slotOf(vec2(0.0f), 0.0f, vec2(2.0f, -1.0f)), uv);
    EXPECT_NEAR(scaled.x, 0.6f, 1e-6f);
    EXPECT_NEAR(scaled.y, -0.7f, 1e-6f);
    // A quarter turn takes (1, 0) to (cos, sin) = (0, 1) and (0, 1) to (−1, 0).
    const float quarter = 1.57079632679f;
    vec2 turned = gpu::transformUv(slotOf(vec2(0.0f), quarter, vec2(1.0f)), vec2(1.0f, 0.0f));
    EXPECT_NEAR(turned.x, 0.0f, 1e-6f);
    EXPECT_NEAR(turned.y, 1.0f, 1e-6f);
    turned = gpu::transformUv(slotOf(vec2(0.0f), quarter, vec2(1.0f)), vec2(0.0f, 1.0f));
    EXPECT_NEAR(turned.x, -1.0f, 1e-6f);
    EXPECT_NEAR(turned.y, 0.0f, 1e-6f);
    // All three: scale first, then rotate, then offset.
    const vec2 offset(0.1f, 0.2f), scale(2.0f, 3.0f);
    const float rotation = 0.3f;
    vec2 all = gpu::transformUv(slotOf(offset, rotation, scale), uv);
    vec2 s = uv * scale;
    vec2 expected(std::cos(rotation) * s.x - std::sin(rotation) * s.y + offset.x,
                  std::sin(rotation) * s.x + std::cos(rotation) * s.y + offset.y);
    EXPECT_NEAR(all.x, expected.x, 1e-6f);
    EXPECT_NEAR(all.y, expected.y, 1e-6f);
}

} // namespace
} // namespace vkpt::texture_sampling_test
