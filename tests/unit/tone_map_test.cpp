// tone_map_test.cpp — the Khronos PBR Neutral operator against values worked out by hand from
// its specification (KhronosGroup/ToneMapping, PBR_Neutral/README.md), and its properties.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "image/tone_map.h"

namespace vkpt::tone_map_test {
namespace {

void expectNear(glm::vec3 actual, glm::vec3 expected, float tolerance = 1e-5f) {
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(actual[c], expected[c], tolerance) << "component " << c;
}

TEST(PbrNeutral, PassesMidTonesLessTheToeOffset) {
    // min 0.1 > 2·F90, so f = F90 = 0.04; the peak 0.26 stays below Ks = 0.76.
    expectNear(pbrNeutralToneMap({0.3f, 0.2f, 0.1f}), {0.26f, 0.16f, 0.06f});
    expectNear(pbrNeutralToneMap(glm::vec3(0.5f)), glm::vec3(0.46f));
}

TEST(PbrNeutral, TheToeFollowsItsParabolaBelowTwiceF90) {
    // x = 0.04: f = 0.04 − 0.04²/0.16 = 0.03. x = 0: f = 0, black stays black.
    expectNear(pbrNeutralToneMap(glm::vec3(0.04f)), glm::vec3(0.01f));
    expectNear(pbrNeutralToneMap(glm::vec3(0.0f)), glm::vec3(0.0f));
}

TEST(PbrNeutral, CompressesAGreyAboveTheStartToTheNewPeak) {
    // Grey 1: p = 0.96, pn = 1 − 0.24²/(0.96 + 1 − 1.52) = 1 − 0.0576/0.44; a grey maps to pn.
    expectNear(pbrNeutralToneMap(glm::vec3(1.0f)), glm::vec3(1.0f - 0.0576f / 0.44f));
}

TEST(PbrNeutral, DesaturatesABrightColourTowardsWhite) {
    // (2, 0, 0): f = 0, p = 2, pn = 1 − 0.0576/1.48, g = 1/(0.15·(2 − pn) + 1); red becomes pn,
    // the others pn·(1 − g).
    const float pn = 1.0f - 0.0576f / 1.48f;
    const float g = 1.0f / (0.15f * (2.0f - pn) + 1.0f);
    expectNear(pbrNeutralToneMap({2.0f, 0.0f, 0.0f}), {pn, pn * (1.0f - g), pn * (1.0f - g)});
}

TEST(PbrNeutral, IsContinuousAndMonotonicForGreysAndStaysWithinOne) {
    float previous = pbrNeutralToneMap(glm::vec3(0.0f)).x;
    EXPECT_EQ(previous, 0.0f);
    for (float v = 0.001f; v < 1000.0f; v = v < 0.01f ? v + 0.001f : v * 1.01f) {
        const float out = pbrNeutralToneMap(glm::vec3(v)).x;
        EXPECT_GE(out, previous) << "at " << v;
        EXPECT_LE(out, 1.0f) << "at " << v;
        EXPECT_LE(out - previous, 0.02f) << "a jump at " << v;
        previous = out;
    }
    EXPECT_GT(previous, 0.999f);
}

TEST(ToneMap, ClampLeavesColoursAndBothMakeNonFiniteAndNegativeBlack) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    expectNear(applyToneMap(ToneMap::Clamp, {0.3f, 2.0f, 0.0f}), {0.3f, 2.0f, 0.0f});
    for (ToneMap toneMap : {ToneMap::Clamp, ToneMap::PbrNeutral}) {
        expectNear(applyToneMap(toneMap, {nan, inf, -1.0f}), glm::vec3(0.0f));
        EXPECT_STREQ(toneMapName(toneMap), toneMap == ToneMap::Clamp ? "clamp" : "neutral");
    }
    expectNear(applyToneMap(ToneMap::PbrNeutral, glm::vec3(0.5f)), glm::vec3(0.46f));
}

} // namespace
} // namespace vkpt::tone_map_test
