// normal_mapping_test.cpp — shared/normal_mapping.h: decoding a normal texture's texel (scale,
// the green channel's direction), the tangent frame, and the bend that keeps a mapped normal
// facing the viewer and its mirror direction above the surface.
#include <cmath>

#include <gtest/gtest.h>

#include "shared/normal_mapping.h"
#include "shared/rng.h"
#include "shared/sampling.h"

namespace vkpt::gpu::normal_mapping_test {
namespace {

void expectNear(const vec3& actual, const vec3& expected, float tolerance = 1e-6f) {
    EXPECT_NEAR(actual.x, expected.x, tolerance) << "x";
    EXPECT_NEAR(actual.y, expected.y, tolerance) << "y";
    EXPECT_NEAR(actual.z, expected.z, tolerance) << "z";
}

TEST(NormalMapDecoding, FlatTexelIsTheNormal) {
    expectNear(decodeTangentSpaceNormal(vec4(0.5f, 0.5f, 1.0f, 1.0f), 1.0f), vec3(0, 0, 1));
}

TEST(NormalMapDecoding, ChannelsMapToMinusOneToOne) {
    expectNear(decodeTangentSpaceNormal(vec4(1.0f, 0.5f, 0.5f, 1.0f), 1.0f), vec3(1, 0, 0));
    expectNear(decodeTangentSpaceNormal(vec4(0.5f, 0.0f, 0.5f, 1.0f), 1.0f), vec3(0, -1, 0));
}

// glTF: normalize((texel·2 − 1)·(scale, scale, 1)).
TEST(NormalMapDecoding, ScaleMultipliesXAndYBeforeNormalising) {
    const vec4 texel(0.75f, 0.5f, 1.0f, 1.0f); // (0.5, 0, 1) before normalising
    expectNear(decodeTangentSpaceNormal(texel, 2.0f), normalize(vec3(1, 0, 1)));
    expectNear(decodeTangentSpaceNormal(texel, 0.0f), vec3(0, 0, 1));
    expectNear(decodeTangentSpaceNormal(texel, -1.0f), normalize(vec3(-0.5f, 0, 1)));
}

TEST(NormalMapDecoding, ATexelDecodingToZeroGivesTheNormal) {
    expectNear(decodeTangentSpaceNormal(vec4(0.5f, 0.5f, 0.5f, 1.0f), 1.0f), vec3(0, 0, 1));
}

// Green (+Y) runs along the bitangent w·cross(n, t): up the texture for w = +1, and the
// other way for a mirrored frame (w = −1), which is what keeps mirrored halves lit alike.
TEST(NormalMapFrame, GreenFollowsTheBitangentSign) {
    const vec3 n(0, 0, 1);
    const vec3 green(0, 1, 0);
    expectNear(tangentToWorld(green, n, vec4(1, 0, 0, 1)), vec3(0, 1, 0));
    expectNear(tangentToWorld(green, n, vec4(1, 0, 0, -1)), vec3(0, -1, 0));
    expectNear(tangentToWorld(vec3(1, 0, 0), n, vec4(1, 0, 0, 1)), vec3(1, 0, 0));
}

TEST(NormalMapFrame, InterpolatedTangentIsMadeOrthogonalToTheNormal) {
    const vec3 n(0, 0, 1);
    // A tangent leaning out of the surface: only its in-plane part counts.
    expectNear(tangentToWorld(vec3(1, 0, 0), n, vec4(2, 0, 5, 1)), vec3(1, 0, 0));
    // A tangent along the normal has no frame: the normal is kept.
    expectNear(tangentToWorld(vec3(1, 0, 0), n, vec4(0, 0, 1, 1)), n);
}

// For random mapped normals (any direction, also below the surface) and outgoing directions
// above it: the bent normal is unit, faces wo, and reflects wo to at least the bound above the
// geometric surface; a normal that already does is left exactly as it was.
TEST(NormalMapBend, KeepsTheViewAndItsMirrorAboveTheSurface) {
    const vec3 ng(0, 0, 1);
    int bent = 0;
    for (uint i = 0; i < 20000; ++i) {
        const vec4 u = randomFloats(7u, i, 0u, 0u, 0u);
        const vec3 n = sampleUniformSphere(vec2(u.x, u.y));
        vec3 wo = sampleUniformSphere(vec2(u.z, u.w));
        wo.z = std::abs(wo.z);
        const vec3 b = bendTowardsViewer(n, ng, wo);
        ASSERT_NEAR(length(b), 1.0f, 1e-5f) << i;
        ASSERT_GT(dot(b, wo), 0.0f) << i;
        const vec3 r = 2.0f * dot(wo, b) * b - wo;
        ASSERT_GT(dot(r, ng), 0.5f * VKPT_NORMAL_BEND_MIN_COS) << i;
        const bool fine =
            dot(wo, n) > 0.0f && dot(2.0f * dot(wo, n) * n - wo, ng) >= VKPT_NORMAL_BEND_MIN_COS;
        if (fine) {
            ASSERT_EQ(b, n) << i;
        } else {
            ++bent;
        }
    }
    EXPECT_GT(bent, 1000); // the random normals do test the bend
}

} // namespace
} // namespace vkpt::gpu::normal_mapping_test
