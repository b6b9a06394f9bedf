// pixel_features.h — the executors' per-pixel AOV accumulators (gpu::PixelFeatures, the same on
// the device and in vkpt-ref) as the state's FeatureRecord, and back for a resumed render.
#pragma once

#include "shared/sample_features.h"
#include "state/render_state.h"

namespace vkpt {

FeatureRecord featureRecordOf(const gpu::PixelFeatures& pixel);
gpu::PixelFeatures pixelFeaturesOf(const FeatureRecord& record);

} // namespace vkpt
