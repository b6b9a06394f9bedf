// farm_render_test.cpp — a render is a sum of independent sample ranges (DESIGN.md), on both
// executors: tasks merged equal one run, crops tiled equal one run, a resumed render equals the
// uninterrupted one, and device and CPU parts merge into the reference's image — the two halves'
// means and counts (even and odd sample indices) as well as the whole mean.
//
// Bounds, and why: the reference keeps double sums and Chan's merge is exact up to double
// rounding, so its merged and resumed means agree with one run to 1e-12 relative and its float
// images to one float rounding (2^-23 relative). The device keeps Kahan-compensated float sums,
// whose result is within about 2 float roundings of the exact sum however it is split, so its
// merged or resumed means agree to 1e-6 relative. Crops change nothing in a pixel's
// arithmetic: equal bit for bit. Device and CPU parts together obey the same-seed bound of
// docs/wavefront.md.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "render/wavefront.h"
#include "scene/camera.h"
#include "state/state_merge.h"
#include "wavefront_test_support.h"

namespace vkpt::test::farm_render_test {
namespace {

constexpr double kReferenceRelative = 1e-12;
constexpr double kDeviceRelative = 1e-6;
constexpr double kFloatRounding = 1.0 / (1 << 23);
constexpr double kDeviceHalfRelative = 1e-5;

enum class Executor { Cpu, Gpu };

double halfRelativeOf(Executor executor) {
    return executor == Executor::Cpu ? kReferenceRelative : kDeviceHalfRelative;
}

class RenderParts : public GpuTest {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        scene_ = loadTestScene("cornell-box.gltf");
        settings_ = testSettings(16, 28);
    }

    gpu::Camera camera() const {
        return makeGpuCamera(selectCamera(scene_.scene, settings_.cameraIndex), settings_.width,
                             settings_.height);
    }

    SamplePlan wholePlan(std::uint32_t spp) const {
        return {fullFrame(settings_.width, settings_.height), {0, spp}};
    }

    // The records of one part; `resume` continues a part's records.
    std::vector<PixelRecord> render(Executor executor, const SamplePlan& plan,
                                    const std::vector<PixelRecord>* resume = nullptr) {
        if (executor == Executor::Cpu) {
            ReferenceOptions options;
            options.plan = plan;
            options.resume = resume;
            RenderStats stats;
            return renderReferenceParts(scene_.prepared, camera(), settings_, stats, options)
                .records;
        }
        WavefrontOptions options;
        options.plan = plan;
        options.resume = resume;
        WavefrontResult result =
            renderWavefront(context(), scene_.prepared, camera(), settings_, options);
        EXPECT_EQ(result.truncatedTraversals, 0u);
        return std::move(result.records);
    }

    StatePart part(const std::string& name, const SamplePlan& plan,
                   std::vector<PixelRecord> records) const {
        RenderState state;
        state.identity = {"test", "test", settings_.seed, settings_.width, settings_.height};
        state.window = plan.crop;
        state.regions = {{plan.crop, {plan.range}}};
        state.pixels = std::move(records);
        return {name, std::move(state)};
    }

    RenderState renderTasks(const std::vector<Executor>& executors) {
        std::vector<StatePart> parts;
        const std::uint32_t n = std::uint32_t(executors.size());
        for (std::uint32_t k = 0; k < n; ++k) {
            SamplePlan plan = wholePlan(settings_.samplesPerPixel);
            plan.range = taskSampleRange(settings_.samplesPerPixel, {k, n});
            parts.push_back(part("task " + std::to_string(k), plan, render(executors[k], plan)));
        }
        return mergeStates(std::move(parts));
    }

    // Tasks of one executor, merged, against one run of all 28 samples.
    void expectTasksMergeToOneRun(Executor executor, double relative, double image);

