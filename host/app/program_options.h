// program_options.h — the command line of vkpt and vkpt-ref: the options both take (image,
// integrator, scene, run, convergence, farm), each program's own, --help, the scene file and
// the checks across options, parsed by one function so that the two programs cannot drift.
#pragma once

#include <functional>

#include "app/command_line.h"
#include "app/convergence_options.h"
#include "app/farm_options.h"
#include "app/frame_options.h"
#include "common/render_settings.h"

namespace vkpt {

struct ProgramOptions {
    RenderSettings settings;
    ConvergenceSettings convergence;
    FarmSettings farm;
    FrameSettings frames;
    bool showHelp = false;
};

// What a program adds to the shared command line.
struct ProgramCommandLine {
    std::string program; // in messages and the usage line
    // Adds the program's own options, listed after the shared ones and before --help.
    std::function<void(CommandLine&)> addOwnOptions;
    // True when the options given ask for no render (vkpt --list-devices): then no scene file
    // is required and the settings are not checked.
    std::function<bool()> rendersNothing;
};

// Parses argv into `options`. On --help prints the usage and sets showHelp; otherwise takes
// the one scene file and checks the settings. Throws InputError naming the option.
void parseProgramOptions(const ProgramCommandLine& commandLine, ProgramOptions& options, int argc,
                         char** argv);

} // namespace vkpt
