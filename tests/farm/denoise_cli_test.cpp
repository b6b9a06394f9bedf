// denoise_cli_test.cpp — the denoiser through the command line: vkpt and vkpt-ref write the same
// denoised image at one seed (as they do the raw one); a farm render merged and then denoised by
// vkpt-denoise equals the one-run render denoised; an .exr keeps the raw image; and
// vkpt-denoise refuses what it cannot denoise with one line, writing nothing. 16×16 at 8 spp:
// enough pixels for the filter's steps, seconds on lavapipe.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "../support/child_process.h"
#include "../support/test_directory.h"
#include "image/image_io.h"
#include "state/state_file.h"

namespace vkpt::test::denoise_cli_test {
namespace {

const std::string kScene = VKPT_SCENES_DIR "/cornell-box.gltf";

class DenoiseCli : public TestDirectory {
protected:
    DenoiseCli() : TestDirectory("vkpt_denoise_cli") {}

    Finished render(const char* program, const std::string& out,
                    std::vector<std::string> extra = {}) {
        std::vector<std::string> a = {program, "-q", "--spp", "8",      "--res",
                                      "16",    "16", "-o",    path(out)};
        a.insert(a.end(), extra.begin(), extra.end());
        a.push_back(kScene);
        return runProcess(a);
    }

    Finished denoise(const std::string& in, const std::string& out,
                     std::vector<std::string> extra = {}) {
        std::vector<std::string> a = {VKPT_DENOISE, "-q", path(in), "-o", path(out)};
        a.insert(a.end(), extra.begin(), extra.end());
        return runProcess(a);
    }

    // Images equal within the same-seed bound of docs/wavefront.md (1e-4 relative + 1e-6) in
    // at least `share` of the pixels.
    void expectSameImage(const std::string& a, const std::string& b, double share) {
        const Image x = readPfm(path(a)), y = readPfm(path(b));
        ASSERT_EQ(x.pixels.size(), y.pixels.size());
        std::size_t within = 0;
        for (std::size_t i = 0; i < x.pixels.size(); ++i) {
            bool ok = true;
            for (int c = 0; c < 3; ++c)
                ok = ok && std::abs(x.pixels[i][c] - y.pixels[i][c]) <=
                               1e-4f * std::abs(y.pixels[i][c]) + 1e-6f;
            within += ok ? 1 : 0;
        }
        EXPECT_GE(double(within), share * double(x.pixels.size())) << a << " vs " << b;
    }

    void expectRefused(const std::string& in, const std::string& reason) {
        const Finished f = denoise(in, "refused.png");
        EXPECT_EQ(f.exitCode, 1) << f.stderrText;
        EXPECT_EQ(std::count(f.stderrText.begin(), f.stderrText.end(), '\n'), 1) << f.stderrText;
        EXPECT_EQ(f.stderrText.rfind("vkpt-denoise: error: " + path(in) + ": ", 0), 0u)
            << f.stderrText;
        EXPECT_NE(f.stderrText.find(reason), std::string::npos) << f.stderrText;
        EXPECT_FALSE(std::filesystem::exists(path("refused.png")));
    }
};

TEST_F(DenoiseCli, DeviceAndReferenceDenoiseAlike) {
    ASSERT_EQ(
        render(VKPT, "device.pfm", {"--denoise", "--stats-json", path("stats.json")}).exitCode, 0);
    ASSERT_EQ(render(VKPT_REF, "reference.pfm", {"--denoise"}).exitCode, 0);
    ASSERT_EQ(render(VKPT_REF, "raw.pfm").exitCode, 0);
    expectSameImage("device.pfm", "reference.pfm", 0.99);
    // And the denoiser did something: the raw image differs.
    const Image raw = readPfm(path("raw.pfm")), denoised = readPfm(path("reference.pfm"));
    EXPECT_NE(raw.pixels, denoised.pixels);
    // Its time is a phase of its own.
    std::ifstream stats(path("stats.json"));
    const std::string json((std::istreambuf_iterator<char>(stats)), {});
    EXPECT_NE(json.find("\"name\": \"denoise\""), std::string::npos) << json;
}

TEST_F(DenoiseCli, MergedFarmRenderDenoisesLikeOneRun) {
    ASSERT_EQ(render(VKPT_REF, "t0.exr", {"--task", "0/2"}).exitCode, 0);
    ASSERT_EQ(render(VKPT_REF, "t1.exr", {"--task", "1/2"}).exitCode, 0);
    ASSERT_EQ(
        runProcess({VKPT_MERGE, "-q", "-o", path("merged.exr"), path("t0.exr"), path("t1.exr")})
            .exitCode,
        0);
    ASSERT_EQ(render(VKPT_REF, "one.exr").exitCode, 0);
    const Finished merged = denoise("merged.exr", "merged.pfm");
    ASSERT_EQ(merged.exitCode, 0) << merged.stderrText;
    ASSERT_EQ(denoise("one.exr", "one.pfm").exitCode, 0);
    ASSERT_EQ(denoise("one.exr", "one_cpu.pfm", {"--cpu"}).exitCode, 0);
    expectSameImage("merged.pfm", "one.pfm", 0.99);
    expectSameImage("one.pfm", "one_cpu.pfm", 0.99);
}

TEST_F(DenoiseCli, AnExrKeepsTheRawImage) {
    ASSERT_EQ(render(VKPT_REF, "raw.exr").exitCode, 0);
    ASSERT_EQ(render(VKPT_REF, "denoised.exr", {"--denoise"}).exitCode, 0);
    // The raw layer reads back as the state: the same moments as the render without --denoise.
    const RenderState raw = readStateFile(path("raw.exr"));
    const RenderState kept = readStateFile(path("denoised.exr"));
    ASSERT_EQ(raw.pixels.size(), kept.pixels.size());
    for (std::size_t i = 0; i < raw.pixels.size(); ++i)
        ASSERT_EQ(raw.pixels[i].mean, kept.pixels[i].mean) << "pixel " << i;
    EXPECT_EQ(kept.features.size(), kept.pixels.size());
}

TEST_F(DenoiseCli, RefusesWhatItCannotDenoise) {
    expectRefused("missing.exr", "");
    ASSERT_EQ(render(VKPT_REF, "image.png").exitCode, 0);
    expectRefused("image.png", "");
    // A state without AOV layers: written as a render stopped before it had any would be.
    RenderState bare = readStateFile([&] {
        EXPECT_EQ(render(VKPT_REF, "full.exr").exitCode, 0);
        return path("full.exr");
    }());
    bare.features.clear();
    writeStateFile(bare, path("bare.exr"));
    expectRefused("bare.exr", "no albedo, normal and depth layers");
    const Finished noOutput = runProcess({VKPT_DENOISE, path("full.exr")});
    EXPECT_EQ(noOutput.exitCode, 1);
    EXPECT_NE(noOutput.stderrText.find("no output given"), std::string::npos);
}

} // namespace
} // namespace vkpt::test::denoise_cli_test
