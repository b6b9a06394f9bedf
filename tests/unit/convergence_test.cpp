// convergence_test.cpp — the curve that --reference, --target-error and --time-limit report:
// points measured from a render, the rule that stops at a target error, the reference file's
// checks and the JSON.
#include "convergence/convergence.h"

#include <cmath>
#include <filesystem>
#include <sstream>

#include <gtest/gtest.h>

#include "common/errors.h"
#include "common/json_writer.h"
#include "image/image_io.h"

namespace vkpt::convergence_test {
namespace {

// Every pixel: n samples of luminance mean 1 and sample variance `variance`, image value
// `value` in every channel.
RenderOutput render(std::uint32_t n, float value, float variance) {
    RenderOutput output;
    output.image = Image(4, 4);
    for (glm::vec3& p : output.image.pixels)
        p = glm::vec3(value);
    output.sampleCounts.assign(16, n);
    output.luminanceMean.assign(16, 1.0f);
    output.luminanceM2.assign(16, variance * float(n - 1));
    return output;
}

Image grey(float value) {
    Image image(4, 4);
    for (glm::vec3& p : image.pixels)
        p = glm::vec3(value);
    return image;
}

PassFigures pass(std::uint32_t number, std::uint32_t spp) {
    PassFigures f;
    f.pass = number;
    f.seconds = f.renderSeconds = 0.1 * number;
    f.samplesPerPixel = spp;
    f.activePixels = 16;
    return f;
}

TEST(ConvergenceTracker, MeasuresAgainstTheReference) {
    const Image reference = grey(1.0f);
    ConvergenceTracker tracker(&reference, 0.0);
    const RenderOutput output = render(32, 1.1f, 0.5f);
    const ConvergencePoint& point = tracker.record(pass(1, 32), &output);
    EXPECT_NEAR(point.relMse, 0.01 / 1.01, 1e-6);
    EXPECT_NEAR(point.rmse, 0.1, 1e-6);
    EXPECT_NEAR(point.estimatedRelMse, 0.5 / 32 / 1.01, 1e-6);
    EXPECT_NEAR(point.meanHalfWidth, 1.96 * std::sqrt(0.5 / 32), 1e-6);
    EXPECT_EQ(tracker.trackedError(point), point.relMse);
}

TEST(ConvergenceTracker, WithoutPixelsKeepsOnlyThePassFigures) {
    ConvergenceTracker tracker(nullptr, 0.0);
    const ConvergencePoint& point = tracker.record(pass(3, 12), nullptr);
    EXPECT_EQ(point.figures.samplesPerPixel, 12u);
    EXPECT_TRUE(std::isnan(point.relMse));
    EXPECT_TRUE(std::isnan(point.estimatedRelMse));
}

TEST(ConvergenceTracker, TargetAgainstTheReference) {
    const Image reference = grey(1.0f);
    ConvergenceTracker tracker(&reference, 0.005);
    const RenderOutput far = render(32, 1.1f, 0.0f), near = render(64, 1.05f, 0.0f);
    tracker.record(pass(1, 32), &far); // relMSE 0.0099
    EXPECT_FALSE(tracker.targetReached());
    tracker.record(pass(2, 64), &near); // relMSE 0.0025
    EXPECT_TRUE(tracker.targetReached());
}

TEST(ConvergenceTracker, WithoutAReferenceTheEstimateCountsFromTheMinimumSampleCount) {
    ConvergenceTracker tracker(nullptr, 0.01);
    // The estimate, 0.001 / 16 / (1 + ε) ≈ 6e-5, is far below the target, but with 16 samples
    // per pixel it is not trusted yet.
    const RenderOutput early = render(16, 1.0f, 0.001f);
    tracker.record(pass(1, 16), &early);
    EXPECT_TRUE(std::isnan(tracker.trackedError(tracker.curve().back())));
    EXPECT_FALSE(tracker.targetReached());
    const RenderOutput later = render(kMinSamplesForEstimate, 1.0f, 0.001f);
    tracker.record(pass(2, kMinSamplesForEstimate), &later);
    EXPECT_TRUE(tracker.targetReached());
}

TEST(ConvergenceTracker, AnAdaptiveRenderWhosePixelsAllStoppedIsTrustedEarlier) {
    ConvergenceTracker tracker(nullptr, 0.01);
    const RenderOutput output = render(32, 1.0f, 0.001f);
    PassFigures figures = pass(1, 32);
    figures.activePixels = 0; // every pixel passed adaptive sampling's own test
    tracker.record(figures, &output);
    EXPECT_TRUE(tracker.targetReached());
}

TEST(ConvergenceTracker, NoTargetIsNeverReached) {
    ConvergenceTracker tracker(nullptr, 0.0);
    const RenderOutput output = render(64, 1.0f, 0.0f);
    tracker.record(pass(1, 64), &output);
    EXPECT_FALSE(tracker.targetReached());
}

class ReferenceFile : public ::testing::Test {
protected:
    std::string path(const std::string& name) {
        return (std::filesystem::temp_directory_path() / ("vkpt_convergence_test_" + name + ".pfm"))
            .string();
    }
};

TEST_F(ReferenceFile, LoadsAReferenceOfTheRenderSize) {
    writePfm(grey(0.5f), path("good"));
    EXPECT_EQ(loadReference(path("good"), 4, 4).pixels[5], glm::vec3(0.5f));
}

TEST_F(ReferenceFile, RejectsAnotherSizeNamingBoth) {
    writePfm(grey(0.5f), path("size"));
    try {
        loadReference(path("size"), 8, 4);
        FAIL() << "no error";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("the reference is 4x4, the render 8x4"),
                  std::string::npos)
            << error.what();
    }
}

TEST_F(ReferenceFile, RejectsNonFiniteValues) {
    Image image = grey(0.5f);
    image.pixels[3].y = std::nanf("");
    writePfm(image, path("nan"));
    EXPECT_THROW(loadReference(path("nan"), 4, 4), InputError);
}

TEST_F(ReferenceFile, AMissingFileIsBadInput) {
    EXPECT_THROW(loadReference(path("does_not_exist"), 4, 4), InputError);
}

TEST(ConvergenceJson, HoldsTheSettingsTheStopAndEveryPoint) {
    const Image reference = grey(1.0f);
    ConvergenceTracker tracker(&reference, 0.02);
    const RenderOutput output = render(16, 1.1f, 0.5f);
    tracker.record(pass(1, 1), nullptr);
    tracker.record(pass(2, 16), &output);
    // Field by field: the nested braces with a string literal trip GCC 12's
    // -Wmaybe-uninitialized at -O3 (a false positive on the std::string member).
    ConvergenceReport report;
    report.settings.referencePath = "ref.pfm";
    report.settings.targetError = 0.02;
    report.stop = RenderStop::TargetError;
    report.targetReached = true;
    report.curve = tracker.curve();
    std::ostringstream out;
    JsonWriter json(out, 0);
    json.beginObject();
    writeConvergenceJson(json, report);
    json.endObject();
    const std::string text = out.str();
    for (const char* expected :
         {"\"reference\":\"ref.pfm\"", "\"targetError\":0.02", "\"timeLimit\":null",
          "\"relMseEpsilon\":0.01", "\"stop\":\"target-error\"", "\"targetReached\":true",
          "\"pass\":1", "\"relMse\":null", "\"pass\":2", "\"spp\":16"})
        EXPECT_NE(text.find(expected), std::string::npos) << expected << " in " << text;
}

TEST(RenderStops, HaveTheNamesTheJsonUses) {
    EXPECT_STREQ(stopName(RenderStop::Budget), "budget");
    EXPECT_STREQ(stopName(RenderStop::Converged), "converged");
    EXPECT_STREQ(stopName(RenderStop::TargetError), "target-error");
    EXPECT_STREQ(stopName(RenderStop::TimeLimit), "time-limit");
    EXPECT_STREQ(stopName(RenderStop::Interrupted), "interrupted");
}

} // namespace
} // namespace vkpt::convergence_test
