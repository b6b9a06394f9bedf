// convergence_render_test.cpp — vkpt buying accuracy with time on lavapipe: a time limit stops
// at a pass end with the image so far, a target error stops the render once the estimate
// crosses it (and that estimate, from the two halves, is the true relMSE within one render's
// noise, with independent samples and with the Sobol sampler's stratified ones alike), and a
// reference
// gives an error after every pass at log-spaced sample counts.
#include <cmath>
#include <cstdio>
#include <vector>

#include "convergence/convergence.h"
#include "image/error_metrics.h"
#include "wavefront_test_support.h"

namespace vkpt::test::convergence_render_test {
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

    double trueOverEstimatedError(RenderSettings settings);

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

// A render to kTarget, stopped by the estimate from the two halves: the true relMSE at the stop
// over the estimate. The truth is measured against a 2048-spp reference, less that reference's
// own relMSE (its estimate from its halves).
double ConvergenceRender::trueOverEstimatedError(RenderSettings settings) {
    constexpr double kTarget = 0.004; // crossed after the estimate's minimum of 64 spp
    ConvergenceTracker tracker(nullptr, kTarget);
    const WavefrontResult result = render(settings, tracked(tracker));
    EXPECT_EQ(result.stop, RenderStop::TargetError);
    const std::vector<ConvergencePoint>& curve = tracker.curve();
    EXPECT_GE(curve.size(), 2u);
    if (curve.size() < 2) return std::nan("");
    EXPECT_LE(tracker.trackedError(curve.back()), kTarget);
    EXPECT_FALSE(tracker.trackedError(curve[curve.size() - 2]) <= kTarget) << "the first below";
    EXPECT_GT(curve.back().figures.samplesPerPixel, kMinSamplesForEstimate);
    EXPECT_LT(curve.back().figures.samplesPerPixel, 400u);
    RenderSettings truthSettings = testSettings(32, 2048);
    truthSettings.seed = 99;
    const RenderOutput truthRender = renderTestScene(box_, truthSettings);
    const double truth = compareWithReference(result.output.image, truthRender.image).relMse -
                         estimateFromVariance(truthRender).estimatedRelMse;
    const double estimate = curve.back().estimatedRelMse;
    std::printf("true relMSE %.4g, estimated %.4g, ratio %.3f\n", truth, estimate,
                truth / estimate);
    return truth / estimate;
}

// One 32×32 render's true relMSE is far from its expectation: fireflies make it heavy-tailed. With
// independent numbers at 64 spp, six seeds of vkpt-ref gave true relMSEs of 4.4e-3 to 1.06e-2
// and halves' estimates of 4.9e-3 to 6.8e-3: true ÷ estimated from 0.79 to 2.19. One render can
// only bound the ratio loosely — 0.5 to 2 held five of those six seeds, and holds this test's
// fixed seed (0.66 with independent numbers, 0.88 with Sobol) — which σ²/n with Sobol (0.38
// here) fails; tests/render/error_estimate_test.cpp pins the estimate down over seeds.
constexpr double kLowestTrueOverEstimated = 0.5;
constexpr double kHighestTrueOverEstimated = 2.0;

// With independent numbers the halves' difference and σ²/n both estimate the truth.
TEST_F(ConvergenceRender, ATargetErrorStopsOnceTheEstimateCrossesIt) {
    RenderSettings settings = testSettings(32, 4096);
    settings.sampler = Sampler::Independent;
    const double ratio = trueOverEstimatedError(settings);
    EXPECT_GT(ratio, kLowestTrueOverEstimated);
    EXPECT_LT(ratio, kHighestTrueOverEstimated);
}

// A pixel's Sobol samples are stratified, so their mean varies less than σ²/n says (which made
// the estimate 2.6× the truth here: true ÷ estimated 0.38); the two halves are independent
// sequences, so their difference measures the stratified mean's error itself, as above.
TEST_F(ConvergenceRender, WithTheSobolSamplerTheEstimateIsTheTrueError) {
    const double ratio = trueOverEstimatedError(testSettings(32, 4096));
    EXPECT_GT(ratio, kLowestTrueOverEstimated);
    EXPECT_LT(ratio, kHighestTrueOverEstimated);
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
} // namespace vkpt::test::convergence_render_test
