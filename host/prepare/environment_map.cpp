// environment_map.cpp — reads the --env map and builds its importance-sampling tables: the
// 2D piecewise-constant distribution of pbrt-v3 §14.2.4 (luminance × sin θ, marginal over
// rows, conditional within each row), summed in double and stored as float CDFs.
#include "prepare/environment_map.h"

#include <cmath>
#include <sstream>

#include "common/errors.h"
#include "common/math_constants.h"
#include "image/hdr_read.h"
#include "shared/sampling.h"

namespace vkpt {

namespace {

// The Rec. 709 weights of the shared luminance(), read from it so the two cannot drift apart;
// applied in double, since a bright texel times the scale can exceed the float range.
double luminanceOf(const glm::dvec3& c) {
    static const glm::dvec3 weights(gpu::luminance(glm::vec3(1.0f, 0.0f, 0.0f)),
                                    gpu::luminance(glm::vec3(0.0f, 1.0f, 0.0f)),
                                    gpu::luminance(glm::vec3(0.0f, 0.0f, 1.0f)));
    return glm::dot(c, weights);
}

std::string describeColour(const glm::vec3& c) {
    std::ostringstream text;
    text << "(" << c.r << ", " << c.g << ", " << c.b << ")";
    return text.str();
}

bool isValidRadiance(const glm::vec3& c) {
    // Written so that NaN fails: every comparison with NaN is false.
    return c.r >= 0.0f && c.g >= 0.0f && c.b >= 0.0f && std::isfinite(c.r) && std::isfinite(c.g) &&
           std::isfinite(c.b);
}

void checkSize(const Image& image, const std::string& path) {
    if (image.width == 0 || image.height == 0)
        throw InputError(path + ": environment map has no texels");
    if (image.width > kMaxEnvironmentSide || image.height > kMaxEnvironmentSide ||
        std::uint64_t(image.width) * image.height > kMaxEnvironmentTexels)
        throw InputError(path + ": environment map " + std::to_string(image.width) + "x" +
                         std::to_string(image.height) + " is too large (at most " +
                         std::to_string(kMaxEnvironmentSide) + " texels a side and " +
                         std::to_string(kMaxEnvironmentTexels) + " in all)");
}

// The first offending texel is named: radiance is never negative, and a NaN or infinity
// would poison the CDF and every pixel that sees it.
void checkTexels(const Image& image, const std::string& path) {
    for (std::uint32_t y = 0; y < image.height; ++y)
        for (std::uint32_t x = 0; x < image.width; ++x)
            if (!isValidRadiance(image.at(x, y)))
                throw InputError(path + ": texel (" + std::to_string(x) + ", " + std::to_string(y) +
                                 ") is " + describeColour(image.at(x, y)) +
                                 ", expected finite non-negative radiance");
}

// sin θ at the centre of row `row` of `height`: the row's share of solid angle per texel.
double rowSinTheta(std::uint32_t row, std::uint32_t height) {
    return std::sin(kPi * (double(row) + 0.5) / double(height));
}

// The exact solid angle of one texel in row `row`: (2π/width)·(cos θ_top − cos θ_bottom).
double texelSolidAngle(std::uint32_t row, std::uint32_t width, std::uint32_t height) {
    const double top = kPi * double(row) / double(height);
    const double bottom = kPi * double(row + 1) / double(height);
    return 2.0 * kPi / double(width) * (std::cos(top) - std::cos(bottom));
}

// Writes weights[0..n) as an inclusive CDF at out[0..n), normalised so that the last entry is
// exactly 1; a total of 0 gives the uniform CDF, so every row stays a distribution (a row
// of weight 0 is never chosen by the marginal, but its entries must still be ordered).
void writeInclusiveCdf(const std::vector<double>& weights, double total, float* out) {
    const std::size_t n = weights.size();
    double running = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        running += weights[i];
        out[i] = total > 0.0 ? float(running / total) : float(double(i + 1) / double(n));
    }
    out[n - 1] = 1.0f;
}

double sum(const std::vector<double>& values) {
    double total = 0.0;
    for (double v : values)
        total += v;
    return total;
}

// Fills the conditional rows and returns each row's luminance sum.
std::vector<double> writeConditionalRows(const SceneEnvironment& environment,
                                         std::vector<float>& cdf) {
    const std::uint32_t width = environment.width;
    const glm::dvec3 scale(environment.radiance);
    std::vector<double> rowSums(environment.height), weights(width);
    for (std::uint32_t row = 0; row < environment.height; ++row) {
        const std::size_t rowStart = std::size_t(row) * width;
        for (std::uint32_t x = 0; x < width; ++x)
            weights[x] = luminanceOf(scale * glm::dvec3(environment.texels[rowStart + x]));
        rowSums[row] = sum(weights);
        writeInclusiveCdf(weights, rowSums[row], cdf.data() + rowStart);
    }
    return rowSums;
}

// (1/4π)·∫ L dω over the map, each texel weighted by its exact solid angle.
glm::dvec3 averageMapRadiance(const SceneEnvironment& environment) {
    glm::dvec3 total(0.0);
    for (std::uint32_t row = 0; row < environment.height; ++row) {
        glm::dvec3 rowTotal(0.0);
        for (std::uint32_t x = 0; x < environment.width; ++x)
            rowTotal += glm::dvec3(environment.texels[std::size_t(row) * environment.width + x]);
        total += rowTotal * texelSolidAngle(row, environment.width, environment.height);
    }
    return total * glm::dvec3(environment.radiance) / (4.0 * kPi);
}

} // namespace

