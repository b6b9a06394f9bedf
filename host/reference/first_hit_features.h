// first_hit_features.h — the layers a denoiser and a compositor read beside the colour:
// albedo, shading normal and depth at the first surface each camera sample sees. Both
// executors take them from here, so that a pixel's features are the same in every part of a
// render whichever executor made it.
#pragma once

#include <vector>

#include "prepare/prepared_scene.h"
#include "reference/scene_intersector.h"
#include "state/render_state.h"

namespace vkpt {

// Camera samples per pixel for the features: the camera jitters of sample indices 0..15 (the
// same rays as the colour's first 16 samples), whatever the part's sample range, so that a
// pixel's features depend on the pixel alone and every part agrees on them. Features vary only
// at edges within a pixel; 16 samples resolve those to about 1/16 of coverage.
inline constexpr std::uint32_t kFeatureSamples = 16;

// For each pixel of `window`, row-major: albedo (the base colour, textures applied) and
// shading normal (world space, turned towards the camera) averaged over the samples, a miss
// counting as 0, so that edges are filtered like the colour (Open Image Denoise asks for that);
// depth the camera-space z of the nearest hit (+inf when every sample misses). Rays go through
// `intersectors`; `threads` 0: every core.
std::vector<FeatureRecord> renderFirstHitFeatures(const PreparedScene& scene,
                                                  const IntersectorFactory& intersectors,
                                                  const gpu::Camera& camera, std::uint32_t seed,
                                                  const PixelRect& window, unsigned threads);

} // namespace vkpt
