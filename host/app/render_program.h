// render_program.h — the one program vkpt and vkpt-ref (and the benchmarks' embree-ref) are:
// check the outputs, load and prepare the scene, run the render driver over the program's
// executor with every option that steers it (plan, resume, AOVs, checkpoints and previews,
// signals, --time-limit, --target-error, --reference), write, report. A program supplies its
// executor: the device it renders on and what it adds to the report.
#pragma once

#include <memory>
#include <string>

#include "app/program_options.h"
#include "app/render_report.h"
#include "app/scene_setup.h"
#include "denoise/denoiser.h"
#include "driver/render_run.h"
#include "scene/scene.h"

namespace vkpt {

class RenderPart;

class ProgramExecutor {
public:
    virtual ~ProgramExecutor() = default;

    // Once the outputs are checked, before the scene loads: a device that is missing is then
    // reported before a long load.
    virtual void start() {}
    // The loaded scene, before it is prepared (vkpt starts creating its pipelines here).
    virtual void sceneLoaded(const Scene&, const RenderPart&) {}
    // The render of the prepared scene through the render driver, with `options` (the run's
    // options every executor takes) and the executor's own.
    virtual RenderRunResult render(SceneSetup& setup, const RenderSettings& settings,
                                   const RenderRunOptions& options) = 0;
    // What the executor adds to the report of `result` (its device, its figures); `seconds`
    // is render()'s wall time, set-up included.
    virtual void completeReport(RenderReport& report, const RenderRunResult& result,
                                double seconds) = 0;
    // After the report: warnings, and failures that must not lose the image (a validation
    // message on a validated run).
    virtual void afterReport(const RenderRunResult&) {}
    // The denoiser of --denoise, on the executor's device (after start()): the CPU loop unless
    // the executor has a device of its own.
    virtual std::unique_ptr<Denoiser> makeDenoiser(const RenderSettings& settings);
};

// Renders as `invocation` says with `executor`; returns the exit code: 0, or 128 + the signal
// that stopped the render.
int runRenderProgram(const std::string& program, const ProgramOptions& invocation,
                     ProgramExecutor& executor);

} // namespace vkpt
