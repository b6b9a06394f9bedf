// program_options.cpp — the shared options in the order --help lists them, then the scene.
#include "app/program_options.h"

#include <cstdio>
#include <string>
#include <vector>

#include "app/render_options.h"
#include "common/errors.h"

namespace vkpt {

void parseProgramOptions(const ProgramCommandLine& program, ProgramOptions& options, int argc,
                         char** argv) {
    CommandLine commandLine(program.program);
    addRenderOptions(commandLine, options.settings);
    addConvergenceOptions(commandLine, options.convergence);
    addFarmOptions(commandLine, options.farm);
    addFrameOptions(commandLine, options.frames);
    if (program.addOwnOptions) program.addOwnOptions(commandLine);
    commandLine.add({"help", {'h'}, "", "show this help", [&](auto) { options.showHelp = true; }});
    std::vector<std::string> arguments(argv + 1, argv + argc);
    std::vector<std::string> positional = commandLine.parse(arguments);
    if (options.showHelp) {
        std::fputs(commandLine.usage("scene.gltf|scene.glb").c_str(), stdout);
        return;
    }
    if (program.rendersNothing && program.rendersNothing()) return;
    if (positional.size() > 1) throw InputError("more than one scene file given");
    if (!positional.empty()) options.settings.scenePath = positional[0];
    validateRenderSettings(options.settings);
    validateFarmSettings(options.farm, options.settings);
    validateFrameSettings(options.frames, options.settings);
}

} // namespace vkpt
