// convergence_render_test.cpp — vkpt buying accuracy with time on lavapipe: a time limit stops
// at a pass end with the image so far, a target error stops the render once the estimate
// crosses it (and that estimate is within 25 % of the true relMSE), and a reference
// gives an error after every pass at log-spaced sample counts.
#include <cmath>
#include <vector>

#include "convergence/convergence.h"
#include "image/error_metrics.h"
#include "wavefront_test_support.h"

namespace vkpt::test {
namespace {

class ConvergenceRender : public GpuTest {
protected:
    WavefrontResult render(const RenderSettings& settings, const WavefrontOptions& options) {
        const gpu::Camera camera =
            makeGpuCamera(selectCamera(box_.scene, {}), settings.width, settings.height);
        return renderWavefront(context(), box_.prepared, camera, settings, options);
    }

    // vkpt-ref at another seed: the truth the device's renders are measured against.
    Image reference(std::uint32_t size, std::uint32_t spp) {
        RenderSettings settings = testSettings(size, spp);
        settings.seed = 99;
        return renderTestScene(box_, settings).image;
    }

    static WavefrontOptions tracked(ConvergenceTracker& tracker) {
        WavefrontOptions options;
        options.readPixelsAfterPass = true;
        options.afterPass = [&tracker](const PassFigures& figures, const RenderOutput* output) {
            tracker.record(figures, output);
            return tracker.targetReached();
        };
        return options;
    }

    LoadedTestScene box_ = loadTestScene("cornell-box.gltf");
};

TEST_F(ConvergenceRender, ATimeLimitStopsAtAPassEndWithTheImageSoFar) {
    constexpr double kLimit = 0.5;
    const RenderSettings settings = testSettings(32, 1u << 20); // a budget no test waits for
    std::vector<PassFigures> passes;
    WavefrontOptions options;
    options.timeLimitSeconds = kLimit;
    options.afterPass = [&passes](const PassFigures& figures, const RenderOutput*) {
        passes.push_back(figures);
        return false;
    };
    const WavefrontResult result = render(settings, options);
    EXPECT_EQ(result.stop, RenderStop::TimeLimit);
    ASSERT_GE(passes.size(), 2u);
    EXPECT_LT(passes[passes.size() - 2].seconds, kLimit) << "it stopped at the first pass end";
    EXPECT_GE(passes.back().seconds, kLimit);
    // The last pass was sized to the time left; a generous bound, as a loaded machine is slow.
    EXPECT_LT(result.stats.seconds, kLimit + 2.0);
    EXPECT_LT(result.stats.samplesTaken, result.stats.uniformBudget);
    EXPECT_GT(estimateFromVariance(result.output).minSamples, 1u) << "every pixel has samples";
}

TEST_F(ConvergenceRender, ATargetErrorStopsOnceTheEstimateCrossesIt) {
    constexpr double kTarget = 0.004; // crossed after the estimate's minimum of 64 spp
    const RenderSettings settings = testSettings(32, 4096);
    ConvergenceTracker tracker(nullptr, kTarget);
    const WavefrontResult result = render(settings, tracked(tracker));
    EXPECT_EQ(result.stop, RenderStop::TargetError);
    const std::vector<ConvergencePoint>& curve = tracker.curve();
    ASSERT_GE(curve.size(), 2u);
    EXPECT_LE(tracker.trackedError(curve.back()), kTarget);
    EXPECT_FALSE(tracker.trackedError(curve[curve.size() - 2]) <= kTarget) << "the first below";
    EXPECT_GT(curve.back().figures.samplesPerPixel, kMinSamplesForEstimate);
    EXPECT_LT(curve.back().figures.samplesPerPixel, 400u);
    // The estimate against the truth, less the 2048-spp reference's own relMSE (about 2e-4,
    // its estimate from its variances).
    RenderSettings truthSettings = testSettings(32, 2048);
    truthSettings.seed = 99;
    const RenderOutput truthRender = renderTestScene(box_, truthSettings);
    const double truth = compareWithReference(result.output.image, truthRender.image).relMse -
                         estimateFromVariance(truthRender).estimatedRelMse;
    const double estimate = curve.back().estimatedRelMse;
    EXPECT_GT(truth / estimate, 0.8) << "true " << truth << ", estimated " << estimate;
    EXPECT_LT(truth / estimate, 1.25) << "true " << truth << ", estimated " << estimate;
}

TEST_F(ConvergenceRender, AReferenceGivesTheErrorAfterEveryPassAtLogSpacedCounts) {
    const Image truth = reference(32, 1024);
    ConvergenceTracker tracker(&truth, 0.0);
    const WavefrontResult result = render(testSettings(32, 64), tracked(tracker));
    EXPECT_EQ(result.stop, RenderStop::Budget);
    std::vector<std::uint32_t> spp;
    for (const ConvergencePoint& point : tracker.curve()) {
        spp.push_back(point.figures.samplesPerPixel);
        EXPECT_TRUE(std::isfinite(point.relMse) && std::isfinite(point.rmse));
        EXPECT_GE(point.figures.seconds, point.figures.renderSeconds);
    }
    EXPECT_EQ(spp, (std::vector<std::uint32_t>{1, 2, 3, 4, 5, 6, 7, 8, 10, 12, 15, 18, 22, 27, 33,
                                               41, 51, 63, 64}));
    const ConvergencePoint& last = tracker.curve().back();
    EXPECT_LT(last.relMse, tracker.curve().front().relMse / 10.0);
    EXPECT_EQ(last.figures.samplesTaken, 64u * 32 * 32);
    EXPECT_DOUBLE_EQ(last.relMse, compareWithReference(result.output.image, truth).relMse);
}

} // namespace
} // namespace vkpt::test
