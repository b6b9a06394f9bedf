// live_preview_test.cpp — the checkpoint and the preview through the executors' one periodic
// hook: called at the shorter period, each write runs only once its own period has passed.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "../support/scratch_directory.h"
#include "app/live_preview.h"
#include "image/image_io.h"

namespace vkpt::live_preview_test {
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

// A denoiser whose output is known: every pixel (0.25, 0.5, 0.75), and it counts its calls.
class ConstantDenoiser final : public Denoiser {
public:
    std::vector<glm::vec3> denoise(const std::vector<gpu::DenoisePixel>& pixels, std::uint32_t,
                                   std::uint32_t, const DenoiseSettings&) override {
        ++calls;
        return std::vector<glm::vec3>(pixels.size(), glm::vec3(0.25f, 0.5f, 0.75f));
    }
    std::string where() const override { return "test"; }
    int calls = 0;
};

TEST(PreviewWriter, ShowsTheDenoisedImageUnderDenoise) {
    // A 4×2 frame whose crop is its right half: the preview is the denoiser's image inside the
    // crop and 0 outside it; without AOVs (none recorded yet) it is the raw image.
    RenderSettings settings;
    settings.width = 4;
    settings.height = 2;
    settings.outputPath = test::scratchPath("preview.pfm");
    const PixelRect crop{2, 0, 4, 2};
    PixelRecord record;
    record.mean = glm::dvec3(1.0);
    record.count = 4;
    const std::vector<PixelRecord> records(crop.area(), record);
    ConstantDenoiser denoiser;
    const RecordsWriter preview = previewWriter(settings, crop, {}, &denoiser);
    preview(records, std::vector<FeatureRecord>(crop.area()));
    EXPECT_EQ(denoiser.calls, 1);
    Image shown = readPfm(settings.outputPath);
    EXPECT_EQ(shown.at(0, 0), glm::vec3(0.0f));
    EXPECT_EQ(shown.at(3, 1), glm::vec3(0.25f, 0.5f, 0.75f));
    preview(records, {});
    EXPECT_EQ(denoiser.calls, 1);
    shown = readPfm(settings.outputPath);
    EXPECT_EQ(shown.at(3, 1), glm::vec3(1.0f));
}

} // namespace
} // namespace vkpt::live_preview_test
