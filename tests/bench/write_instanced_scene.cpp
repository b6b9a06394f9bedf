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
#include "bench_options.h"
#include "common/errors.h"
#include "instanced_scene.h"

namespace {

const char* const kProgram = "write_instanced_scene";

int writeScene(int argc, char** argv) {
    vkpt::test::InstancedSceneSpec spec;
    vkpt::CommandLine commandLine(kProgram);
    commandLine.add({"grid", {'g'}, "N", "N × N placements (default 4)", [&](auto v) {
                         spec.columns = spec.rows = vkpt::parseUnsigned("grid", v[0], 1);
                     }});
    commandLine.add({"rings", {}, "R", "4·R² triangles per sphere (default 6)", [&](auto v) {
                         spec.rings = vkpt::parseUnsigned("rings", v[0], 2);
                     }});
    std::vector<std::string> positional =
        vkpt::bench::parseBenchArguments(commandLine, argc, argv, "out.gltf");
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
