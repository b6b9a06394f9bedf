// farm_cli_test.cpp — the command-line contract of distributed rendering, with real processes as
// a scheduler runs them: a task killed with SIGKILL after a checkpoint, or stopped by SIGTERM,
// resumes to the image of the uninterrupted run; output paths are checked before the scene
// loads; a final write that fails saves the state to a rescue file; vkpt-merge refuses parts
// that do not belong together, one line naming the file, and writes nothing; device and CPU
// parts merge; and the EXR's channels are what OpenImageIO's oiiotool, a compositor's tool,
// reads.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "../support/child_process.h"
#include "../support/test_directory.h"
#include "state/state_file.h"

namespace vkpt::test::farm_cli_test {
namespace {

const std::string kScene = VKPT_SCENES_DIR "/cornell-box.gltf";

std::vector<std::string> command(const char* program, std::vector<std::string> arguments) {
    arguments.insert(arguments.begin(), program);
    arguments.push_back(kScene);
    return arguments;
}

int lineCount(const std::string& text) {
    return int(std::count(text.begin(), text.end(), '\n'));
}

class FarmCli : public TestDirectory {
protected:
    FarmCli() : TestDirectory("vkpt_farm_cli") {}

    // A part of a 16×16 render: task 1 of 2 of `spp` samples.
    std::vector<std::string> task(const char* program, std::uint32_t spp, const std::string& out,
                                  std::vector<std::string> extra = {}) {
        std::vector<std::string> a = {
            "-q", "--spp",  std::to_string(spp), "--res", "16", "16", "--task", "1/2",
            "-o", path(out)};
        a.insert(a.end(), extra.begin(), extra.end());
        return command(program, a);
    }

    // Same counts and samples, means within `relative` (a float rounding for the reference,
    // whose state file keeps ~48 bits of its double sums; the device's Kahan sums for vkpt).
    void expectSameState(const std::string& a, const std::string& b, double relative) {
        const RenderState x = readStateFile(path(a)), y = readStateFile(path(b));
        ASSERT_EQ(x.pixels.size(), y.pixels.size());
        ASSERT_EQ(x.regions.size(), 1u);
        EXPECT_EQ(x.regions[0].ranges, y.regions[0].ranges);
        for (std::size_t i = 0; i < x.pixels.size(); ++i) {
            ASSERT_EQ(x.pixels[i].count, y.pixels[i].count) << "pixel " << i;
            for (int c = 0; c < 3; ++c)
                ASSERT_LE(std::abs(x.pixels[i].mean[c] - y.pixels[i].mean[c]),
                          relative * std::abs(y.pixels[i].mean[c]))
                    << "pixel " << i;
        }
    }

    // Uninterrupted; killed (SIGKILL) after its first checkpoint and resumed; stopped (SIGTERM)
    // and resumed. `started` is the stderr text that says the stop handlers are in place.
    void expectInterruptionsLoseNothing(const char* program, std::uint32_t spp,
                                        const std::string& started, double relative) {
        ASSERT_EQ(runProcess(task(program, spp, "full.exr")).exitCode, 0);

        Child killed =
            spawnWithStderrPipe(task(program, spp, "killed.exr", {"--checkpoint", "0.05"}));
        std::string text;
        if (!readUntil(killed.stderrFd, "checkpoint: wrote", text)) {
            finish(killed, text);
            GTEST_SKIP() << "the render ended before its first checkpoint: " << text;
        }
        kill(killed.pid, SIGKILL);
        EXPECT_EQ(finish(killed, text).signal, SIGKILL);
        const RenderState checkpoint = readStateFile(path("killed.exr"));
        EXPECT_LT(checkpoint.regions[0].ranges.at(0).end, taskEnd(spp)) << "killed too late";
        const Finished resumed =
            runProcess(task(program, spp, "killed.exr", {"--resume", path("killed.exr")}));
        ASSERT_EQ(resumed.exitCode, 0) << resumed.stderrText;
        expectSameState("killed.exr", "full.exr", relative);

        Child stopped = spawnWithStderrPipe(task(program, spp, "stopped.exr"));
        text.clear();
        ASSERT_TRUE(readUntil(stopped.stderrFd, started, text)) << text;
        kill(stopped.pid, SIGTERM);
        const Finished end = finish(stopped, text);
        EXPECT_EQ(end.exitCode, 128 + SIGTERM) << end.stderrText;
        const Finished continued =
            runProcess(task(program, spp, "stopped.exr", {"--resume", path("stopped.exr")}));
        ASSERT_EQ(continued.exitCode, 0) << continued.stderrText;
        expectSameState("stopped.exr", "full.exr", relative);
    }

