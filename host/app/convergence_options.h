// convergence_options.h — the options that buy accuracy with time: --reference (error against
// a reference after every batch), --target-error and --time-limit (they stop the render
// driver's loop, for vkpt and vkpt-ref alike).
#pragma once

#include <optional>

#include "app/command_line.h"
#include "common/render_settings.h"
#include "convergence/convergence.h"

namespace vkpt {

void addConvergenceOptions(CommandLine& commandLine, ConvergenceSettings& settings);

// The --reference image at the render's size (loadReference), or none without --reference.
std::optional<Image> loadReferenceFor(const ConvergenceSettings& convergence,
                                      const RenderSettings& settings);

} // namespace vkpt
