// sample_plan.h — which pixels and which samples one process renders: --task K/N takes the
// K-th of N contiguous shares of every pixel's sample indices, --crop a pixel rectangle; and
// the settings that must match for renders to be parts of one image.
#pragma once

#include <cstdint>
#include <string>

#include "common/render_settings.h"
#include "state/render_state.h"

namespace vkpt {

// Task K of N (K from 0).
struct TaskShare {
    std::uint32_t index = 0;
    std::uint32_t count = 1;
};

// "K/N" with 0 <= K < N; throws InputError naming the option.
TaskShare parseTaskShare(const std::string& text);

// Task K's share of [0, spp): [⌊K·spp/N⌋, ⌊(K+1)·spp/N⌋). The shares are disjoint, cover
// [0, spp) and differ in size by at most one sample.
SampleRange taskSampleRange(std::uint32_t samplesPerPixel, const TaskShare& task);

struct SamplePlan {
    PixelRect crop;    // the pixels rendered
    SampleRange range; // the sample indices each pixel is given (its budget)
};

// The canonical text of every setting that changes a sample's value (integrator, sampler, depths,
// light sampling, path filter, clamp, adaptive rule with its dark floor); the scene, camera and
// environment are in the scene hash, the seed and image size in StateIdentity. Options that
// only change how fast the same samples are made (--general, --threads, --path-slots) and
// what is done with the finished image (--exposure, outside adaptive sampling) are left out.
std::string settingsKey(const RenderSettings& settings);

} // namespace vkpt
