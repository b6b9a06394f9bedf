// heat_map.cpp — the adaptive sampler's effort made visible: samples per pixel as a
// colour-mapped PNG written next to the render.
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <vector>

#include "common/errors.h"
#include "image/image_file.h"
#include "image/image_io.h"

namespace vkpt {

namespace {

struct ColourMapPoint {
    float t;
    glm::vec3 rgb;
};

// Viridis (Nathaniel J. Smith, Stéfan van der Walt and Eric Firing, 2015; CC0), the 256-entry
// table _viridis_data in matplotlib's lib/matplotlib/_cm_listed.py, sampled at every 16th entry
// and the last. It is perceptually uniform and stays readable in greyscale and for common
// colour-vision deficiencies; linear interpolation between these 17 entries stays within
// 5/255 of the full table. Values are display (sRGB-encoded) colours.
constexpr std::array<ColourMapPoint, 17> kViridis = {{
    {0.0f / 255.0f, {0.267004f, 0.004874f, 0.329415f}},
    {16.0f / 255.0f, {0.282327f, 0.094955f, 0.417331f}},
    {32.0f / 255.0f, {0.278826f, 0.175490f, 0.483397f}},
    {48.0f / 255.0f, {0.258965f, 0.251537f, 0.524736f}},
    {64.0f / 255.0f, {0.229739f, 0.322361f, 0.545706f}},
    {80.0f / 255.0f, {0.199430f, 0.387607f, 0.554642f}},
    {96.0f / 255.0f, {0.172719f, 0.448791f, 0.557885f}},
    {112.0f / 255.0f, {0.149039f, 0.508051f, 0.557250f}},
    {128.0f / 255.0f, {0.127568f, 0.566949f, 0.550556f}},
    {144.0f / 255.0f, {0.120638f, 0.625828f, 0.533488f}},
    {160.0f / 255.0f, {0.157851f, 0.683765f, 0.501686f}},
    {176.0f / 255.0f, {0.246070f, 0.738910f, 0.452024f}},
    {192.0f / 255.0f, {0.369214f, 0.788888f, 0.382914f}},
    {208.0f / 255.0f, {0.515992f, 0.831158f, 0.294279f}},
    {224.0f / 255.0f, {0.678489f, 0.863742f, 0.189503f}},
    {240.0f / 255.0f, {0.845561f, 0.887322f, 0.099702f}},
    {255.0f / 255.0f, {0.993248f, 0.906157f, 0.143936f}},
}};

std::uint8_t displayByte(float value) {
    return std::uint8_t(std::lround(std::clamp(value, 0.0f, 1.0f) * 255.0f));
}

// Zero samples is black rather than the map's darkest purple, so pixels the sampler never
// reached stand out from pixels that converged at once.
glm::vec3 countColour(std::uint32_t count, std::uint32_t maxCount) {
    if (count == 0) return glm::vec3(0.0f);
    return viridisColour(float(double(count) / double(maxCount)));
}

} // namespace

glm::vec3 viridisColour(float t) {
    if (!(t > 0.0f)) return kViridis.front().rgb; // also NaN
    if (!(t < 1.0f)) return kViridis.back().rgb;
    const auto upper = std::upper_bound(kViridis.begin(), kViridis.end(), t,
                                        [](float v, const ColourMapPoint& p) { return v < p.t; });
    const ColourMapPoint& hi = *upper;
    const ColourMapPoint& lo = *(upper - 1);
    return glm::mix(lo.rgb, hi.rgb, (t - lo.t) / (hi.t - lo.t));
}

void writeSampleCountHeatMap(std::span<const std::uint32_t> counts, std::uint32_t width,
                             std::uint32_t height, const std::string& path) {
    VKPT_ASSERT(counts.size() == std::size_t(width) * height, "sample counts != width * height");
    if (detail::lowerCaseExtension(path) != ".png")
        throw InputError(path + ": the sample-count heat map is a PNG; give it a .png name");
    const std::uint32_t maxCount =
        counts.empty() ? 0 : *std::max_element(counts.begin(), counts.end());
    std::vector<std::uint8_t> rgb;
    rgb.reserve(counts.size() * 3);
    for (std::uint32_t count : counts) {
        const glm::vec3 colour = countColour(count, maxCount);
        for (int c = 0; c < 3; ++c)
            rgb.push_back(displayByte(colour[c]));
    }
    detail::writeFileBytes(path, detail::encodePngRgb8(width, height, rgb));
}

// "dir/x.png" → "dir/x_rate.png"; the map is always a PNG, so "x.pfm" → "x_rate.png" too.
std::string heatMapPathFor(const std::string& outputPath) {
    const std::filesystem::path output(outputPath);
    const std::string name = output.stem().string() + "_rate.png";
    return (output.parent_path() / name).string();
}

} // namespace vkpt
