// accumulate.comp — the last stage of a pass, one invocation per active pixel of the chunk: adds
// the pixel's k samples in sample order to its running estimate (non-finite ones discarded and
// counted, the rest clamped when --clamp asks, shared/sample_guard.h), applies the adaptive
// stopping rule after every sample that completes a batch (exactly where the reference does),
// keeps the means of the two halves of the samples (even and odd sample indices), and appends
// the pixels that go on to the next pass's active list. When the render records
// AOVs, each sample's features join the pixel's in the same order and up to the same sample.
#version 460
#extension GL_GOOGLE_include_directive : require
#include "lib/aovs.glsl"
#include "lib/frame.glsl"

layout(local_size_x = WORKGROUP_SIZE) in;

#include "lib/kernel_bindings.h"

VKPT_DECLARE_BUFFERS(ACCUMULATE_BINDINGS)

#include "lib/counters.glsl"
#include "lib/records.glsl"
#include "shared/adaptive.h"
#include "shared/sample_guard.h"
#include "shared/sampler.h"
#include "shared/sampling.h"

// The largest float: M2 saturates there instead of overflowing to infinity (a pixel of samples
// above ~1e19 has a variance beyond float; it then never counts as converged).
#define FLOAT_MAX 3.402823466e38

// The running mean of the half that sample `sampleIndex` belongs to (shared/sampler.h).
void addSampleToHalf(inout PixelState pixel, vec3 radiance, uint sampleIndex) {
    if (sampleHalf(sampleIndex) == 0u) {
        pixel.evenCount += 1u;
        pixel.evenMean += (radiance - pixel.evenMean) / float(pixel.evenCount);
    } else {
        pixel.oddCount += 1u;
        pixel.oddMean += (radiance - pixel.oddMean) / float(pixel.oddCount);
    }
}

// Kahan summation of the radiance, scaled by ACCUMULATION_SCALE (precise: reassociation would
// cancel the compensation), and Welford's running mean and M2 of the luminance. M2 cannot go
// negative in exact arithmetic; the clamp keeps rounding from making it so.
void addSample(inout PixelState pixel, vec3 radiance) {
    precise vec3 corrected = radiance * ACCUMULATION_SCALE - pixel.compensation;
    precise vec3 total = pixel.radianceSum + corrected;
    precise vec3 lost = (total - pixel.radianceSum) - corrected;
    pixel.compensation = lost;
    pixel.radianceSum = total;
    pixel.count += 1u;
    float value = luminance(radiance);
    float delta = value - pixel.luminanceMean;
    pixel.luminanceMean += delta / float(pixel.count);
    float m2 = pixel.luminanceM2 + delta * (value - pixel.luminanceMean);
    pixel.luminanceM2 = clamp(m2, 0.0, FLOAT_MAX);
}

bool batchConverged(PixelState pixel) {
    if (frame.adaptive == 0u || pixel.samplesTaken % frame.adaptiveBatch != 0u) return false;
    return isPixelConverged(pixel.count, pixel.luminanceMean, pixel.luminanceM2,
                            frame.adaptiveMinSamples, frame.adaptiveTolerance,
                            frame.adaptiveDarkFloor, passParams.adaptiveVarianceScale);
}

// Adds the pixel's samples of this pass; returns whether it goes on sampling, and how many of
// its samples were not finite.
bool accumulatePixel(uint activeIndex, out uint pixelIndex, out uint nonFinite) {
    uint k = passParams.samplesPerPass;
    uint first = activeIndex * k;
    pixelIndex = fetchPathState(first).pixel;
    PixelState pixel = pixelStates[pixelIndex];
    PixelFeatures features;
    if (renderAovs()) features = pixelFeatures[pixelIndex];
    nonFinite = 0u;
    for (uint j = 0u; j < k; ++j) {
        if (renderAovs()) addSampleFeatures(features, sampleFeatures[first + j]);
        PathState path = fetchPathState(first + j);
        if (isFiniteSample(path.radiance)) {
            vec3 radiance = clampSample(path.radiance, frame.sampleClamp);
            addSample(pixel, radiance);
            addSampleToHalf(pixel, radiance, path.sampleIndex);
        } else {
            ++nonFinite; // discarded: one NaN would poison the pixel for good
        }
        // A count, not the sample index + 1: a task's samples start at its share's first index.
        pixel.samplesTaken += 1u;
        // A converged pixel ignores the rest of the pass, so it takes the reference's samples.
        if (batchConverged(pixel)) {
            pixel.converged = 1u;
            break;
        }
    }
    pixelStates[pixelIndex] = pixel;
    if (renderAovs()) pixelFeatures[pixelIndex] = features;
    return pixel.converged == 0u;
}

void main() {
    uint activeIndex = flatInvocationIndex();
    uint pixelIndex = 0u;
    uint nonFinite = 0u;
    bool goesOn = activeIndex < passParams.chunkPixels &&
                  accumulatePixel(activeIndex, pixelIndex, nonFinite);
    addToCounter64InSubgroup(COUNTER_NON_FINITE, nonFinite);
    uint next = appendToQueue(COUNTER_ACTIVE_NEXT, goesOn);
    if (goesOn) activePixels[(passParams.activeParity ^ 1u) * frame.pixelCount + next] = pixelIndex;
}
