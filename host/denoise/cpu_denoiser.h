// cpu_denoiser.h — the denoiser's iterations on the host's cores: the functions vkpt's kernels
// run (shared/denoise_filter.h), in the same order, for vkpt-ref and `vkpt-denoise --cpu`.
#pragma once

#include "denoiser.h"

namespace vkpt {

class CpuDenoiser final : public Denoiser {
public:
    // threads 0: every core.
    explicit CpuDenoiser(unsigned threads = 0) : threads_(threads) {}

    std::vector<glm::vec3> denoise(const std::vector<gpu::DenoisePixel>& pixels,
                                   std::uint32_t width, std::uint32_t height,
                                   const DenoiseSettings& settings) override;
    std::string where() const override { return "CPU"; }

private:
    unsigned threads_;
};

} // namespace vkpt
