// render_options.h — the options vkpt and vkpt-ref share, bound to a RenderSettings.
#pragma once

#include "app/command_line.h"
#include "common/render_settings.h"

namespace vkpt {

void addRenderOptions(CommandLine& commandLine, RenderSettings& settings);

// Cross-option checks after parsing (e.g. a scene path given); throws InputError.
void validateRenderSettings(const RenderSettings& settings);

} // namespace vkpt
