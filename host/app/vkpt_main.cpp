// vkpt_main.cpp — vkpt, the wavefront path tracer on a Vulkan compute device: load, build,
// upload, render, write. Same options and outputs as vkpt-ref, plus the device's own.
#include <chrono>
#include <cstdio>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "app/command_line.h"
#include "app/convergence_options.h"
#include "app/interrupt.h"
#include "app/live_preview.h"
#include "app/output_checks.h"
#include "app/program_options.h"
#include "app/render_part.h"
#include "app/render_report.h"
#include "app/run_program.h"
#include "app/scene_setup.h"
#include "common/errors.h"
#include "common/phase_log.h"
#include "gpu/context.h"
#include "gpu/device_list.h"
#include "gpu/vk_check.h"
#include "image/image_io.h"
#include "render/early_pipelines.h"
#include "render/wavefront.h"

namespace {

using namespace vkpt;

const char* const kProgram = "vkpt";

// The options vkpt-ref takes too, and the device's own.
struct Invocation : ProgramOptions {
    GpuOptions gpu;
    bool listDevices = false;
    bool kernelStats = false;
    std::uint32_t pathSlots = 0; // 0: chosen from the device
};

void addDeviceOptions(CommandLine& commandLine, Invocation& invocation) {
    commandLine.add(
        {"device", {}, "N|NAME", "Vulkan device by index or name substring", [&](auto v) {
             invocation.gpu.device = parseDeviceSelection(v[0]);
         }});
    commandLine.add({"list-devices", {}, "", "list the Vulkan devices and exit", [&](auto) {
                         invocation.listDevices = true;
                     }});
    commandLine.add({"validate",
                     {},
                     "",
                     "enable the Vulkan validation layer (or VKPT_VALIDATION=1)",
                     [&](auto) { invocation.gpu.validation = true; }});
    commandLine.add({"stats", {}, "", "print per-kernel GPU times (timestamp queries)", [&](auto) {
                         invocation.kernelStats = true;
                     }});
    commandLine.add({"no-cache",
                     {},
                     "",
                     "do not read or write the pipeline cache file (or VKPT_NO_PIPELINE_CACHE=1)",
                     [&](auto) { invocation.gpu.persistentPipelineCache = false; }});
    commandLine.add(
        {"path-slots", {}, "N", "paths in flight per pass (default: from the device)", [&](auto v) {
             invocation.pathSlots = parseUnsigned("path-slots", v[0], 64);
         }});
}

Invocation parseArguments(int argc, char** argv) {
    Invocation invocation;
    // Drivers that honour a pipeline cache compile each kernel once, not once per render.
    invocation.gpu.persistentPipelineCache = true;
    const ProgramCommandLine commandLine{
        kProgram, ConvergenceOptionSet::All,
        [&invocation](CommandLine& own) { addDeviceOptions(own, invocation); },
        [&invocation] { return invocation.listDevices; }};
    parseProgramOptions(commandLine, invocation, argc, argv);
    return invocation;
}

int printDevices() {
    std::vector<DeviceInfo> devices = vkpt::listDevices();
    if (devices.empty()) throw VulkanError("no Vulkan device found");
    for (const DeviceInfo& device : devices)
        std::printf("%s\n", describeDevice(device).c_str());
    return 0;
}

DeviceRunReport deviceRunReport(const WavefrontResult& result, double setupSeconds) {
    DeviceRunReport d;
    d.passes = result.passes;
    d.pathSlots = result.slotCount;
    d.setupSeconds = setupSeconds;
    d.truncatedTraversals = result.truncatedTraversals;
    d.interrupted = result.interrupted;
    d.kernelTimes = result.kernelTimes;
    d.pipelineCreationSeconds = result.pipelineCreationSeconds;
    d.pipelineCreations = result.pipelineCreations;
    d.pipelinesCreatedEarly = result.pipelinesCreatedEarly;
    d.sceneBufferBytes = result.sceneBufferBytes;
    d.sceneBuffers = result.sceneBuffers;
    return d;
}

// --reference, --target-error, --time-limit: the tracker sees every pass; with a reference or
// a target it gets the image (one readback per pass) and prints a line per pass instead of
// the progress bar.
bool printsPassLines(const Invocation& invocation) {
    return invocation.convergence.needsPixels() && !invocation.settings.quiet;
}

WavefrontOptions wavefrontOptions(const Invocation& invocation, ConvergenceTracker& tracker,
                                  RenderPart& part) {
    WavefrontOptions options;
    options.timeKernels = invocation.kernelStats;
    options.slotCount = invocation.pathSlots;
    options.interrupt = &stopRequested();
    options.plan = part.plan();
    options.resume = part.resumeRecords();
    options.aovs = part.needsAovs();
    options.resumeFeatures = part.resumeFeatures();
    const PeriodicWrite periodic = periodicWrites(invocation.settings, part);
    options.checkpointSeconds = periodic.seconds;
    options.checkpoint = periodic.write;
    const ConvergenceSettings& convergence = invocation.convergence;
    options.timeLimitSeconds = convergence.timeLimitSeconds;
    if (!convergence.any()) return options;
    options.readPixelsAfterPass = convergence.needsPixels();
    const bool printLines = printsPassLines(invocation);
    options.afterPass = [&tracker, printLines](const PassFigures& figures,
                                               const RenderOutput* output) {
        const ConvergencePoint& point = tracker.record(figures, output);
        if (printLines) std::fprintf(stderr, "%s: %s\n", kProgram, describePoint(point).c_str());
        return tracker.targetReached();
    };
    return options;
}

std::optional<ConvergenceReport> convergenceReport(const Invocation& invocation,
                                                   const ConvergenceTracker& tracker,
                                                   RenderStop stop) {
    if (!invocation.convergence.any()) return std::nullopt;
    return ConvergenceReport{invocation.convergence, stop, tracker.targetReached(),
                             tracker.curve()};
}

RenderReport makeReport(RenderReport report, const GpuContext& context,
                        const WavefrontResult& result, double setupSeconds) {
    report.device = context.deviceInfo().name;
    report.stats = result.stats;
    report.deviceMemoryBytes = context.memoryStats().peakBytes;
    report.deviceRun = deviceRunReport(result, setupSeconds);
    return report;
}

// A walk the driver cut short means a wrong image, not a slow one: say so loudly.
void warnAboutTruncation(const WavefrontResult& result) {
    if (result.truncatedTraversals == 0) return;
    std::fprintf(stderr,
                 "%s: warning: %llu BVH traversals were cut short by the driver's loop limit; "
                 "the image is missing hits (see docs/wavefront.md)\n",
                 kProgram, (unsigned long long)result.truncatedTraversals);
}

int render(const Invocation& invocation) {
    const RenderSettings& settings = invocation.settings;
    // Every output path and a resumed state first: a typo costs a second, not the render.
    checkOutputPaths(settings);
    RenderPart part(kProgram, settings, invocation.farm);
    // The device next: without one, the user hears that (one line) before a long load.
    ScopedPhase devicePhase("device");
    GpuContext context(invocation.gpu);
    devicePhase.end();
    const std::optional<Image> reference = loadReferenceFor(invocation.convergence, settings);
    // The pipelines need the scene's features alone: the driver compiles them while the BVH
    // builds and the scene uploads.
    std::optional<EarlyPipelines> earlyPipelines;
    SceneSetup setup = setUpScene(settings, kProgram, [&](const Scene& scene) {
        const SceneFeatures used = analyseScene(scene);
        earlyPipelines.emplace(context, settings.general ? generalFeatures(used) : used,
                               part.needsAovs(), KernelBuilds::ForFeatureSet);
    });
    part.attachScene(setup);
    // Everything that reads the host's copy of the scene runs before the render frees the device
    // arrays' copies as they are uploaded (and the tree, just before): a large scene is then held
    // once, not twice, while it renders (docs/benchmarks.md, host memory). The AOVs come from the
    // kernels' own camera samples, so nothing here traces rays on the CPU.
    RenderReport sceneFigures = sceneReport(kProgram, settings, setup);
    const auto start = std::chrono::steady_clock::now();
    installStopHandlers();
    std::fprintf(stderr, "%s: device %s\n", kProgram, describeDevice(context.deviceInfo()).c_str());
    ConvergenceTracker tracker(reference ? &*reference : nullptr,
                               invocation.convergence.targetError);
    RenderSettings renderSettings = settings;
    renderSettings.quiet = settings.quiet || printsPassLines(invocation);
    WavefrontOptions options = wavefrontOptions(invocation, tracker, part);
    options.earlyPipelines = earlyPipelines ? &*earlyPipelines : nullptr;
    options.beforeSceneUpload = [&setup] {
        setup.prepared.tree = {};
        setup.prepared.meshes = {};
        setup.prepared.instanceTree = {};
    };
    WavefrontResult result =
        renderWavefrontReleasing(context, setup.prepared, setup.camera, renderSettings, options);
    const std::chrono::duration<double> total = std::chrono::steady_clock::now() - start;
    ScopedPhase writePhase("write");
    part.writeResults(result.output, result.records, result.features, result.interrupted);
    writePhase.end();
    RenderReport report =
        makeReport(std::move(sceneFigures), context, result, total.count() - result.stats.seconds);
    report.convergence = convergenceReport(invocation, tracker, result.stop);
    writeRenderReport(report);
    warnAboutTruncation(result);
    if (context.validationMessageCount() > 0)
        throw InternalError("the validation layer reported " +
                            std::to_string(context.validationMessageCount()) + " messages");
    return result.interrupted ? exitCodeForStop() : 0;
}

} // namespace

int main(int argc, char** argv) {
    return vkpt::runProgram(kProgram, [argc, argv] {
        const Invocation invocation = parseArguments(argc, argv);
        if (invocation.showHelp) return 0;
        if (invocation.listDevices) return printDevices();
        return render(invocation);
    });
}
