// bench_options.h — the options the render benchmarks share (--spp, --res, --runs, --help),
// parsed by the renderers' own CommandLine, so that a benchmark rejects a mistyped option or
// number the way vkpt does instead of taking it for a scene file.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "app/command_line.h"

namespace vkpt::bench {

// --spp N, --res W H and --runs N; the help text names the values given as defaults.
inline void addRenderBenchOptions(CommandLine& commandLine, std::uint32_t& spp,
                                  std::uint32_t& width, std::uint32_t& height, int& runs) {
    commandLine.add(
        {"spp", {}, "N", "samples per pixel (default " + std::to_string(spp) + ")", [&spp](auto v) {
             spp = parseUnsigned("spp", v[0], 1);
         }});
    commandLine.add(
        {"res",
         {},
         "W H",
         "image size (default " + std::to_string(width) + " " + std::to_string(height) + ")",
         [&width, &height](auto v) {
             width = parseUnsigned("res", v[0], 1);
             height = parseUnsigned("res", v[1], 1);
         }});
    commandLine.add({"runs",
                     {},
                     "N",
                     "timed runs per scene, medians printed (default " + std::to_string(runs) + ")",
                     [&runs](auto v) { runs = int(parseUnsigned("runs", v[0], 1)); }});
}

// Adds --help, parses the arguments and returns the scene files; on --help prints the usage
// and exits.
inline std::vector<std::string> parseBenchArguments(CommandLine& commandLine, int argc,
                                                    char** argv) {
    bool help = false;
    commandLine.add({"help", {'h'}, "", "show this help", [&help](auto) { help = true; }});
    std::vector<std::string> scenes =
        commandLine.parse(std::vector<std::string>(argv + 1, argv + argc));
    if (help) {
        std::fputs(commandLine.usage("[scene ...]").c_str(), stdout);
        std::exit(0);
    }
    return scenes;
}

} // namespace vkpt::bench
