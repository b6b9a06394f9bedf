// image_compare.cpp — per-pixel z-test between two renders (GPU against CPU reference, or two
// seeds), using the variance each accumulator already keeps: noise passes, bias is located.
#include "image/image_compare.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include "common/errors.h"
#include "image/student_t.h"

namespace vkpt {

namespace {

// Luminance statistics of one pixel: the sample count, the mean and the variance of that mean
// (the sample variance M2 / (n − 1) divided by n).
struct PixelStats {
    std::uint32_t n = 0;
    double mean = 0.0;
    double varianceOfMean = 0.0;
};

enum class Verdict { Agrees, Differs, ZeroVarianceMismatch, TooFewSamples, NonFinite };

struct PixelVerdict {
    Verdict verdict = Verdict::Agrees;
    double z = 0.0; // meaningful for Agrees and Differs
};

// How many pixels got one verdict, and where the first of them is (row-major order).
struct Tally {
    std::uint64_t count = 0;
    std::uint32_t firstX = 0;
    std::uint32_t firstY = 0;

    void add(std::uint32_t x, std::uint32_t y) {
        if (count++ == 0) firstX = x, firstY = y;
    }
};

struct ZTestTally {
    Tally differs, zeroVarianceMismatch, tooFewSamples, nonFinite;
    bool haveZ = false;
    double worstZ = 0.0;
    std::uint32_t worstX = 0, worstY = 0;
};

void checkConsistent(const RenderOutput& output) {
    const std::size_t pixels = std::size_t(output.image.width) * output.image.height;
    VKPT_ASSERT(output.sampleCounts.size() == pixels && output.luminanceMean.size() == pixels &&
                    output.luminanceM2.size() == pixels,
                "render output statistics do not match its image size");
}

PixelStats pixelStats(const RenderOutput& output, std::size_t i) {
    PixelStats stats;
    stats.n = output.sampleCounts[i];
    stats.mean = output.luminanceMean[i];
    if (stats.n >= 2) {
        // Welford's M2 cannot go negative in exact arithmetic; never let rounding make it so.
        const double m2 = std::max(0.0, double(output.luminanceM2[i]));
        stats.varianceOfMean = m2 / double(stats.n - 1) / double(stats.n);
    }
    return stats;
}

bool isFinite(const PixelStats& s) {
    return std::isfinite(s.mean) && std::isfinite(s.varianceOfMean);
}

// With no noise on either side (a pixel that sees only the background, or only an emitter)
// the means must agree up to float rounding of the accumulators.
bool meansAgreeExactly(double a, double b) {
    constexpr double kRelative = 1e-5, kAbsolute = 1e-7;
    return std::abs(a - b) <= std::max(kAbsolute, kRelative * std::max(std::abs(a), std::abs(b)));
}

// Welch–Satterthwaite degrees of freedom of the difference of two means whose variances
// were estimated from na and nb samples.
double welchDegreesOfFreedom(const PixelStats& a, const PixelStats& b) {
    const double va = a.varianceOfMean, vb = b.varianceOfMean;
    const double denominator = va * va / double(a.n - 1) + vb * vb / double(b.n - 1);
    return (va + vb) * (va + vb) / denominator;
}

// Welch's t-test: the statistic is the z of the header, but its null distribution is Student's
// t, whose heavier tails matter when a pixel's variance comes from a few dozen samples.
PixelVerdict comparePixel(const PixelStats& a, const PixelStats& b, double alphaPerPixel) {
    if (a.n < 2 || b.n < 2) return {Verdict::TooFewSamples};
    if (!isFinite(a) || !isFinite(b)) return {Verdict::NonFinite};
    const double variance = a.varianceOfMean + b.varianceOfMean;
    if (variance == 0.0)
        return {meansAgreeExactly(a.mean, b.mean) ? Verdict::Agrees
                                                  : Verdict::ZeroVarianceMismatch};
    const double z = (a.mean - b.mean) / std::sqrt(variance);
    const double pValue = studentTwoSidedPValue(z, welchDegreesOfFreedom(a, b));
    return {pValue < alphaPerPixel ? Verdict::Differs : Verdict::Agrees, z};
}

void record(ZTestTally& tally, const PixelVerdict& v, std::uint32_t x, std::uint32_t y) {
    switch (v.verdict) {
    case Verdict::Differs:
        tally.differs.add(x, y);
        break;
    case Verdict::ZeroVarianceMismatch:
        tally.zeroVarianceMismatch.add(x, y);
        return;
    case Verdict::TooFewSamples:
        tally.tooFewSamples.add(x, y);
        return;
    case Verdict::NonFinite:
        tally.nonFinite.add(x, y);
        return;
    case Verdict::Agrees:
        break;
    }
    if (!tally.haveZ || std::abs(v.z) > std::abs(tally.worstZ)) {
        tally.haveZ = true;
        tally.worstZ = v.z;
        tally.worstX = x, tally.worstY = y;
    }
}

std::string formatted(const char* format, double value) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, format, value);
    return buffer;
}

// Appended piecewise: GCC 12 at -O2 reports a false -Wrestrict for "(" + std::to_string(x).
std::string at(std::uint32_t x, std::uint32_t y) {
    std::string text = "(";
    text.append(std::to_string(x)).append(", ").append(std::to_string(y)) += ')';
    return text;
}

