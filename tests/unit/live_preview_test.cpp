// live_preview_test.cpp — the checkpoint and the preview through the executors' one periodic
// hook: called at the shorter period, each write runs only once its own period has passed.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "app/live_preview.h"

namespace vkpt {
namespace {

PeriodicWrite counting(double seconds, int& count) {
    return {seconds, [&count](const std::vector<PixelRecord>&, const std::vector<FeatureRecord>&) {
                ++count;
            }};
}

TEST(PeriodicWrites, NeitherAskedForGivesNoHook) {
    const PeriodicWrite none = combinePeriodicWrites({}, {});
    EXPECT_EQ(none.seconds, 0.0);
    EXPECT_FALSE(none.write);
}

TEST(PeriodicWrites, OneAskedForIsPassedOnAsItIs) {
    int previews = 0;
    const PeriodicWrite one = combinePeriodicWrites({}, counting(2.5, previews));
    EXPECT_EQ(one.seconds, 2.5);
    one.write({}, {});
    EXPECT_EQ(previews, 1); // the executor keeps the time; the hook writes when called
}

TEST(PeriodicWrites, BothRunAtTheShorterPeriodEachWhenItsOwnIsDue) {
    int checkpoints = 0, previews = 0;
    const PeriodicWrite both =
        combinePeriodicWrites(counting(3600.0, checkpoints), counting(0.02, previews));
    EXPECT_EQ(both.seconds, 0.02);
    std::this_thread::sleep_for(std::chrono::milliseconds(30));
    both.write({}, {});
    EXPECT_EQ(previews, 1);
    EXPECT_EQ(checkpoints, 0);
    both.write({}, {}); // at once again: the preview's period has not passed
    EXPECT_EQ(previews, 1);
}

} // namespace
} // namespace vkpt
