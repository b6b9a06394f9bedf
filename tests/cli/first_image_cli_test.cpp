// first_image_cli_test.cpp — a published asset's first image as a new user makes it, through
// both programs: a scene without lights is lit by the default studio and says so once; one with
// lights, or with an environment asked for (black included), is left as it is; --tonemap acts
// on 8-bit output after the exposure and on nothing else; and --preview writes a readable image
// while the render still runs, with crops, adaptive sampling, tasks and resume.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <regex>
#include <thread>

#include "../support/child_process.h"
#include "../support/decode_png.h"
#include "../support/test_directory.h"
#include "image/image_compare.h"
#include "image/image_io.h"
#include "image/tone_map.h"
#include "shared/sampling.h"
#include "state/state_file.h"

namespace vkpt::test::first_image_cli_test {
namespace {

const std::string kSpheres = VKPT_SCENES_DIR "/test/metal-rough-spheres.gltf";
const std::string kCornell = VKPT_SCENES_DIR "/cornell-box.gltf";
const std::string kToyCar = VKPT_SCENES_DIR "/../../shared/scenes/ToyCar/ToyCar.gltf";
const std::string kStudioLine = "lit by the default studio environment";
const std::string kInsideOutBox = VKPT_SCENES_DIR "/test/inside-out-box.gltf";
const std::string kUnlitLine = "pixels received any light; check for single-sided";

int linesContaining(const std::string& text, const std::string& part) {
    int count = 0;
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        if (text.substr(start, end - start).find(part) != std::string::npos) ++count;
        start = end + 1;
    }
    return count;
}

double meanOf(const Image& image) {
    double sum = 0.0;
    for (const glm::vec3& p : image.pixels)
        sum += double(gpu::luminance(p));
    return sum / double(image.pixels.size());
}

class FirstImage : public TestDirectory, public ::testing::WithParamInterface<const char*> {
protected:
    FirstImage() : TestDirectory("vkpt_first_image") {}

    std::vector<std::string> command(std::vector<std::string> arguments,
                                     const std::string& scene) const {
        arguments.insert(arguments.begin(), GetParam());
        arguments.push_back(scene);
        return arguments;
    }

