// bench_options.h — the options the benchmarks share (--spp, --res, --runs, the scenes, --help),
// one definition parsed by the renderers' own CommandLine, so that a benchmark rejects a
// mistyped option or number the way vkpt does instead of taking it for a scene file.
#pragma once

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "app/command_line.h"
#include "common/render_settings.h"

namespace vkpt::bench {

// What a render benchmark renders and how often; each benchmark sets its own defaults.
struct RenderBenchOptions {
    std::uint32_t spp = 16;
    std::uint32_t width = 256;
    std::uint32_t height = 256;
    int runs = 3;
    std::vector<std::string> scenes;

    // The settings of a timed render: this size and sample count, no progress output.
    RenderSettings settings() const {
        RenderSettings s;
        s.width = width;
        s.height = height;
        s.samplesPerPixel = spp;
        s.quiet = true;
        return s;
    }
};

// --spp N; the help text names the value given as the default.
inline void addSamplesOption(CommandLine& commandLine, RenderBenchOptions& o) {
    commandLine.add(
        {"spp", {}, "N", "samples per pixel (default " + std::to_string(o.spp) + ")", [&o](auto v) {
             o.spp = parseUnsigned("spp", v[0], 1);
         }});
}

// --res W H, described as `what` followed by the default.
inline void addResolutionOption(CommandLine& commandLine, RenderBenchOptions& o,
                                const std::string& what = "image size") {
    commandLine.add(
        {"res",
         {},
         "W H",
         what + " (default " + std::to_string(o.width) + " " + std::to_string(o.height) + ")",
         [&o](auto v) {
             o.width = parseUnsigned("res", v[0], 1);
             o.height = parseUnsigned("res", v[1], 1);
         }});
}

// --runs N: timed runs, of which the benchmark prints medians.
inline void addRunsOption(CommandLine& commandLine, RenderBenchOptions& o,
                          const std::string& what = "timed runs per scene, medians printed") {
    commandLine.add(
        {"runs", {}, "N", what + " (default " + std::to_string(o.runs) + ")", [&o](auto v) {
             o.runs = int(parseUnsigned("runs", v[0], 1));
         }});
}

// --spp N, --res W H and --runs N.
inline void addRenderBenchOptions(CommandLine& commandLine, RenderBenchOptions& o) {
    addSamplesOption(commandLine, o);
    addResolutionOption(commandLine, o);
    addRunsOption(commandLine, o);
}

// Adds --help and parses the arguments; on --help prints the usage (`operands` after the
// options) and exits. Returns the operands.
inline std::vector<std::string> parseBenchArguments(CommandLine& commandLine, int argc, char** argv,
                                                    const std::string& operands = "[scene ...]") {
    bool help = false;
    commandLine.add({"help", {'h'}, "", "show this help", [&help](auto) { help = true; }});
    std::vector<std::string> positional =
        commandLine.parse(std::vector<std::string>(argv + 1, argv + argc));
    if (help) {
        std::fputs(commandLine.usage(operands).c_str(), stdout);
        std::exit(0);
    }
    return positional;
}

// The scenes of the render benchmarks when none is given: the Cornell box and the largest
// shared scene (tests/image's sharedScenePath; absent on a machine without it).
inline std::vector<std::string> defaultBenchScenes() {
    return {std::string(VKPT_SCENES_DIR) + "/cornell-box.gltf",
            std::string(VKPT_SCENES_DIR) +
                "/../../shared/scenes/TransmissionTest/TransmissionTest.glb"};
}

} // namespace vkpt::bench
