// render_program.cpp — the shared render program (render_program.h).
#include "app/render_program.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
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
#include "state/render_state.h"

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

// Fewer lit pixels than this share of those rendered: almost no camera path reached light.
constexpr double kLitPixelShareToWarn = 0.01;

// An image (nearly) black although the scene has light is most often geometry seen from the
// side that does not show: single-sided surfaces seen from behind (the camera passes them,
// shared/camera_culling.h) or emitters whose front faces away. Said once per process (an
// animation's frames would repeat it), after the render, from the pixels' records.
void warnIfAlmostNothingIsLit(const std::string& program, const RenderRunResult& result) {
    static bool warned = false;
    if (warned) return;
    std::size_t rendered = 0, lit = 0;
    for (const PixelRecord& record : result.records) {
        if (record.count == 0) continue;
        ++rendered;
        if (record.mean != glm::dvec3(0.0)) ++lit;
    }
    if (rendered == 0 || double(lit) >= kLitPixelShareToWarn * double(rendered)) return;
    warned = true;
    std::fprintf(stderr,
                 "%s: warning: %zu of %zu pixels received any light; check for single-sided "
                 "surfaces seen from behind (glTF doubleSided false: the camera sees through "
                 "their back) and for emitters or lights facing away from what the camera sees\n",
                 program.c_str(), lit, rendered);
}

// One image: the whole program without frames, one frame of a sequence with them (the executor
// then started once, before the first).
int renderImage(const std::string& program, const ProgramOptions& invocation,
                ProgramExecutor& executor, bool startExecutor, FrameCache* frames = nullptr) {
    const RenderSettings& settings = invocation.settings;
    // Every output path and a resumed state first: a typo costs a second, not the render.
    checkOutputPaths(settings);
    RenderPart part(program, settings, invocation.farm);
    // Before the device and the load, so that a stop during them still ends with the image
    // and the state (vkpt names its device once the handlers are in place).
    installStopHandlers();
    // The --reference image next: like the outputs, a wrong file costs a second.
    const std::optional<Image> reference = loadReferenceFor(invocation.convergence, settings);
    if (startExecutor) executor.start();
    // Before the render: the preview shows the denoised image too.
    const std::unique_ptr<Denoiser> denoiser = makeDenoiser(settings, executor);
    SceneSetup setup = setUpScene(
        settings, program, [&](const Scene& scene) { executor.sceneLoaded(scene, part); }, frames);
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
    warnIfAlmostNothingIsLit(program, result);
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

// The frames in order, each posed at frame / fps, with the executor's device (and pipelines)
// kept from one to the next, and the file read once (docs/distributed.md, "Animations"). Run
// again with the same command, a sequence stopped part way (killed, preempted) continues where
// it stopped: a frame whose image exists is skipped (images are written atomically, so one that
// exists is whole), and a frame that left its state (a stopped frame does; .exr outputs are
// their state, and --checkpoint leaves one) resumes from it, the state beside an image removed
// once the frame is whole. Each frame's statistics JSON holds its own phases.
int renderFrames(const std::string& program, const ProgramOptions& invocation,
                 ProgramExecutor& executor) {
    bool started = false;
    FrameCache cache; // the file, the --env image and the still geometry's BVHs
    for (const std::uint32_t frame : framesToRender(invocation.frames)) {
        ProgramOptions each = invocation;
        each.settings = frameSettings(invocation.settings, invocation.frames, frame);
        const std::string state = statePathFor(each.settings.outputPath);
        const bool leftState = std::filesystem::exists(state) && invocation.farm.resumePath.empty();
        if (std::filesystem::exists(each.settings.outputPath) && !leftState) {
            std::fprintf(stderr, "%s: frame %u: %s exists; skipped\n", program.c_str(), frame,
                         each.settings.outputPath.c_str());
            continue;
        }
        if (leftState) each.farm.resumePath = state;
        if (started) processPhases().clear();
        std::fprintf(stderr, "%s: frame %u at %.6g s -> %s\n", program.c_str(), frame,
                     *each.settings.animationTime, each.settings.outputPath.c_str());
        const int code = renderImage(program, each, executor, !started, &cache);
        started = true;
        if (code != 0) return code;
        // The frame is whole now: the state it resumed from would only make the next run
        // render it again (unless the state is the output itself, or checkpoints keep one).
        if (leftState && !stopRequested() && state != each.settings.outputPath &&
            invocation.farm.checkpointSeconds == 0.0)
            std::filesystem::remove(state);
        // A stop that came as a frame ended: that frame is whole, the rest wait for the next run.
        if (stopRequested()) return exitCodeForStop();
    }
    return 0;
}

} // namespace

std::unique_ptr<Denoiser> ProgramExecutor::makeDenoiser(const RenderSettings& settings) {
    return std::make_unique<CpuDenoiser>(settings.threads);
}

int runRenderProgram(const std::string& program, const ProgramOptions& invocation,
                     ProgramExecutor& executor) {
    if (invocation.frames.any()) return renderFrames(program, invocation, executor);
    return renderImage(program, invocation, executor, true);
}

} // namespace vkpt
