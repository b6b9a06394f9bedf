// frame_options_test.cpp — frame numbering of --frames/--frame: which frames, their file names,
// their times, and the options that do not go together.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/frame_options.h"
#include "common/errors.h"

namespace vkpt::frame_options_test {
namespace {

TEST(FrameOptions, NumbersTheLastRunOfHashesZeroPadded) {
    EXPECT_EQ(framePath("out.####.png", 7), "out.0007.png");
    EXPECT_EQ(framePath("out.##.png", 1234), "out.1234.png"); // longer than the run: whole
    EXPECT_EQ(framePath("a#/b.###.exr", 12), "a#/b.012.exr");
    EXPECT_EQ(framePath("plain.png", 3), "plain.png");
}

TEST(FrameOptions, ListsTheRangeByItsStepOrTheSingleFrame) {
    FrameSettings frames;
    frames.range = FrameRange{2, 9, 3};
    EXPECT_EQ(framesToRender(frames), (std::vector<std::uint32_t>{2, 5, 8}));
    frames.single = 5;
    EXPECT_EQ(framesToRender(frames), (std::vector<std::uint32_t>{5}));
}

TEST(FrameOptions, PosesEachFrameAtItsTimeAndNamesItsFiles) {
    FrameSettings frames;
    frames.range = FrameRange{0, 10, 1};
    frames.fps = 4.0;
    RenderSettings settings;
    settings.outputPath = "walk.####.png";
    settings.statsJsonPath = "walk.####.json";
    const RenderSettings each = frameSettings(settings, frames, 6);
    ASSERT_TRUE(each.animationTime.has_value());
    EXPECT_DOUBLE_EQ(*each.animationTime, 1.5);
    EXPECT_EQ(each.outputPath, "walk.0006.png");
    EXPECT_EQ(each.statsJsonPath, "walk.0006.json");
}

void expectRejected(const FrameSettings& frames, const RenderSettings& settings,
                    const std::string& message) {
    try {
        validateFrameSettings(frames, settings);
        ADD_FAILURE() << "accepted";
    } catch (const InputError& error) {
        EXPECT_EQ(std::string(error.what()).substr(0, message.size()), message);
    }
}

TEST(FrameOptions, RejectsWhatCannotNumberOrTimeTheFrames) {
    FrameSettings frames;
    frames.range = FrameRange{0, 4, 2};
    RenderSettings settings;
    settings.outputPath = "out.png";
    expectRejected(frames, settings, "option --frames/--frame: the output 'out.png' needs a run");
    settings.outputPath = "out.#.png";
    settings.statsJsonPath = "stats.json";
    expectRejected(frames, settings, "option --stats-json: with --frames/--frame the name needs");
    settings.statsJsonPath.clear();
    frames.single = 3; // 0, 2, 4 only
    expectRejected(frames, settings, "option --frame: frame 3 is not one of the --frames range");
    frames.single.reset();
    settings.animationTime = 1.0;
    expectRejected(frames, settings, "options --time and --frames/--frame");
    settings.animationTime.reset();
    EXPECT_NO_THROW(validateFrameSettings(frames, settings));
    settings.animation = "walk";
    EXPECT_NO_THROW(validateFrameSettings(frames, settings)); // the frames give the time
    expectRejected(FrameSettings{}, settings, "option --animation: give the time");
}

} // namespace
} // namespace vkpt::frame_options_test
