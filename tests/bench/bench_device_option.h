// bench_device_option.h — --device N|NAME for the benchmarks that run on a Vulkan device, as
// vkpt reads it (gpu/device_list.h), so that only they depend on vkpt_gpu.
#pragma once

#include <string>

#include "app/command_line.h"
#include "gpu/context.h"
#include "gpu/device_list.h"

namespace vkpt::bench {

inline void addDeviceOption(CommandLine& commandLine, GpuOptions& gpu,
                            const std::string& what = "Vulkan device by index or name substring") {
    commandLine.add({"device", {}, "N|NAME", what, [&gpu](auto v) {
                         gpu.device = parseDeviceSelection(v[0]);
                     }});
}

} // namespace vkpt::bench
