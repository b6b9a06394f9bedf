// write_room_scene.cpp — writes the benchmarks' generated room with the displaced sphere
// (tests/support/room_scene.h) as a .gltf with a .bin beside it, so that vkpt, vkpt-ref and
// embree-ref can be timed as whole processes on the same file.
//
//   write_room_scene [--triangles N] [--textured] out.gltf      (default 1,000,000 triangles)
#include <cstdio>
#include <string>
#include <vector>

#include "../support/room_scene.h"
#include "app/command_line.h"
#include "app/run_program.h"
#include "bench_options.h"
#include "common/errors.h"

namespace {

const char* const kProgram = "write_room_scene";

int writeScene(int argc, char** argv) {
    std::uint32_t triangles = 1000000;
    bool textured = false;
    vkpt::CommandLine commandLine(kProgram);
    commandLine.add({"triangles", {'n'}, "N", "about N triangles (default 1000000)", [&](auto v) {
                         triangles = vkpt::parseUnsigned("triangles", v[0], 8);
                     }});
    commandLine.add({"textured",
                     {},
                     "",
                     "texture the sphere (TEXCOORD_0 per vertex and a base colour texture)",
                     [&](auto) { textured = true; }});
    std::vector<std::string> positional =
        vkpt::bench::parseBenchArguments(commandLine, argc, argv, "out.gltf");
    if (positional.size() != 1) throw vkpt::InputError("give one output file (see --help)");
    vkpt::test::RoomScene room = vkpt::test::makeRoomScene(triangles, textured);
    vkpt::test::writeRoomSceneGltf(room, positional[0]);
    std::printf("%s: %zu triangles\n", positional[0].c_str(), room.triangleCount());
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    return vkpt::runProgram(kProgram, [argc, argv] { return writeScene(argc, argv); });
}