    Finished render(std::vector<std::string> arguments, const std::string& scene) const {
        Finished f = runProcess(command(std::move(arguments), scene));
        EXPECT_EQ(f.exitCode, 0) << f.stderrText;
        return f;
    }
};

std::string programName(const ::testing::TestParamInfo<const char*>& info) {
    return std::filesystem::path(info.param).filename() == "vkpt" ? "vkpt" : "vkpt_ref";
}

// What the published asset's screenshot shows (a green car on red cloth), not black with two
// headlight glints: ToyCar's emissive texture emits 1.9e-4 of the studio's power. 64² at 16
// samples is enough to tell the two apart: the lit image's mean luminance is 0.185 (either
// program), with a standard error of its pixels' mean of 0.003, against the bound of 0.05.
TEST_P(FirstImage, ToyCarWithoutOptionsIsLitAndSaysSoOnce) {
    if (!std::filesystem::exists(kToyCar)) GTEST_SKIP() << kToyCar << " is not present";
    const Finished f = render({"--spp", "16", "--res", "64", "64", "-o", path("car.pfm")}, kToyCar);
    EXPECT_EQ(linesContaining(f.stderrText, kStudioLine), 1) << f.stderrText;
    EXPECT_EQ(linesContaining(f.stderrText, "--default-light off"), 1) << f.stderrText;
    EXPECT_GE(meanOf(readPfm(path("car.pfm"))), 0.05);
}

TEST_P(FirstImage, SpheresWithoutEmittersOrCameraRenderLit) {
    const Finished f =
        render({"-q", "--spp", "8", "--res", "32", "24", "-o", path("s.pfm")}, kSpheres);
    EXPECT_EQ(linesContaining(f.stderrText, kStudioLine), 1) << f.stderrText;
    EXPECT_GE(meanOf(readPfm(path("s.pfm"))), 0.05);
}

TEST_P(FirstImage, AnEnvironmentOfZeroOrTheDefaultLightOffKeepsTheSceneBlack) {
    for (const std::vector<std::string>& option :
         {std::vector<std::string>{"--env-color", "0", "0", "0"},
          std::vector<std::string>{"--default-light", "off"}}) {
        std::vector<std::string> arguments = {"-q", "--spp", "4",  "--res",
                                              "16", "16",    "-o", path("black.pfm")};
        arguments.insert(arguments.end(), option.begin(), option.end());
        const Finished f = render(arguments, kSpheres);
        EXPECT_EQ(linesContaining(f.stderrText, kStudioLine), 0) << f.stderrText;
        EXPECT_EQ(linesContaining(f.stderrText, "has no emitters"), 1) << f.stderrText;
        for (const glm::vec3& p : readPfm(path("black.pfm")).pixels)
            ASSERT_EQ(p, glm::vec3(0.0f)) << option.front();
    }
}

// The Cornell box has its light: the same image, bit for bit, whether the default may apply
// (and no warning that nothing is lit).
TEST_P(FirstImage, ASceneWithLightsGetsNoExtraLight) {
    const Finished f =
        render({"-q", "--spp", "4", "--res", "16", "16", "-o", path("a.pfm")}, kCornell);
    EXPECT_EQ(linesContaining(f.stderrText, kStudioLine), 0) << f.stderrText;
    EXPECT_EQ(linesContaining(f.stderrText, kUnlitLine), 0) << f.stderrText;
    render({"-q", "--spp", "4", "--res", "16", "16", "--default-light", "off", "-o", path("b.pfm")},
           kCornell);
    EXPECT_EQ(bytesOf(path("a.pfm")), bytesOf(path("b.pfm")));
}

// A camera inside a crate of single-sided faces turned out, with the light facing away: every
// face is seen from behind, so the image is black, and the program says what to check, once.
// 8 x 8 pixels at 2 samples: every pixel is black whatever the samples.
TEST_P(FirstImage, ACameraThatSeesNothingLitSaysWhatToCheckOnce) {
    const Finished f =
        render({"-q", "--spp", "2", "--res", "8", "8", "-o", path("crate.pfm")}, kInsideOutBox);
    EXPECT_EQ(linesContaining(f.stderrText, kUnlitLine), 1) << f.stderrText;
    EXPECT_EQ(linesContaining(f.stderrText, "0 of 64 pixels"), 1) << f.stderrText;
    EXPECT_EQ(linesContaining(f.stderrText, kStudioLine), 0) << f.stderrText;
}

// The decision is part of the render's identity (through the environment the scene hash covers):
// a part lit by the studio and one kept dark are not one render.
TEST_P(FirstImage, PartsLitDifferentlyDoNotMerge) {
    const auto part = [&](const std::string& task, const std::string& out,
                          std::vector<std::string> extra) {
        std::vector<std::string> a = {"-q", "--spp",  "4",  "--res", "8",
                                      "8",  "--task", task, "-o",    path(out)};
        a.insert(a.end(), extra.begin(), extra.end());
        render(a, kSpheres);
    };
    part("0/2", "lit.exr", {});
    part("1/2", "dark.exr", {"--default-light", "off"});
    const Finished f =
        runProcess({VKPT_MERGE, "-o", path("merged.exr"), path("lit.exr"), path("dark.exr")});
    EXPECT_EQ(f.exitCode, 1);
    EXPECT_EQ(linesContaining(f.stderrText, path("dark.exr") + ": another scene than"), 1)
        << f.stderrText;
    EXPECT_FALSE(std::filesystem::exists(path("merged.exr")));
}

// Each PNG byte is the sRGB encoding of the tone-mapped, exposed linear value of the PFM of the
// same render; the PFM does not depend on the tone map.
TEST_P(FirstImage, ToneMapsApplyAfterTheExposureToEightBitOutputOnly) {
    const auto run = [&](const std::string& toneMap, const std::string& output) {
        render({"-q", "--spp", "4", "--res", "16", "12", "--exposure", "1", "--tonemap", toneMap,
                "-o", path(output)},
               kSpheres);
    };
    run("clamp", "clamp.pfm");
    run("neutral", "neutral.pfm");
    EXPECT_EQ(bytesOf(path("clamp.pfm")), bytesOf(path("neutral.pfm")));
    const Image linear = readPfm(path("neutral.pfm"));
    for (ToneMap toneMap : {ToneMap::Clamp, ToneMap::PbrNeutral}) {
        const std::string name = std::string(toneMapName(toneMap)) + ".png";
        run(toneMapName(toneMap), name);
        int width = 0, height = 0;
        const std::vector<std::uint8_t> rgb = decodePng(path(name), width, height);
        ASSERT_EQ(rgb.size(), linear.pixels.size() * 3) << name;
        std::size_t below = 0;
        for (std::size_t i = 0; i < linear.pixels.size(); ++i) {
            const glm::vec3 display = applyToneMap(toneMap, 2.0f * linear.pixels[i]);
            for (int c = 0; c < 3; ++c) {
                ASSERT_EQ(rgb[3 * i + std::size_t(c)],
                          std::lround(double(linearToSrgb(display[c])) * 255.0))
                    << name << " pixel " << i;
                below += rgb[3 * i + std::size_t(c)] < 255;
            }
        }
        if (toneMap == ToneMap::PbrNeutral) {
            EXPECT_EQ(below, rgb.size()) << "neutral clipped";
        }
    }
    const Finished f = runProcess(command({"--tonemap", "aces"}, kSpheres));
    EXPECT_EQ(f.exitCode, 1);
    EXPECT_EQ(f.stderrText, std::filesystem::path(GetParam()).filename().string() +
                                ": error: option --tonemap: 'aces' is not one of neutral, clamp\n");
}

// --- previews ---------------------------------------------------------------------------------

class Preview : public FirstImage {
protected:
    // Starts a render far longer than the test, waits (up to a minute) for `output` to appear
    // while the process still runs, checks it with `readable`, then stops the render (SIGTERM)
    // and checks that it ended as a stopped render does, with the final image in place.
    void expectPreview(std::vector<std::string> arguments, const std::string& scene,
                       const std::string& output,
                       const std::function<void(const std::string&)>& readable) {
        arguments.insert(arguments.end(),
                         {"-q", "--spp", "1000000", "--preview", "0.3", "-o", path(output)});
        Child child = spawnWithStderrPipe(command(arguments, scene));
        ASSERT_GT(child.pid, 0);
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
        bool running = true;
        while (!std::filesystem::exists(path(output)) && running &&
               std::chrono::steady_clock::now() < deadline) {
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
            running = waitpid(child.pid, nullptr, WNOHANG) == 0;
        }
        ASSERT_TRUE(running) << "the render ended before a preview appeared";
        ASSERT_TRUE(std::filesystem::exists(path(output))) << "no preview within a minute";
        EXPECT_EQ(waitpid(child.pid, nullptr, WNOHANG), 0) << "the render ended too soon";
        readable(path(output));
        kill(child.pid, SIGTERM);
        const Finished f = finish(child);
        EXPECT_EQ(f.exitCode, 143) << f.stderrText;
        readable(path(output));
        for (const auto& entry : std::filesystem::directory_iterator(dir_))
            EXPECT_NE(entry.path().filename().string().front(), '.')
                << "a temporary file was left: " << entry.path();
    }

