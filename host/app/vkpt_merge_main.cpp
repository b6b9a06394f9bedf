// vkpt_merge_main.cpp — vkpt-merge: the parts of one render (tasks, crops, checkpoints, from vkpt
// and vkpt-ref alike) combined into one image and one state, exactly as one run of all their
// samples would have accumulated them. Parts that do not belong together are refused, one line
// naming the file and the reason, before anything is written.
#include <cstdio>
#include <string>
#include <vector>

#include "app/command_line.h"
#include "app/output_checks.h"
#include "app/run_program.h"
#include "app/scene_setup.h"
#include "common/errors.h"
#include "image/image_file.h"
#include "image/image_io.h"
#include "state/state_file.h"
#include "state/state_merge.h"

namespace {

using namespace vkpt;

const char* const kProgram = "vkpt-merge";

struct Invocation {
    std::string outputPath;
    std::vector<std::string> parts;
    bool quiet = false;
    bool showHelp = false;
};

Invocation parseArguments(int argc, char** argv) {
    Invocation invocation;
    CommandLine commandLine(kProgram);
    commandLine.add({"output",
                     {'o'},
                     "FILE",
                     ".exr: the merged state and image; .png, .pfm, .hdr: the image, and the "
                     "state beside it (NAME_state.exr)",
                     [&](auto v) { invocation.outputPath = v[0]; }});
    commandLine.add(
        {"quiet", {'q'}, "", "print nothing on success", [&](auto) { invocation.quiet = true; }});
    commandLine.add(
        {"help", {'h'}, "", "show this help", [&](auto) { invocation.showHelp = true; }});
    std::vector<std::string> arguments(argv + 1, argv + argc);
    invocation.parts = commandLine.parse(arguments);
    if (invocation.showHelp) {
        std::fputs(commandLine.usage("PART.exr...").c_str(), stdout);
        return invocation;
    }
    if (invocation.outputPath.empty()) throw InputError("no output given (-o FILE)");
    if (invocation.parts.empty()) throw InputError("no parts given (PART.exr...)");
    return invocation;
}

std::vector<StatePart> readParts(const std::vector<std::string>& paths) {
    std::vector<StatePart> parts;
    for (const std::string& path : paths)
        parts.push_back({path, readStateFile(path)});
    return parts;
}

void writeMerged(const RenderState& merged, const std::string& path) {
    const RenderOutput output = renderOutputOf(merged);
    if (outputHoldsState(path)) {
        writeStateFile(merged, path);
    } else {
        writeImage(output.image, path);
        writeStateFile(merged, statePathFor(path));
    }
    writeSampleCountHeatMap(output.sampleCounts, output.image.width, output.image.height,
                            heatMapPathFor(path));
}

std::string describeRegions(const RenderState& state) {
    std::string text;
    for (const Region& region : state.regions)
        text += (text.empty() ? "" : "; ") + describeRect(region.rect) + ": samples " +
                describeRanges(region.ranges);
    return text;
}

int run(const Invocation& invocation) {
    RenderSettings output;
    output.outputPath = invocation.outputPath;
    checkOutputPaths(output);
    const RenderState merged = mergeStates(readParts(invocation.parts));
    writeMerged(merged, invocation.outputPath);
    if (!invocation.quiet)
        std::printf("%s: %zu parts into %s (%s)\n", kProgram, invocation.parts.size(),
                    invocation.outputPath.c_str(), describeRegions(merged).c_str());
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    return vkpt::runProgram(kProgram, [argc, argv] {
        const Invocation invocation = parseArguments(argc, argv);
        return invocation.showHelp ? 0 : run(invocation);
    });
}
