// denoiser.cpp — the denoiser's settings and input (denoiser.h).
#include "denoiser.h"

#include "common/errors.h"

namespace vkpt {

gpu::DenoiseParams denoiseParams(const DenoiseSettings& settings, std::uint32_t width,
                                 std::uint32_t height, std::uint32_t iteration) {
    gpu::DenoiseParams params{};
    params.width = width;
    params.height = height;
    const bool last = iteration == settings.iterations;
    params.step = last ? 0u : 1u << iteration;
    params.modulate = last ? 1u : 0u;
    params.gateT = settings.gateT;
    params.normalPower = settings.normalPower;
    params.depthSigma = settings.depthSigma;
    params.albedoSigma = settings.albedoSigma;
    return params;
}

std::vector<gpu::DenoisePixel> denoiseInput(const std::vector<PixelRecord>& pixels,
                                            const std::vector<FeatureRecord>& features) {
    VKPT_ASSERT(features.size() == pixels.size(), "one feature record per pixel");
    std::vector<gpu::DenoisePixel> input(pixels.size());
    for (std::size_t i = 0; i < pixels.size(); ++i) {
        gpu::DenoisePixel& pixel = input[i];
        pixel.radiance = glm::vec3(pixels[i].mean);
        pixel.luminanceVariance = float(varianceOfMean(pixels[i]));
        pixel.albedo = features[i].albedo;
        pixel.depth = features[i].depth;
        pixel.normal = features[i].normal;
        pixel.sampleCount = pixels[i].count;
        pixel.halfA = glm::vec3(pixels[i].halves[0].mean);
        pixel.halfCountA = float(pixels[i].halves[0].count);
        pixel.halfB = glm::vec3(pixels[i].halves[1].mean);
        pixel.halfCountB = float(pixels[i].halves[1].count);
    }
    return input;
}

} // namespace vkpt
