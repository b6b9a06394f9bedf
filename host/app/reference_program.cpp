// reference_program.cpp — vkpt-ref's program: the shared render program (app/render_program.h)
// over the CPU reference, its rays traced by the program's intersectors.
#include "app/reference_program.h"

#include <string>
#include <thread>

#include "app/program_options.h"
#include "app/render_program.h"
#include "app/run_program.h"
#include "common/phase_log.h"
#include "reference/reference_renderer.h"

namespace vkpt {

namespace {

ProgramOptions parseArguments(const std::string& program, int argc, char** argv) {
    ProgramOptions invocation;
    parseProgramOptions({program, {}, {}}, invocation, argc, argv);
    return invocation;
}

std::string deviceDescription(const RenderSettings& settings) {
    unsigned threads = settings.threads ? settings.threads : std::thread::hardware_concurrency();
    return "CPU, " + std::to_string(threads) + " threads";
}

// The reference's integrators on every core, rays through the program's intersectors.
class CpuExecutor final : public ProgramExecutor {
public:
    explicit CpuExecutor(const ReferenceProgram& program) : program_(program) {}

    RenderRunResult render(SceneSetup& setup, const RenderSettings& settings,
                           const RenderRunOptions& run) override {
        ScopedPhase layoutPhase("ray queries");
        const std::unique_ptr<IntersectorFactory> intersectors =
            program_.makeIntersectors(setup.prepared, settings);
        layoutPhase.end();
        ScopedPhase renderPhase("render");
        ReferenceOptions options;
        static_cast<RenderRunOptions&>(options) = run;
        options.intersectors = intersectors.get();
        RenderStats stats;
        return renderReferenceParts(setup.prepared, setup.camera, settings, stats, options);
    }

    void completeReport(RenderReport& report, const RenderRunResult& result, double) override {
        report.device = deviceDescription(*report.settings);
        report.stats = result.stats;
    }

private:
    const ReferenceProgram& program_;
};

} // namespace

int runReferenceProgram(const ReferenceProgram& program, int argc, char** argv) {
    return runProgram(program.name, [&program, argc, argv] {
        const ProgramOptions invocation = parseArguments(program.name, argc, argv);
        if (invocation.showHelp) return 0;
        CpuExecutor executor(program);
        return runRenderProgram(program.name, invocation, executor);
    });
}

} // namespace vkpt
