// farm_options.h — the options that make one process a part of a larger render: --task K/N,
// --crop X0 Y0 X1 Y1, --resume FILE and --checkpoint S (docs/distributed.md).
#pragma once

#include <optional>
#include <string>

#include "app/command_line.h"
#include "common/render_settings.h"
#include "state/sample_plan.h"

namespace vkpt {

struct FarmSettings {
    std::optional<TaskShare> task;
    std::optional<PixelRect> crop;
    std::string resumePath;
    double checkpointSeconds = 0.0; // 0: no periodic checkpoints
};

void addFarmOptions(CommandLine& commandLine, FarmSettings& farm);

// Cross-option checks after parsing; throws InputError naming the options.
void validateFarmSettings(const FarmSettings& farm, const RenderSettings& settings);

// The pixels and samples this process renders before a resumed state is taken into account:
// the crop (default: every pixel) and the task's share of [0, spp) (default: all of it).
SamplePlan samplePlanFor(const FarmSettings& farm, const RenderSettings& settings);

} // namespace vkpt