// "3 of 4096 pixels differ", "1 of 4096 pixels differs": the verb agrees with the count.
std::string countOf(const Tally& t, std::uint64_t pixels, const char* one, const char* many) {
    return std::to_string(t.count) + " of " + std::to_string(pixels) + " pixels " +
           (t.count == 1 ? one : many);
}

std::string worstZText(const ZTestTally& tally) {
    return "worst z = " + formatted("%.3g", tally.worstZ) + " at " + at(tally.worstX, tally.worstY);
}

std::string failureSummary(const ZTestTally& tally, const ZTestResult& r, std::uint64_t pixels) {
    std::vector<std::string> clauses;
    if (tally.differs.count > 0)
        clauses.push_back(countOf(tally.differs, pixels, "differs", "differ") +
                          " at per-pixel p < " + formatted("%.3g", r.alphaPerPixel) +
                          " (Welch t; |z| > " + formatted("%.3g", r.criticalZ) +
                          " for many samples; family alpha " + formatted("%g", r.alphaFamily) +
                          "); " + worstZText(tally));
    if (const Tally& t = tally.zeroVarianceMismatch; t.count > 0)
        clauses.push_back(countOf(t, pixels, "has", "have") +
                          " zero variance in both images but different means (first at " +
                          at(t.firstX, t.firstY) + ")");
    if (const Tally& t = tally.tooFewSamples; t.count > 0)
        clauses.push_back(countOf(t, pixels, "has", "have") +
                          " fewer than 2 samples in an image, so no variance to test with "
                          "(first at " +
                          at(t.firstX, t.firstY) + ")");
    if (const Tally& t = tally.nonFinite; t.count > 0)
        clauses.push_back(countOf(t, pixels, "has", "have") +
                          " a non-finite mean or variance (first at " + at(t.firstX, t.firstY) +
                          ")");
    std::string summary = "z-test: ";
    for (std::size_t i = 0; i < clauses.size(); ++i)
        summary += (i > 0 ? "; " : "") + clauses[i];
    return summary;
}

std::string passSummary(const ZTestTally& tally, const ZTestResult& r, std::uint64_t pixels) {
    return "z-test passed: " + std::to_string(pixels) +
           " pixels, per-pixel p >= " + formatted("%.3g", r.alphaPerPixel) +
           " (Welch t; family alpha " + formatted("%g", r.alphaFamily) + "), " + worstZText(tally);
}

ZTestTally tallyPixels(const RenderOutput& a, const RenderOutput& b, double alphaPerPixel) {
    ZTestTally tally;
    const std::uint32_t width = a.image.width;
    for (std::uint32_t y = 0; y < a.image.height; ++y)
        for (std::uint32_t x = 0; x < width; ++x) {
            const std::size_t i = std::size_t(y) * width + x;
            record(tally, comparePixel(pixelStats(a, i), pixelStats(b, i), alphaPerPixel), x, y);
        }
    return tally;
}

} // namespace

// Šidák: with N independent pixel tests at level α₁, the chance of no false alarm is
// (1 − α₁)^N; setting it to 1 − α gives α₁ = 1 − (1 − α)^(1/N). Written with log1p and expm1
// because (1 − α)^(1/N) rounds to 1 for large N and small α.
ZTestResult zTestPerPixel(const RenderOutput& a, const RenderOutput& b, double alphaFamily) {
    VKPT_ASSERT(a.image.width == b.image.width && a.image.height == b.image.height,
                "z-test of images of different sizes");
    VKPT_ASSERT(alphaFamily > 0.0 && alphaFamily < 1.0, "family alpha must lie in (0, 1)");
    checkConsistent(a);
    checkConsistent(b);
    const std::uint64_t pixels = std::uint64_t(a.image.width) * a.image.height;
    VKPT_ASSERT(pixels > 0, "z-test of empty images");

    ZTestResult result;
    result.alphaFamily = alphaFamily;
    result.alphaPerPixel = -std::expm1(std::log1p(-alphaFamily) / double(pixels));
    result.criticalZ = normalUpperQuantile(result.alphaPerPixel / 2.0); // two-sided
    const ZTestTally tally = tallyPixels(a, b, result.alphaPerPixel);
    result.rejectedPixels = tally.differs.count + tally.zeroVarianceMismatch.count +
                            tally.tooFewSamples.count + tally.nonFinite.count;
    result.passed = result.rejectedPixels == 0;
    result.worstZ = tally.worstZ;
    result.worstX = tally.worstX;
    result.worstY = tally.worstY;
    result.summary =
        result.passed ? passSummary(tally, result, pixels) : failureSummary(tally, result, pixels);
    return result;
}

MeanEstimate meanLuminance(const RenderOutput& output) {
    checkConsistent(output);
    const std::size_t pixels = output.luminanceMean.size();
    VKPT_ASSERT(pixels > 0, "mean luminance of an empty image");
    double sum = 0.0, varianceSum = 0.0;
    bool varianceKnown = true;
    for (std::size_t i = 0; i < pixels; ++i) {
        const PixelStats stats = pixelStats(output, i);
        sum += stats.mean;
        varianceSum += stats.varianceOfMean;
        varianceKnown = varianceKnown && stats.n >= 2;
    }
    // A pixel with one sample has no variance estimate; NaN rather than an optimistic figure,
    // so that a check built on the standard error cannot pass by accident.
    const double n = double(pixels);
    return {sum / n,
            varianceKnown ? std::sqrt(varianceSum) / n : std::numeric_limits<double>::quiet_NaN()};
}

} // namespace vkpt
