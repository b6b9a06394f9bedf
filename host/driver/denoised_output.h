// denoised_output.h — the denoised image as the driver's output: whichever executor rendered the
// pixels, and whether they come from one run or a merge of many (vkpt-denoise), the denoiser
// reads the pixels' moments and AOVs and nothing else, under a phase of its own ("denoise").
#pragma once

#include <vector>

#include "denoise/denoiser.h"
#include "image/image.h"
#include "state/render_state.h"

namespace vkpt {

// The denoised radiance of the window's pixels (row-major), with the AOVs `features` of the
// same pixels. InputError when there are none (a state saved without AOV layers).
std::vector<glm::vec3> denoiseWindow(Denoiser& denoiser, const PixelRect& window,
                                     const std::vector<PixelRecord>& pixels,
                                     const std::vector<FeatureRecord>& features,
                                     const DenoiseSettings& settings = {});

// `raw` (the whole frame) with the window's pixels replaced by `denoised` (denoiseWindow's).
Image denoisedFrame(const Image& raw, const PixelRect& window,
                    const std::vector<glm::vec3>& denoised);

} // namespace vkpt
