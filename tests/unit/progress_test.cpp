// progress_test.cpp — progress reporting: one log line per 10 % step off a terminal, in order
// under concurrent advances, and a bar redrawn in place on a terminal.
#include "common/progress.h"

#include <algorithm>
#include <memory>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

namespace vkpt::progress_test {
namespace {

std::vector<std::string> linesOf(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        lines.push_back(line);
    return lines;
}

bool startsWith(const std::string& text, const std::string& prefix) {
    return text.compare(0, prefix.size(), prefix) == 0;
}

TEST(ProgressBar, LogPrintsOneLinePerTenPercentStepThenTheFinalLine) {
    std::ostringstream out;
    ProgressBar bar("render", 100, out, false);
    for (int i = 0; i < 100; ++i)
        bar.advance();
    bar.finish();
    const std::vector<std::string> lines = linesOf(out.str());
    ASSERT_EQ(lines.size(), 10u) << out.str();
    for (int step = 1; step <= 9; ++step) {
        const std::string expected =
            "render: " + std::to_string(step * 10) + "% (" + std::to_string(step * 10) + "/100), ";
        EXPECT_TRUE(startsWith(lines[std::size_t(step - 1)], expected))
            << lines[std::size_t(step - 1)];
        EXPECT_NE(lines[std::size_t(step - 1)].find(" elapsed, ETA "), std::string::npos);
    }
    EXPECT_TRUE(startsWith(lines[9], "render: done, 100/100 in ")) << lines[9];
}

TEST(ProgressBar, LogPrintsOneLineForAJumpAcrossSeveralSteps) {
    std::ostringstream out;
    ProgressBar bar("pixels", 4096, out, false);
    bar.advance(1500); // 36 %: one line, not three
    bar.advance(10);   // still 36 %: nothing
    const std::vector<std::string> lines = linesOf(out.str());
    ASSERT_EQ(lines.size(), 1u) << out.str();
    EXPECT_TRUE(startsWith(lines[0], "pixels: 36% (1500/4096), ")) << lines[0];
}

TEST(ProgressBar, LogShowsTheStatusField) {
    std::ostringstream out;
    ProgressBar bar("render", 10, out, false);
    bar.setStatus("active pixels 1234");
    bar.advance(5);
    bar.setStatus("active pixels 0");
    bar.finish();
    const std::vector<std::string> lines = linesOf(out.str());
    ASSERT_EQ(lines.size(), 2u) << out.str();
    EXPECT_TRUE(lines[0].ends_with(", active pixels 1234")) << lines[0];
    EXPECT_TRUE(lines[1].ends_with(", active pixels 0")) << lines[1];
}

TEST(ProgressBar, FinishPrintsOnceAndReportsAnEarlyStop) {
    std::ostringstream out;
    ProgressBar bar("samples", 1000, out, false);
    bar.advance(50);
    bar.finish();
    bar.finish();
    bar.advance(900); // after finish: counted, not printed
    const std::vector<std::string> lines = linesOf(out.str());
    ASSERT_EQ(lines.size(), 1u) << out.str();
    EXPECT_TRUE(startsWith(lines[0], "samples: done, 50/1000 in ")) << lines[0];
    EXPECT_EQ(bar.done(), 950u);
}

TEST(ProgressBar, EmptyJobFinishesCleanly) {
    std::ostringstream out;
    ProgressBar bar("nothing", 0, out, false);
    bar.finish();
    EXPECT_TRUE(startsWith(out.str(), "nothing: done, 0/0 in ")) << out.str();
}

TEST(ProgressBar, ConcurrentAdvancesCountEverythingAndLogStepsInOrder) {
    constexpr int kThreads = 8, kPerThread = 5000;
    std::ostringstream out;
    ProgressBar bar("threads", kThreads * kPerThread, out, false);
    std::vector<std::thread> workers;
    for (int t = 0; t < kThreads; ++t)
        workers.emplace_back([&bar] {
            for (int i = 0; i < kPerThread; ++i)
                bar.advance();
        });
    for (std::thread& worker : workers)
        worker.join();
    bar.finish();
    EXPECT_EQ(bar.done(), std::uint64_t(kThreads * kPerThread));
    const std::vector<std::string> lines = linesOf(out.str());
    ASSERT_EQ(lines.size(), 10u) << out.str();
    int previous = 0;
    for (std::size_t i = 0; i + 1 < lines.size(); ++i) {
        const int percent = std::stoi(lines[i].substr(std::string("threads: ").size()));
        EXPECT_GT(percent, previous) << lines[i];
        EXPECT_GE(percent, int(i + 1) * 10) << lines[i];
        previous = percent;
    }
}

TEST(ProgressBar, TerminalRedrawsInPlaceAndEndsTheLine) {
    std::ostringstream out;
    {
        ProgressBar bar("render", 200, out, true);
        for (int i = 0; i < 200; ++i)
            bar.advance();
        bar.finish();
    }
    const std::string text = out.str();
    // 200 quick advances fall within one 0.1 s redraw interval: one draw, then the final line.
    EXPECT_LE(std::count(text.begin(), text.end(), '\r'), 3);
    EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1);
    EXPECT_NE(text.find("[########################] 100% 200/200"), std::string::npos) << text;
    EXPECT_TRUE(text.ends_with("\x1b[K\n"));
}

TEST(ProgressBar, TerminalBarInterruptedByAnErrorEndsItsLine) {
    std::ostringstream out;
    {
        ProgressBar bar("render", 10, out, true);
        bar.advance(3);
    }
    const std::string text = out.str();
    EXPECT_NE(text.find("  30% 3/10"), std::string::npos) << text;
    EXPECT_TRUE(text.ends_with("\n"));
}

TEST(ProgressBar, SilentBarCountsWithoutPrinting) {
    const std::unique_ptr<ProgressBar> bar = ProgressBar::silent("quiet", 10);
    bar->advance(4);
    bar->advance(6);
    bar->finish();
    EXPECT_EQ(bar->done(), 10u);
    const std::unique_ptr<ProgressBar> quiet = makeProgressBar("quiet", 5, true);
    quiet->advance(5);
    quiet->finish();
    EXPECT_EQ(quiet->done(), 5u);
}

TEST(FormatDuration, ChoosesUnitsByMagnitude) {
    EXPECT_EQ(formatDuration(0.0), "0.0 s");
    EXPECT_EQ(formatDuration(4.24), "4.2 s");
    EXPECT_EQ(formatDuration(187.0), "3 min 07 s");
    EXPECT_EQ(formatDuration(7500.0), "2 h 05 min");
    EXPECT_EQ(formatDuration(-1.0), "?");
    EXPECT_EQ(formatDuration(1e30), "more than 1000 h");
}

} // namespace
} // namespace vkpt::progress_test
