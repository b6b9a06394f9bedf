// pixel_features.cpp — field by field; the means and the count carry over unchanged.
#include "state/pixel_features.h"

namespace vkpt {

FeatureRecord featureRecordOf(const gpu::PixelFeatures& pixel) {
    FeatureRecord record;
    record.albedo = pixel.albedoMean;
    record.normal = pixel.normalMean;
    record.depth = pixel.depth;
    record.samples = pixel.count;
    return record;
}

gpu::PixelFeatures pixelFeaturesOf(const FeatureRecord& record) {
    gpu::PixelFeatures pixel = gpu::noPixelFeatures();
    pixel.albedoMean = record.albedo;
    pixel.normalMean = record.normal;
    pixel.depth = record.depth;
    pixel.count = record.samples;
    return pixel;
}

} // namespace vkpt
