// sampler_setup.h — the sampler setup word both executors hand to shared/sampler.h, from the
// render's settings and image size, so that vkpt and vkpt-ref draw the same numbers.
#pragma once

#include <cstdint>

#include "common/render_settings.h"
#include "shared/sampler.h"

namespace vkpt {

// The block exponent follows --spp (shared/sampler.h, makeSamplerSetup): parts of one render
// (--task, --crop, checkpoints) share their --spp, so they share the setup.
inline std::uint32_t samplerSetupFor(const RenderSettings& settings, std::uint32_t width,
                                     std::uint32_t height) {
    const std::uint32_t kind =
        settings.sampler == Sampler::Sobol ? SAMPLER_SOBOL : SAMPLER_INDEPENDENT;
    return gpu::makeSamplerSetup(kind, width, height, settings.samplesPerPixel);
}

} // namespace vkpt