    static void expectPng(const std::string& file, int width, int height) {
        int w = 0, h = 0;
        EXPECT_FALSE(decodePng(file, w, h).empty()) << file << " does not decode";
        EXPECT_EQ(w, width);
        EXPECT_EQ(h, height);
    }
};

TEST_P(Preview, APngPreviewIsReadableBeforeTheRenderEnds) {
    expectPreview({"--res", "24", "16"}, kSpheres, "p.png",
                  [](const std::string& file) { expectPng(file, 24, 16); });
}

TEST_P(Preview, ACroppedAdaptivePreviewHoldsItsCrop) {
    expectPreview(
        {"--res", "24", "24", "--crop", "8", "8", "20", "16", "--adaptive", "16", "0.00001"},
        kSpheres, "p.pfm", [](const std::string& file) {
            const Image image = readPfm(file);
            ASSERT_EQ(image.pixels.size(), 24u * 24u);
            EXPECT_EQ(image.at(2, 2), glm::vec3(0.0f)); // outside the crop
            EXPECT_GT(image.at(12, 12).x, 0.0f);
        });
}

TEST_P(Preview, ATaskWritesItsStateAsItsPreview) {
    expectPreview({"--res", "16", "16", "--task", "0/2"}, kSpheres, "p.exr",
                  [](const std::string& file) {
                      const RenderState state = readStateFile(file);
                      ASSERT_FALSE(state.pixels.empty());
                      EXPECT_GT(state.pixels.front().count, 0u);
                  });
}

TEST_P(Preview, AResumedRenderPreviewsWhatItHasAndWhatItAdds) {
    render({"-q", "--spp", "4", "--res", "16", "16", "-o", path("first.exr")}, kSpheres);
    expectPreview({"--res", "16", "16", "--resume", path("first.exr")}, kSpheres, "r.png",
                  [](const std::string& file) { expectPng(file, 16, 16); });
}

INSTANTIATE_TEST_SUITE_P(Programs, FirstImage, ::testing::Values(VKPT, VKPT_REF), programName);
INSTANTIATE_TEST_SUITE_P(Programs, Preview, ::testing::Values(VKPT, VKPT_REF), programName);

} // namespace
} // namespace vkpt::test::first_image_cli_test
