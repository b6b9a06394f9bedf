// pass_schedule_test.cpp — how vkpt cuts a render into passes and chunks (CPU only).
#include <vector>

#include <gtest/gtest.h>

#include "driver/batch_policy.h"
#include "render/pass_schedule.h"

namespace vkpt::pass_schedule_test {
namespace {

ScheduleInputs uniform(std::uint32_t spp, std::uint32_t done, std::uint32_t active,
                       std::uint32_t slots) {
    return {spp, done, active, slots, false, 1, 0};
}

ScheduleInputs adaptive(std::uint32_t done, std::uint32_t active, std::uint32_t slots) {
    return {512, done, active, slots, true, 16, 64};
}

TEST(PassSchedule, UniformPassesFillTheSlotsWithinTheBudget) {
    EXPECT_EQ(samplesForPass(uniform(16, 0, 1024, 65536)), 16u);    // all in one pass
    EXPECT_EQ(samplesForPass(uniform(512, 0, 1024, 65536)), 64u);   // as many as fit
    EXPECT_EQ(samplesForPass(uniform(512, 500, 1024, 65536)), 12u); // the rest of the budget
    EXPECT_EQ(samplesForPass(uniform(512, 0, 1 << 20, 65536)), 1u); // more pixels than slots
    EXPECT_EQ(samplesForPass(uniform(1 << 20, 0, 1, 65536)), kMaxSamplesPerPass);
}

TEST(PassSchedule, AdaptivePassesEndWhereTheStoppingRuleIsTested) {
    // Before the minimum count no test happens: the pass may end anywhere up to it.
    EXPECT_EQ(samplesForPass(adaptive(0, 65536, 65536)), 1u);
    // A test point within reach: the pass ends on a batch multiple >= the minimum of 64.
    for (std::uint32_t active : {1u, 10u, 100u, 1000u, 4096u}) {
        std::uint32_t k = samplesForPass(adaptive(64, active, 65536));
        EXPECT_EQ((64 + k) % 16, 0u) << active << " active pixels";
        EXPECT_LE(std::uint64_t(k) * active, 65536u);
        EXPECT_GE(std::uint64_t(k) * active, std::min<std::uint64_t>(65536 / 4, 16 * active));
    }
    EXPECT_EQ(samplesForPass(adaptive(0, 1024, 65536)), 64u);  // the first test point
    EXPECT_EQ(samplesForPass(adaptive(64, 1024, 65536)), 16u); // one batch keeps 16384 paths
    EXPECT_EQ(samplesForPass(adaptive(500, 1, 65536)), 12u);   // the budget ends it
}

TEST(PassSchedule, MeasuredRendersGrowTheirPassesGeometrically) {
    std::vector<std::uint32_t> ends;
    std::uint32_t done = 0;
    while (done < 20)
        ends.push_back(done += samplesForGeometricGrowth(64, done));
    EXPECT_EQ(ends, (std::vector<std::uint32_t>{1, 2, 3, 4, 5, 6, 7, 8, 10, 12, 15, 18, 22}));
    EXPECT_EQ(samplesForGeometricGrowth(4, 1000), 4u); // never above the schedule's k
}

TEST(PassSchedule, ATimeLimitCapsAPassToTheTimeLeft) {
    // 1000 pixels at 1 µs per pixel-sample: 1 ms per sample per pixel.
    EXPECT_EQ(samplesWithinTime(64, 1000, 1e-6, 0.010), 10u);
    EXPECT_EQ(samplesWithinTime(64, 1000, 1e-6, 1.0), 64u);   // the schedule's k fits
    EXPECT_EQ(samplesWithinTime(64, 1000, 1e-6, 0.0001), 1u); // at least one sample
    EXPECT_EQ(samplesWithinTime(64, 1000, 1e-6, -1.0), 1u);   // past the limit already
    EXPECT_EQ(samplesWithinTime(64, 1000, 0.0, 0.010), 64u);  // no rate yet: the first pass
}

// Adaptive sampling's calibration points: max(minSamples / 2, 16) · 2^k, whatever the batches.
TEST(PassSchedule, CalibrationPointsDoubleFromHalfTheMinimum) {
    EXPECT_EQ(firstCalibrationPoint(64), 32u);
    EXPECT_EQ(firstCalibrationPoint(8), kFirstCalibrationSamples);
    std::vector<std::uint32_t> points;
    for (std::uint32_t done = 0; done < 300; done = nextCalibrationPoint(done, 32))
        points.push_back(nextCalibrationPoint(done, 32));
    EXPECT_EQ(points, (std::vector<std::uint32_t>{32, 64, 128, 256, 512}));
    for (std::uint32_t done = 0; done < 600; ++done)
        EXPECT_EQ(isCalibrationPoint(done, 32),
                  done == 32 || done == 64 || done == 128 || done == 256 || done == 512)
            << done;
    EXPECT_FALSE(isCalibrationPoint(64, 0));                       // no adaptive sampling
    EXPECT_EQ(nextCalibrationPoint(0xffffff00u, 32), 0xffffffffu); // saturates, never wraps
    EXPECT_EQ(quantizedVarianceScale(0.5 + 1.0 / 200), 0.5f);
}

TEST(PassSchedule, ChunksCoverTheActivePixels) {
    EXPECT_EQ(pixelsPerChunk(1024, 16, 65536), 1024u);
    EXPECT_EQ(pixelsPerChunk(1 << 20, 1, 65536), 65536u);
    EXPECT_EQ(pixelsPerChunk(1000, 3, 256), 85u);
}

} // namespace
} // namespace vkpt::pass_schedule_test