    static std::uint32_t taskEnd(std::uint32_t spp) { return spp; } // task 1/2 ends at spp

    // vkpt-merge -o out.exr PARTS... must fail with one line naming `culprit`.
    void expectMergeRefused(const std::vector<std::string>& parts, const std::string& culprit,
                            const std::string& reason) {
        std::vector<std::string> a = {VKPT_MERGE, "-o", path("refused.exr")};
        for (const std::string& p : parts)
            a.push_back(path(p));
        const Finished f = runProcess(a);
        EXPECT_EQ(f.exitCode, 1) << f.stderrText;
        EXPECT_EQ(lineCount(f.stderrText), 1) << f.stderrText;
        const std::string prefix = "vkpt-merge: error: " + path(culprit) + ": ";
        EXPECT_EQ(f.stderrText.rfind(prefix, 0), 0u) << f.stderrText;
        EXPECT_NE(f.stderrText.find(reason), std::string::npos) << f.stderrText;
        EXPECT_FALSE(std::filesystem::exists(path("refused.exr")));
    }
};

TEST_F(FarmCli, ReferenceTaskKilledOrStoppedResumesToTheUninterruptedImage) {
    expectInterruptionsLoseNothing(VKPT_REF, 8000, "triangles", 1.0 / (1 << 22));
}

TEST_F(FarmCli, DeviceTaskKilledOrStoppedResumesToTheUninterruptedImage) {
    expectInterruptionsLoseNothing(VKPT, 4000, ": device ", 1e-6);
}

// The message names the output although the scene does not even exist: nothing was loaded.
TEST_F(FarmCli, BadOutputPathsFailBeforeTheSceneLoads) {
    const std::string missing = path("missing/x.png");
    struct Case {
        std::vector<std::string> arguments;
        std::string message;
    };
    const std::vector<Case> cases = {
        {{"-o", missing},
         missing + ": cannot write: the folder '" + path("missing") + "' does not exist"},
        {{"-o", path("x.tiff")},
         path("x.tiff") + ": unknown image extension '.tiff' (use .png, .pfm, .hdr or .exr)"},
        {{"-o", path("x.exr"), "--stats-json", path("missing/s.json")},
         path("missing/s.json") + ": cannot write: the folder"},
        {{"-o", dir_.string()}, dir_.string() + ": unknown image extension"},
    };
    for (const char* program : {VKPT_REF, VKPT})
        for (const Case& c : cases) {
            std::vector<std::string> a = {program, "--spp", "1"};
            a.insert(a.end(), c.arguments.begin(), c.arguments.end());
            a.push_back(path("no_such_scene.gltf"));
            const Finished f = runProcess(a);
            const std::string name = std::filesystem::path(program).filename().string();
            EXPECT_EQ(f.exitCode, 1) << f.stderrText;
            EXPECT_EQ(lineCount(f.stderrText), 1) << f.stderrText;
            EXPECT_EQ(f.stderrText.rfind(name + ": error: " + c.message, 0), 0u) << f.stderrText;
        }
}

TEST_F(FarmCli, TasksAndAdaptiveSamplingAreRefusedTogether) {
    const Finished f = runProcess(
        command(VKPT_REF, {"--task", "0/2", "--adaptive", "16", "0.1", "-o", path("x.exr")}));
    EXPECT_EQ(f.exitCode, 1);
    EXPECT_EQ(f.stderrText, "vkpt-ref: error: options --task and --adaptive: an adaptive pixel's "
                            "stop depends on all its samples, so tasks cannot share them; split "
                            "by region with --crop\n");
}

TEST_F(FarmCli, AFailedFinalWriteSavesTheStateToARescueFile) {
    std::filesystem::create_directories(path("out"));
    Child child = spawnWithStderrPipe(
        command(VKPT_REF, {"-q", "--spp", "1000000", "--res", "8", "8", "-o", path("out/x.png")}),
        {"TMPDIR=" + dir_.string()});
    std::string text;
    ASSERT_TRUE(readUntil(child.stderrFd, "triangles", text)) << text;
    std::filesystem::remove_all(path("out")); // the folder vanishes under the running render
    kill(child.pid, SIGTERM);
    const Finished f = finish(child, text);
    EXPECT_EQ(f.exitCode, 1) << f.stderrText;
    const std::string rescue = path("vkpt-rescue-" + std::to_string(child.pid) + "-x_state.exr");
    EXPECT_NE(f.stderrText.find("the render's state is saved in " + rescue), std::string::npos)
        << f.stderrText;
    EXPECT_GT(readStateFile(rescue).pixels.at(0).count, 0u);
}

TEST_F(FarmCli, DeviceAndCpuPartsMergeIntoTheReferenceImage) {
    const auto part = [&](const char* program, const std::string& task, const std::string& out) {
        return runProcess(command(
            program, {"-q", "--spp", "12", "--res", "16", "16", "--task", task, "-o", path(out)}));
    };
    ASSERT_EQ(part(VKPT, "0/3", "t0.exr").exitCode, 0);
    ASSERT_EQ(part(VKPT_REF, "1/3", "t1.exr").exitCode, 0);
    ASSERT_EQ(part(VKPT, "2/3", "t2.exr").exitCode, 0);
    ASSERT_EQ(runProcess(command(VKPT_REF,
                                 {"-q", "--spp", "12", "--res", "16", "16", "-o", path("one.exr")}))
                  .exitCode,
              0);
    const Finished merged = runProcess(
        {VKPT_MERGE, "-o", path("merged.exr"), path("t2.exr"), path("t0.exr"), path("t1.exr")});
    ASSERT_EQ(merged.exitCode, 0) << merged.stderrText;
    // The same-seed bound of docs/wavefront.md: 1e-4 relative + 1e-6.
    const RenderState a = readStateFile(path("merged.exr")), b = readStateFile(path("one.exr"));
    std::size_t within = 0;
    for (std::size_t i = 0; i < b.pixels.size(); ++i) {
        ASSERT_EQ(a.pixels[i].count, b.pixels[i].count);
        bool ok = true;
        for (int c = 0; c < 3; ++c)
            ok = ok && std::abs(a.pixels[i].mean[c] - b.pixels[i].mean[c]) <=
                           1e-4 * std::abs(b.pixels[i].mean[c]) + 1e-6;
        within += ok ? 1 : 0;
    }
    EXPECT_GE(double(within), 0.99 * double(b.pixels.size()));
}

TEST_F(FarmCli, MergeRefusesPartsThatDoNotBelongTogether) {
    const auto part = [&](const std::string& out, std::vector<std::string> extra,
                          const std::string& scene = kScene) {
        std::vector<std::string> a = {VKPT_REF, "-q", "--spp", "4",      "--res",
                                      "8",      "8",  "-o",    path(out)};
        a.insert(a.end(), extra.begin(), extra.end());
        a.push_back(scene);
        ASSERT_EQ(runProcess(a).exitCode, 0) << out;
    };
    part("a0.exr", {"--task", "0/2"});
    part("a1.exr", {"--task", "1/2"});
    part("seed.exr", {"--task", "1/2", "--seed", "5"});
    part("depth.exr", {"--task", "1/2", "--max-depth", "2"});
    part("sampler.exr", {"--task", "1/2", "--sampler", "independent"});
    part("scene.exr", {"--task", "1/2"}, VKPT_SCENES_DIR "/furnace.gltf");
    part("all.exr", {});
    std::filesystem::copy_file(path("a1.exr"), path("truncated.exr"));
    std::filesystem::resize_file(path("truncated.exr"),
                                 std::filesystem::file_size(path("a1.exr")) / 2);
    std::filesystem::copy_file(path("a0_rate.png"), path("png.exr"));
    ASSERT_EQ(
        runProcess({"/usr/bin/oiiotool", "--create", "8x8", "3", "-o", path("plain.exr")}).exitCode,
        0)
        << "oiiotool (Debian's openimageio-tools) is a test dependency: bash ci/install_deps.sh";

    expectMergeRefused({"a0.exr", "seed.exr"}, "seed.exr", "seed 5 differs");
    expectMergeRefused({"a0.exr", "depth.exr"}, "depth.exr", "settings");
    expectMergeRefused({"a0.exr", "sampler.exr"}, "sampler.exr", "sampler=independent");
    expectMergeRefused({"a0.exr", "scene.exr"}, "scene.exr", "another scene than");
    expectMergeRefused({"a0.exr", "all.exr"}, "all.exr", "its samples [0,4)");
    expectMergeRefused({"a0.exr", "truncated.exr"}, "truncated.exr", "");
    expectMergeRefused({"a0.exr", "png.exr"}, "png.exr", "not a readable OpenEXR render state");
    expectMergeRefused({"a0.exr", "plain.exr"}, "plain.exr", "without vkpt's metadata");
    expectMergeRefused({"a0.exr", "gone.exr"}, "gone.exr", "cannot read: No such file");
    const Finished ok =
        runProcess({VKPT_MERGE, "-o", path("ok.exr"), path("a1.exr"), path("a0.exr")});
    EXPECT_EQ(ok.exitCode, 0) << ok.stderrText;
}

// What a compositor sees: the layers by name, and each one extracted on its own.
TEST_F(FarmCli, OiiotoolReadsTheImageAndItsLayers) {
    ASSERT_EQ(runProcess(command(VKPT_REF, {"-q", "--spp", "2", "--res", "8", "8", "--crop", "2",
                                            "1", "7", "6", "-o", path("crop.exr")}))
                  .exitCode,
              0);
    const std::string info = path("info.txt");
    const std::string shell = "/usr/bin/oiiotool --info -v " + path("crop.exr") + " > " + info;
    ASSERT_EQ(std::system(shell.c_str()), 0) << "oiiotool (openimageio-tools) is missing";
    std::ifstream in(info);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    for (const char* channel :
         {"R (float)", "G (float)", "B (float)", "albedo.R (float)", "albedo.B (float)",
          "normal.X (float)", "normal.Z (float)", "Z (float)", "sampleCount (float)",
          "variance (float)", "vkpt.count (uint)", "vkpt.samplesTaken (uint)",
          "vkpt.luminanceM2 (float)", "vkpt.meanLo.R (float)"})
        EXPECT_NE(text.find(channel), std::string::npos) << channel << " in\n" << text;
    EXPECT_NE(text.find("full/display size: 8 x 8"), std::string::npos) << text;
    EXPECT_NE(text.find("pixel data origin: x=2, y=1"), std::string::npos) << text; // the crop
    EXPECT_NE(text.find("vkpt.regions: \"2 1 7 6 [0,2)\""), std::string::npos) << text;
    const Finished albedo = runProcess({"/usr/bin/oiiotool", path("crop.exr"), "--ch",
                                        "albedo.R,albedo.G,albedo.B", "-o", path("albedo.exr")});
    EXPECT_EQ(albedo.exitCode, 0) << albedo.stderrText;
}

} // namespace
} // namespace vkpt::test::farm_cli_test
