// write_instanced_scene.cpp — writes the instancing scene (tests/support/instanced_scene.h): a
// grid of spheres and boxes, each mesh stored once in the file and placed many times, so that
// vkpt and vkpt-ref can be timed and measured on it flattened and instanced.
//
//   write_instanced_scene [--grid N] [--rings R] out.gltf      (default 4 × 4, rings 6)
#include <cstdio>
#include <string>
#include <vector>

#include "app/command_line.h"
#include "app/run_program.h"
#include "common/errors.h"
#include "instanced_scene.h"

namespace {

const char* const kProgram = "write_instanced_scene";

int writeScene(int argc, char** argv) {
    vkpt::test::InstancedSceneSpec spec;
    bool help = false;
    vkpt::CommandLine commandLine(kProgram);
    commandLine.add({"grid", {'g'}, "N", "N × N placements (default 4)", [&](auto v) {
                         spec.columns = spec.rows = vkpt::parseUnsigned("grid", v[0], 1);
                     }});
    commandLine.add({"rings", {}, "R", "4·R² triangles per sphere (default 6)", [&](auto v) {
                         spec.rings = vkpt::parseUnsigned("rings", v[0], 2);
                     }});
    commandLine.add({"help", {'h'}, "", "show this help", [&](auto) { help = true; }});
    std::vector<std::string> positional =
        commandLine.parse(std::vector<std::string>(argv + 1, argv + argc));
    if (help) {
        std::fputs(commandLine.usage("out.gltf").c_str(), stdout);
        return 0;
    }
    if (positional.size() != 1) throw vkpt::InputError("give one output file (see --help)");
    spec.separateBuffer = true;
    vkpt::test::writeInstancedScene(spec, positional[0]);
    std::printf("%s: %llu triangles placed\n", positional[0].c_str(),
                static_cast<unsigned long long>(vkpt::test::instancedScenePlacedTriangles(spec)));
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    return vkpt::runProgram(kProgram, [argc, argv] { return writeScene(argc, argv); });
}
