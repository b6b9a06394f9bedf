// convergence_options.h — the options that buy accuracy with time: --reference (error against
// a reference after every pass), --target-error and --time-limit (vkpt only: they stop the
// pass loop).
#pragma once

#include <optional>

#include "app/command_line.h"
#include "common/render_settings.h"
#include "convergence/convergence.h"

namespace vkpt {

enum class ConvergenceOptionSet { ReferenceOnly, All };

void addConvergenceOptions(CommandLine& commandLine, ConvergenceSettings& settings,
                           ConvergenceOptionSet set);

// The --reference image at the render's size (loadReference), or none without --reference.
std::optional<Image> loadReferenceFor(const ConvergenceSettings& convergence,
                                      const RenderSettings& settings);

} // namespace vkpt
