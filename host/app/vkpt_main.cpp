// vkpt_main.cpp — vkpt, the wavefront path tracer on a Vulkan compute device: the shared render
// program (app/render_program.h) over the device's executor, plus the device's own options.
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "app/command_line.h"
#include "app/program_options.h"
#include "app/render_part.h"
#include "app/render_program.h"
#include "app/render_report.h"
#include "app/run_program.h"
#include "common/errors.h"
#include "common/phase_log.h"
#include "gpu/context.h"
#include "gpu/device_list.h"
#include "gpu/vk_check.h"
#include "render/device_denoiser.h"
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
                     "do not read or write the pipeline cache file and folded kernels (or "
                     "VKPT_NO_PIPELINE_CACHE=1)",
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
        kProgram, [&invocation](CommandLine& own) { addDeviceOptions(own, invocation); },
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
    return {{result}, result.passes, setupSeconds, result.interrupted};
}

// A walk the driver cut short means a wrong image, not a slow one: say so loudly.
void warnAboutTruncation(const WavefrontResult& result) {
    if (result.truncatedTraversals == 0) return;
    std::fprintf(stderr,
                 "%s: warning: %llu BVH traversals were cut short by the driver's loop limit; "
                 "the image is missing hits (see docs/wavefront.md)\n",
                 kProgram, (unsigned long long)result.truncatedTraversals);
}

// The wavefront renderer on the chosen Vulkan device.
class DeviceExecutor final : public ProgramExecutor {
public:
    explicit DeviceExecutor(const Invocation& invocation) : invocation_(invocation) {}

    void start() override {
        ScopedPhase devicePhase("device");
        context_.emplace(invocation_.gpu);
        devicePhase.end();
        std::fprintf(stderr, "%s: device %s\n", kProgram,
                     describeDevice(context_->deviceInfo()).c_str());
    }

    // The pipelines need the scene's features alone: the driver compiles them while the BVH
    // builds and the scene uploads. An animation's next frame of the same features takes the
    // pipelines the last one made from the device's memo (gpu/kernel_memo.h), at once.
    void sceneLoaded(const Scene& scene, const RenderPart& /*part*/) override {
        const SceneFeatures used = analyseScene(scene);
        const SceneFeatures features = invocation_.settings.general ? generalFeatures(used) : used;
        earlyPipelines_.reset();
        earlyPipelines_.emplace(*context_, features, KernelBuilds::ForFeatureSet);
    }

    // Everything that reads the host's copy of the scene has run before the render frees the
    // device arrays' copies as they are uploaded (and the tree and meshes, just before): a large
    // scene is then held once, not twice, while it renders (docs/benchmarks.md, host memory).
    RenderRunResult render(SceneSetup& setup, const RenderSettings& settings,
                           const RenderRunOptions& run) override {
        WavefrontOptions options;
        static_cast<RenderRunOptions&>(options) = run;
        options.timeKernels = invocation_.kernelStats;
        options.slotCount = invocation_.pathSlots;
        options.earlyPipelines = earlyPipelines_ ? &*earlyPipelines_ : nullptr;
        if (!invocation_.frames.any()) {
            result_ = renderWavefrontReleasing(*context_, setup.prepared, setup.camera, settings,
                                               options);
            return result_;
        }
        // An animation's frame: what the frame before left on the device stays there.
        result_ = renderWavefrontKeeping(*context_, setup.prepared, setup.camera, settings, options,
                                         keptScene_);
        if (settings.verbose) {
            const KeptUploadStats& upload = keptScene_.stats();
            std::fprintf(
                stderr, "%s: frame upload: %.1f KiB uploaded, %.1f KiB kept on the device\n",
                kProgram, double(upload.uploadedBytes) / 1024.0, double(upload.keptBytes) / 1024.0);
        }
        return result_;
    }

    void completeReport(RenderReport& report, const RenderRunResult&, double seconds) override {
        report.device = context_->deviceInfo().name;
        report.stats = result_.stats;
        report.deviceMemoryBytes = context_->memoryStats().peakBytes;
        report.deviceRun = deviceRunReport(result_, seconds - result_.stats.seconds);
    }

    // The kernels on the render's device.
    std::unique_ptr<Denoiser> makeDenoiser(const RenderSettings&) override {
        return std::make_unique<DeviceDenoiser>(*context_);
    }

    void afterReport(const RenderRunResult&) override {
        warnAboutTruncation(result_);
        if (context_->validationMessageCount() > 0)
            throw InternalError("the validation layer reported " +
                                std::to_string(context_->validationMessageCount()) + " messages");
    }

private:
    const Invocation& invocation_;
    std::optional<GpuContext> context_;
    std::optional<EarlyPipelines> earlyPipelines_; // destroyed before the context
    KeptDeviceScene keptScene_;                    // an animation's arrays, between its frames
    WavefrontResult result_;
};

} // namespace

int main(int argc, char** argv) {
    return vkpt::runProgram(kProgram, [argc, argv] {
        const Invocation invocation = parseArguments(argc, argv);
        if (invocation.showHelp) return 0;
        if (invocation.listDevices) return printDevices();
        DeviceExecutor executor(invocation);
        return runRenderProgram(kProgram, invocation, executor);
    });
}
