// denoised_output.cpp — the denoise phase and its frame (denoised_output.h).
#include "driver/denoised_output.h"

#include "common/errors.h"
#include "common/phase_log.h"

namespace vkpt {

std::vector<glm::vec3> denoiseWindow(Denoiser& denoiser, const PixelRect& window,
                                     const std::vector<PixelRecord>& pixels,
                                     const std::vector<FeatureRecord>& features,
                                     const DenoiseSettings& settings) {
    VKPT_ASSERT(pixels.size() == window.area(), "one record per window pixel");
    if (features.size() != pixels.size())
        throw InputError("no albedo, normal and depth layers to guide the denoiser");
    ScopedPhase phase("denoise");
    return denoiser.denoise(denoiseInput(pixels, features), window.width(), window.height(),
                            settings);
}

Image denoisedFrame(const Image& raw, const PixelRect& window,
                    const std::vector<glm::vec3>& denoised) {
    Image frame = raw;
    for (std::uint32_t y = window.y0; y < window.y1; ++y)
        for (std::uint32_t x = window.x0; x < window.x1; ++x)
            frame.at(x, y) =
                denoised[std::size_t(y - window.y0) * window.width() + (x - window.x0)];
    return frame;
}

} // namespace vkpt