    LoadedTestScene scene_;
    RenderSettings settings_;
};

double relativeDifference(double a, double b) {
    return std::abs(a - b) / std::max(std::abs(b), 1e-30);
}

// Counts equal, means within `relative`, luminance moments within 1e-4 relative (the device's
// float Welford M2 against Chan's combination of float parts) and the float images within
// `imageRelative`; the halves' counts equal and their means within `halfRelative` (the device
// keeps a half as a float running mean, whose rounding a split changes: 1e-5 relative bounds
// the 28 and 128 samples' drift); returns the largest relative difference of a mean.
double expectSameRecords(const std::vector<PixelRecord>& merged,
                         const std::vector<PixelRecord>& oneRun, double relative,
                         double imageRelative, double halfRelative) {
    EXPECT_EQ(merged.size(), oneRun.size());
    double worst = 0.0;
    for (std::size_t i = 0; i < std::min(merged.size(), oneRun.size()); ++i) {
        const PixelRecord& a = merged[i];
        const PixelRecord& b = oneRun[i];
        EXPECT_EQ(a.count, b.count) << "pixel " << i;
        EXPECT_EQ(a.samplesTaken, b.samplesTaken) << "pixel " << i;
        EXPECT_EQ(a.converged, b.converged) << "pixel " << i;
        for (int c = 0; c < 3; ++c) {
            const double d = relativeDifference(a.mean[c], b.mean[c]);
            worst = std::max(worst, d);
            EXPECT_LE(d, relative) << "pixel " << i << " channel " << c;
            const float fa = float(a.mean[c]), fb = float(b.mean[c]);
            EXPECT_LE(std::abs(fa - fb), imageRelative * std::abs(fb) + 1e-30)
                << "pixel " << i << " channel " << c;
        }
        EXPECT_LE(std::abs(a.luminanceM2 - b.luminanceM2), 1e-4 * b.luminanceM2 + 1e-12)
            << "pixel " << i;
        for (int h = 0; h < 2; ++h) {
            EXPECT_EQ(a.halves[h].count, b.halves[h].count) << "pixel " << i << " half " << h;
            for (int c = 0; c < 3; ++c)
                EXPECT_LE(std::abs(a.halves[h].mean[c] - b.halves[h].mean[c]),
                          halfRelative * std::abs(b.halves[h].mean[c]) + 1e-30)
                    << "pixel " << i << " half " << h << " channel " << c;
        }
        EXPECT_EQ(a.halves[0].count + a.halves[1].count, a.count) << "pixel " << i;
        if (::testing::Test::HasFailure()) break; // one pixel's report is enough
    }
    return worst;
}

void RenderParts::expectTasksMergeToOneRun(Executor executor, double relative, double image) {
    const std::vector<PixelRecord> oneRun = render(executor, wholePlan(28));
    // Every split on the CPU; on the device, where each render compiles its pipelines (about a
    // second on lavapipe), the smallest and the largest.
    const std::vector<std::uint32_t> splits = executor == Executor::Cpu
                                                  ? std::vector<std::uint32_t>{1, 2, 3, 7}
                                                  : std::vector<std::uint32_t>{2, 7};
    for (std::uint32_t n : splits) {
        const RenderState merged = renderTasks(std::vector<Executor>(n, executor));
        const double worst =
            expectSameRecords(merged.pixels, oneRun, relative, image, halfRelativeOf(executor));
        std::printf("%s, %u tasks merged: largest relative difference of a mean %.3g\n",
                    executor == Executor::Cpu ? "vkpt-ref" : "vkpt", n, worst);
    }
}

TEST_F(RenderParts, ReferenceTasksMergeToOneRun) {
    expectTasksMergeToOneRun(Executor::Cpu, kReferenceRelative, kFloatRounding);
}

TEST_F(RenderParts, DeviceTasksMergeToOneRun) {
    expectTasksMergeToOneRun(Executor::Gpu, kDeviceRelative, kDeviceRelative);
}

TEST_F(RenderParts, DeviceAndCpuTasksMergeToTheReference) {
    const std::vector<PixelRecord> cpuRun = render(Executor::Cpu, wholePlan(28));
    const RenderState merged = renderTasks({Executor::Gpu, Executor::Cpu, Executor::Gpu});
    RenderState reference = part("one run", wholePlan(28), cpuRun).state;
    const SameSeedAgreement a = compareSameSeed(renderOutputOf(merged), renderOutputOf(reference));
    std::printf("vkpt + vkpt-ref tasks vs vkpt-ref: %s\n", a.summary().c_str());
    EXPECT_GE(a.fraction(), 0.99);
    for (std::size_t i = 0; i < cpuRun.size(); ++i)
        ASSERT_EQ(merged.pixels[i].count, cpuRun[i].count);
}

// Four uneven tiles, rendered by both executors, uniform and adaptive.
TEST_F(RenderParts, CropsTileToOneRun) {
    const std::vector<PixelRect> tiles = {
        {0, 0, 11, 5}, {11, 0, 16, 5}, {0, 5, 7, 16}, {7, 5, 16, 16}};
    for (bool adaptive : {false, true}) {
        // σ²/n alone: calibrated by the halves, a tile's pixels would stop by its own pixels'
        // scale (render_driver.cpp), which only the whole image's run shares.
        settings_.adaptive = {adaptive, 4, 0.3f, 8, false};
        for (Executor executor : {Executor::Cpu, Executor::Gpu}) {
            const SamplePlan whole = wholePlan(adaptive ? 64 : 28);
            std::vector<StatePart> parts;
            for (const PixelRect& tile : tiles) {
                const SamplePlan plan{tile, whole.range};
                parts.push_back(part(describeRect(tile), plan, render(executor, plan)));
            }
            const RenderState merged = mergeStates(std::move(parts));
            const std::vector<PixelRecord> oneRun = render(executor, whole);
            ASSERT_EQ(merged.window, whole.crop);
            expectSameRecords(merged.pixels, oneRun, 0.0, 0.0, 0.0);
        }
    }
}

TEST_F(RenderParts, ResumedRendersEqualTheUninterruptedOne) {
    constexpr std::uint32_t kBudget = 128;
    for (Executor executor : {Executor::Cpu, Executor::Gpu}) {
        const std::vector<PixelRecord> oneRun = render(executor, wholePlan(kBudget));
        const double relative = executor == Executor::Cpu ? kReferenceRelative : kDeviceRelative;
        const double image = executor == Executor::Cpu ? kFloatRounding : kDeviceRelative;
        for (std::uint32_t stop : {1u, 7u, 100u}) {
            const std::vector<PixelRecord> first = render(executor, wholePlan(stop));
            const std::vector<PixelRecord> resumed = render(executor, wholePlan(kBudget), &first);
            const double worst =
                expectSameRecords(resumed, oneRun, relative, image, halfRelativeOf(executor));
            std::printf("%s resumed after %u of %u samples: largest relative difference %.3g\n",
                        executor == Executor::Cpu ? "vkpt-ref" : "vkpt", stop, kBudget, worst);
        }
    }
}

} // namespace
} // namespace vkpt::test::farm_render_test
