// vkpt-denoise: a saved or merged render state (the .exr that vkpt, vkpt-ref and vkpt-merge
// write) denoised once — after a farm's merge, not per task — on a Vulkan device with vkpt's
// kernels, or with --cpu on the host's cores (the same functions, shared/denoise_filter.h).
// A file that is not a state, or a state without the AOV layers, is refused with one line
// before anything is written.
#include <chrono>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/command_line.h"
#include "app/output_checks.h"
#include "app/run_program.h"
#include "common/errors.h"
#include "common/phase_log.h"
#include "common/render_settings.h"
#include "denoise/cpu_denoiser.h"
#include "driver/denoised_output.h"
#include "gpu/context.h"
#include "gpu/device_list.h"
#include "image/image_io.h"
#include "render/device_denoiser.h"
#include "state/state_file.h"

namespace {

using namespace vkpt;

const char* const kProgram = "vkpt-denoise";

struct Invocation {
    std::string inputPath;
    std::string outputPath;
    bool cpu = false;
    GpuOptions gpu;
    bool quiet = false;
    bool showHelp = false;
};

void addOptions(CommandLine& commandLine, Invocation& invocation) {
    commandLine.add({"output",
                     {'o'},
                     "FILE",
                     ".exr: the state with the denoised image as R, G, B and the raw one as "
                     "raw.R, raw.G, raw.B; .png, .pfm, .hdr: the denoised image",
                     [&](auto v) { invocation.outputPath = v[0]; }});
    commandLine.add({"cpu", {}, "", "denoise on the CPU instead of the Vulkan device", [&](auto) {
                         invocation.cpu = true;
                     }});
    commandLine.add(
        {"device", {}, "N|NAME", "Vulkan device by index or name substring", [&](auto v) {
             invocation.gpu.device = parseDeviceSelection(v[0]);
         }});
    commandLine.add({"validate",
                     {},
                     "",
                     "enable the Vulkan validation layer (or VKPT_VALIDATION=1)",
                     [&](auto) { invocation.gpu.validation = true; }});
    commandLine.add(
        {"quiet", {'q'}, "", "print nothing on success", [&](auto) { invocation.quiet = true; }});
    commandLine.add(
        {"help", {'h'}, "", "show this help", [&](auto) { invocation.showHelp = true; }});
}

Invocation parseArguments(int argc, char** argv) {
    Invocation invocation;
    CommandLine commandLine(kProgram);
    addOptions(commandLine, invocation);
    std::vector<std::string> arguments(argv + 1, argv + argc);
    const std::vector<std::string> inputs = commandLine.parse(arguments);
    if (invocation.showHelp) {
        std::fputs(commandLine.usage("STATE.exr").c_str(), stdout);
        return invocation;
    }
    if (invocation.outputPath.empty()) throw InputError("no output given (-o FILE)");
    if (inputs.size() != 1) throw InputError("give one state file (STATE.exr)");
    invocation.inputPath = inputs[0];
    return invocation;
}

// The state to denoise; InputError naming the file when it cannot be.
RenderState readDenoisable(const std::string& path) {
    RenderState state = readStateFile(path);
    if (state.features.size() != state.pixels.size())
        throw InputError(path + ": no albedo, normal and depth layers (a state saved by a render "
                                "that recorded no AOVs)");
    return state;
}

std::unique_ptr<Denoiser> makeDenoiser(const Invocation& invocation,
                                       std::optional<GpuContext>& context) {
    if (invocation.cpu) return std::make_unique<CpuDenoiser>();
    context.emplace(invocation.gpu);
    return std::make_unique<DeviceDenoiser>(*context);
}

int run(const Invocation& invocation) {
    RenderSettings output;
    output.outputPath = invocation.outputPath;
    checkOutputPaths(output);
    RenderState state = readDenoisable(invocation.inputPath);
    std::optional<GpuContext> context;
    std::unique_ptr<Denoiser> denoiser = makeDenoiser(invocation, context);
    const auto start = std::chrono::steady_clock::now();
    const double startCpu = processCpuSeconds();
    state.denoised = denoiseWindow(*denoiser, state.window, state.pixels, state.features);
    const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
    const double cpuSeconds = processCpuSeconds() - startCpu;
    if (outputHoldsState(invocation.outputPath))
        writeStateFile(state, invocation.outputPath);
    else
        writeImage(denoisedFrame(renderOutputOf(state).image, state.window, state.denoised),
                   invocation.outputPath);
    if (context && context->validationMessageCount() > 0)
        throw InternalError("the validation layer reported " +
                            std::to_string(context->validationMessageCount()) + " messages");
    if (!invocation.quiet)
        std::printf("%s: %s (%ux%u) denoised on %s in %.3f s (%.3f s of CPU) into %s\n", kProgram,
                    invocation.inputPath.c_str(), state.window.width(), state.window.height(),
                    denoiser->where().c_str(), seconds.count(), cpuSeconds,
                    invocation.outputPath.c_str());
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    return vkpt::runProgram(kProgram, [argc, argv] {
        const Invocation invocation = parseArguments(argc, argv);
        return invocation.showHelp ? 0 : run(invocation);
    });
}
