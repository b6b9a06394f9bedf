// denoiser.h — the statistics-gated denoiser (shared/denoise.h, docs/denoise.md) as the host sees
// it: its settings, its per-pixel input made from a render state's pixels and AOVs, and the
// interface that the CPU loop (cpu_denoiser.h) and vkpt's device kernels
// (render/device_denoiser.h) implement alike.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "shared/denoise.h"
#include "state/render_state.h"

namespace vkpt {

struct DenoiseSettings {
    std::uint32_t iterations = DENOISE_ITERATIONS; // à-trous steps 1, 2, 4, ...
    float gateT = DENOISE_GATE_T;
    float normalPower = DENOISE_NORMAL_POWER;
    float depthSigma = DENOISE_DEPTH_SIGMA;
    float albedoSigma = DENOISE_ALBEDO_SIGMA;
};

// The push constants of pass `iteration` (0-based) of settings.iterations + 1: the à-trous
// iterations, each after choosing among the candidates so far, then the last choice (step 0).
gpu::DenoiseParams denoiseParams(const DenoiseSettings& settings, std::uint32_t width,
                                 std::uint32_t height, std::uint32_t iteration);

// The denoiser's input for pixels and their features (the same pixels, row-major).
std::vector<gpu::DenoisePixel> denoiseInput(const std::vector<PixelRecord>& pixels,
                                            const std::vector<FeatureRecord>& features);

class Denoiser {
public:
    virtual ~Denoiser() = default;
    // The denoised radiance of a width × height image of `pixels`, row-major. At least one
    // iteration; a pixel of no noise and no neighbour of equal mean comes back as it went in.
    virtual std::vector<glm::vec3> denoise(const std::vector<gpu::DenoisePixel>& pixels,
                                           std::uint32_t width, std::uint32_t height,
                                           const DenoiseSettings& settings) = 0;
    // Where it runs, for messages: "CPU", the device's name.
    virtual std::string where() const = 0;
};

} // namespace vkpt
