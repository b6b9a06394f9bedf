// device_denoiser.h — the denoiser's iterations as compute kernels on a Vulkan device
// (demodulate_radiance, then filter_radiance once per à-trous step, ping-ponging two iterates):
// the same functions as the CPU loop (shared/denoise_filter.h), so that both give the same image
// up to the device's float rounding.
#pragma once

#include <optional>

#include "denoise/denoiser.h"
#include "gpu/kernel.h"

namespace vkpt {

class GpuContext;

class DeviceDenoiser final : public Denoiser {
public:
    // Creates the two pipelines on `context`, which must outlive the denoiser.
    explicit DeviceDenoiser(GpuContext& context);

    std::vector<glm::vec3> denoise(const std::vector<gpu::DenoisePixel>& pixels,
                                   std::uint32_t width, std::uint32_t height,
                                   const DenoiseSettings& settings) override;
    std::string where() const override;

private:
    GpuContext& context_;
    Kernel demodulate_;
    Kernel filter_;
};

} // namespace vkpt