SceneEnvironment readEnvironmentMap(const std::string& path, glm::vec3 scale) {
    if (!isValidRadiance(scale))
        throw InputError(path + ": environment scale " + describeColour(scale) +
                         " must be finite and non-negative");
    Image image = readFloatImage(path);
    checkSize(image, path);
    checkTexels(image, path);
    SceneEnvironment environment;
    environment.radiance = scale;
    environment.width = image.width;
    environment.height = image.height;
    environment.texels = std::move(image.pixels);
    environment.sourcePath = path;
    return environment;
}

EnvironmentDistribution buildEnvironmentDistribution(const SceneEnvironment& environment,
                                                     double sceneRadius) {
    EnvironmentDistribution distribution;
    distribution.averageRadiance = glm::dvec3(environment.radiance);
    if (environment.hasMap()) {
        const std::uint32_t width = environment.width, height = environment.height;
        VKPT_ASSERT(environment.texels.size() == std::size_t(width) * height,
                    "environment texel count != width * height");
        distribution.texels.reserve(environment.texels.size());
        for (const glm::vec3& texel : environment.texels)
            distribution.texels.emplace_back(texel, 0.0f);
        distribution.cdf.resize(std::size_t(width) * height + height);
        const std::vector<double> rowSums = writeConditionalRows(environment, distribution.cdf);
        std::vector<double> rowWeights(height);
        for (std::uint32_t row = 0; row < height; ++row)
            rowWeights[row] = rowSums[row] * rowSinTheta(row, height);
        double total = sum(rowWeights);
        distribution.uniformFallback = !(total > 0.0);
        if (distribution.uniformFallback) {
            // All rows are uniform already (their sums are 0); weigh them by solid angle.
            for (std::uint32_t row = 0; row < height; ++row)
                rowWeights[row] = rowSinTheta(row, height);
            total = sum(rowWeights);
        }
        writeInclusiveCdf(rowWeights, total, distribution.cdf.data() + std::size_t(width) * height);
        distribution.averageRadiance = averageMapRadiance(environment);
    }
    // π·R²·∫ lum(L) dω = π·R²·4π·lum(average).
    distribution.power =
        4.0 * kPi * kPi * sceneRadius * sceneRadius * luminanceOf(distribution.averageRadiance);
    return distribution;
}

gpu::EnvironmentParams makeEnvironmentParams(const SceneEnvironment& environment,
                                             std::uint32_t emitterIndex) {
    gpu::EnvironmentParams params{};
    params.radiance = environment.radiance;
    params.width = environment.hasMap() ? environment.width : 0u;
    params.height = environment.hasMap() ? environment.height : 0u;
    params.emitterIndex = emitterIndex;
    return params;
}

} // namespace vkpt
