// reference_program.cpp — vkpt-ref's program: options, load, build, render, write, report.
#include "app/reference_program.h"

#include <cstdio>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "app/convergence_options.h"
#include "app/interrupt.h"
#include "app/live_preview.h"
#include "app/output_checks.h"
#include "app/program_options.h"
#include "app/render_part.h"
#include "app/render_report.h"
#include "app/run_program.h"
#include "app/scene_setup.h"
#include "common/phase_log.h"
#include "image/image_io.h"
#include "reference/reference_renderer.h"

namespace vkpt {

namespace {

// --reference only of the convergence options: the CPU renders each pixel to the end.
ProgramOptions parseArguments(const std::string& program, int argc, char** argv) {
    ProgramOptions invocation;
    parseProgramOptions({program, ConvergenceOptionSet::ReferenceOnly, {}, {}}, invocation, argc,
                        argv);
    return invocation;
}

std::string deviceDescription(const RenderSettings& settings) {
    unsigned threads = settings.threads ? settings.threads : std::thread::hardware_concurrency();
    return "CPU, " + std::to_string(threads) + " threads";
}

// The reference renders every pixel to its end, so its curve is one point: the final image.
std::optional<ConvergenceReport> finalError(const ConvergenceSettings& convergence,
                                            const Image* reference, const RenderOutput& output,
                                            const RenderStats& stats, std::uint32_t spp) {
    if (!convergence.any()) return std::nullopt;
    ConvergenceTracker tracker(reference, 0.0);
    PassFigures figures;
    figures.pass = 1;
    figures.seconds = figures.renderSeconds = stats.seconds;
    figures.samplesPerPixel = spp;
    figures.samplesTaken = stats.samplesTaken;
    tracker.record(figures, &output);
    return ConvergenceReport{convergence, RenderStop::Budget, false, tracker.curve()};
}

ReferenceOptions referenceOptions(const RenderSettings& settings, RenderPart& part,
                                  const IntersectorFactory& intersectors) {
    ReferenceOptions options;
    options.intersectors = &intersectors;
    options.plan = part.plan();
    options.resume = part.resumeRecords();
    options.aovs = part.needsAovs();
    options.resumeFeatures = part.resumeFeatures();
    options.interrupt = &stopRequested();
    const PeriodicWrite periodic = periodicWrites(settings, part);
    options.checkpointSeconds = periodic.seconds;
    options.checkpoint = periodic.write;
    return options;
}

// Returns the exit code: 0, or 128 + the signal that stopped the render.
int run(const ReferenceProgram& program, const ProgramOptions& invocation) {
    const RenderSettings& settings = invocation.settings;
    const ConvergenceSettings& convergence = invocation.convergence;
    // Every output path and a resumed state first: a typo costs a second, not the render.
    checkOutputPaths(settings);
    RenderPart part(program.name, settings, invocation.farm);
    // Before the load, so that a stop during it still ends with the image and the state.
    installStopHandlers();
    const std::optional<Image> reference = loadReferenceFor(convergence, settings);
    SceneSetup setup = setUpScene(settings, program.name);
    part.attachScene(setup);
    ScopedPhase layoutPhase("ray queries");
    std::unique_ptr<IntersectorFactory> intersectors =
        program.makeIntersectors(setup.prepared, settings);
    layoutPhase.end();
    RenderReport report = sceneReport(program.name, settings, setup);
    ScopedPhase renderPhase("render");
    const ReferenceResult result =
        renderReferenceParts(setup.prepared, setup.camera, settings, report.stats,
                             referenceOptions(settings, part, *intersectors));
    renderPhase.end();
    const RenderOutput& output = result.output;
    ScopedPhase writePhase("write");
    part.writeResults(output, result.records, result.features, result.interrupted);
    writePhase.end();
    report.device = deviceDescription(settings);
    report.convergence = finalError(convergence, reference ? &*reference : nullptr, output,
                                    report.stats, settings.samplesPerPixel);
    writeRenderReport(report);
    return result.interrupted ? exitCodeForStop() : 0;
}

} // namespace

int runReferenceProgram(const ReferenceProgram& program, int argc, char** argv) {
    return runProgram(program.name, [&program, argc, argv] {
        const ProgramOptions invocation = parseArguments(program.name, argc, argv);
        return invocation.showHelp ? 0 : run(program, invocation);
    });
}

} // namespace vkpt
