// render_program.cpp — the shared render program (render_program.h).
#include "app/render_program.h"

#include <chrono>
#include <cstdio>
#include <optional>

#include "app/convergence_options.h"
#include "app/interrupt.h"
#include "app/live_preview.h"
#include "app/output_checks.h"
#include "app/render_part.h"
#include "common/phase_log.h"
#include "convergence/convergence.h"
#include "denoise/cpu_denoiser.h"
#include "driver/denoised_output.h"
#include "image/image_io.h"

namespace vkpt {

namespace {

// --reference, --target-error, --time-limit: the tracker sees every batch; with a reference or
// a target it gets the image (one look at the pixels per batch) and prints a line per batch
// instead of the progress bar.
bool printsPassLines(const ProgramOptions& invocation) {
    return invocation.convergence.needsPixels() && !invocation.settings.quiet;
}

RenderRunOptions runOptions(const std::string& program, const ProgramOptions& invocation,
                            ConvergenceTracker& tracker, RenderPart& part, Denoiser* denoiser) {
    RenderRunOptions options;
    options.interrupt = &stopRequested();
    options.plan = part.plan();
    options.resume = part.resumeRecords();
    options.aovs = part.needsAovs();
    options.resumeFeatures = part.resumeFeatures();
    const PeriodicWrite periodic = periodicWrites(invocation.settings, part, denoiser);
    options.checkpointSeconds = periodic.seconds;
    options.checkpoint = periodic.write;
    const ConvergenceSettings& convergence = invocation.convergence;
    options.timeLimitSeconds = convergence.timeLimitSeconds;
    if (!convergence.any()) return options;
    options.readPixelsAfterPass = convergence.needsPixels();
    const bool printLines = printsPassLines(invocation);
    options.afterPass = [&tracker, printLines, program](const PassFigures& figures,
                                                        const RenderOutput* output) {
        const ConvergencePoint& point = tracker.record(figures, output);
        if (printLines)
            std::fprintf(stderr, "%s: %s\n", program.c_str(), describePoint(point).c_str());
        return tracker.targetReached();
    };
    return options;
}

std::optional<ConvergenceReport> convergenceReport(const ConvergenceSettings& convergence,
                                                   const ConvergenceTracker& tracker,
                                                   RenderStop stop) {
    if (!convergence.any()) return std::nullopt;
    return ConvergenceReport{convergence, stop, tracker.targetReached(), tracker.curve()};
}

// --denoise: the denoiser (its pipelines on vkpt's device), in a phase of its own; otherwise
// none.
std::unique_ptr<Denoiser> makeDenoiser(const RenderSettings& settings, ProgramExecutor& executor) {
    if (!settings.denoise) return nullptr;
    ScopedPhase phase("denoise set-up");
    return executor.makeDenoiser(settings);
}

// --denoise: the crop's denoised radiance; otherwise none.
std::vector<glm::vec3> denoisedPixels(Denoiser* denoiser, const RenderPart& part,
                                      const RenderRunResult& result) {
    if (!denoiser) return {};
    return denoiseWindow(*denoiser, part.plan().crop, result.records, result.features);
}

} // namespace

std::unique_ptr<Denoiser> ProgramExecutor::makeDenoiser(const RenderSettings& settings) {
    return std::make_unique<CpuDenoiser>(settings.threads);
}

int runRenderProgram(const std::string& program, const ProgramOptions& invocation,
                     ProgramExecutor& executor) {
    const RenderSettings& settings = invocation.settings;
    // Every output path and a resumed state first: a typo costs a second, not the render.
    checkOutputPaths(settings);
    RenderPart part(program, settings, invocation.farm);
    // Before the device and the load, so that a stop during them still ends with the image
    // and the state (vkpt names its device once the handlers are in place).
    installStopHandlers();
    // The --reference image next: like the outputs, a wrong file costs a second.
    const std::optional<Image> reference = loadReferenceFor(invocation.convergence, settings);
    executor.start();
    // Before the render: the preview shows the denoised image too.
    const std::unique_ptr<Denoiser> denoiser = makeDenoiser(settings, executor);
    SceneSetup setup = setUpScene(settings, program,
                                  [&](const Scene& scene) { executor.sceneLoaded(scene, part); });
    part.attachScene(setup);
    RenderReport report = sceneReport(program, settings, setup);
    ConvergenceTracker tracker(reference ? &*reference : nullptr,
                               invocation.convergence.targetError);
    RenderSettings renderSettings = settings;
    renderSettings.quiet = settings.quiet || printsPassLines(invocation);
    const RenderRunOptions options = runOptions(program, invocation, tracker, part, denoiser.get());
    const auto start = std::chrono::steady_clock::now();
    const RenderRunResult result = executor.render(setup, renderSettings, options);
    const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
    const std::vector<glm::vec3> denoised = denoisedPixels(denoiser.get(), part, result);
    ScopedPhase writePhase("write");
    part.writeResults(result.output, result.records, result.features, denoised, result.interrupted);
    writePhase.end();
    executor.completeReport(report, result, seconds.count());
    report.convergence = convergenceReport(invocation.convergence, tracker, result.stop);
    writeRenderReport(report);
    executor.afterReport(result);
    return result.interrupted ? exitCodeForStop() : 0;
}

} // namespace vkpt
