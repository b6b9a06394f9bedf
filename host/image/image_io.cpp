// image_io.cpp — the last stage of a render: the mean radiance written as an 8-bit sRGB PNG
// for viewing or as linear float (.pfm, .hdr) for comparison, chosen by extension.
#include "image/image_io.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "common/errors.h"
#include "image/image_file.h"
#include "image/tone_map.h"

namespace vkpt {

namespace {

void checkPixelCount(const Image& image) {
    VKPT_ASSERT(image.pixels.size() == std::size_t(image.width) * image.height,
                "image pixel count != width * height");
}

// Exposure first (in double: a bright pixel times 2^EV can leave the float range), then the tone
// map, then the sRGB encoding; a non-finite component is written as 0 (applyToneMap).
glm::vec3 displayColour(const glm::vec3& linear, double scale, ToneMap toneMap) {
    const glm::dvec3 exposed = glm::dvec3(linear) * scale;
    return applyToneMap(toneMap, glm::vec3(exposed));
}

std::uint8_t srgbByte(float display) {
    return std::uint8_t(std::lround(double(linearToSrgb(display)) * 255.0));
}

// RGBE stores three 8-bit mantissas and a shared exponent byte (exponent + 128), so it has no
// negative numbers, NaN or infinity, and a value of 2^127 or more would need exponent byte 256.
// stb_image_write casts whatever it is given to unsigned char, which for those values is
// undefined, so each component is made representable first: non-finite and negative values
// become 0, larger ones saturate.
float rgbeRepresentable(float value) {
    constexpr float kLargestRgbe = 1.0e38f; // below 2^127 ≈ 1.7e38
    if (!std::isfinite(value) || value < 0.0f) return 0.0f;
    return std::min(value, kLargestRgbe);
}

std::vector<unsigned char> encodeHdr(const Image& image) {
    std::vector<float> rgb;
    rgb.reserve(image.pixels.size() * 3);
    for (const glm::vec3& pixel : image.pixels)
        for (int c = 0; c < 3; ++c)
            rgb.push_back(rgbeRepresentable(pixel[c]));
    return detail::encodeHdrRgb(image.width, image.height, rgb);
}

} // namespace

std::uint64_t countNonFinitePixels(const Image& image) {
    return std::uint64_t(
        std::count_if(image.pixels.begin(), image.pixels.end(), [](const glm::vec3& p) {
            return !(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
        }));
}

float linearToSrgb(float linear) {
    // !(x > 0) also catches NaN, which std::clamp would pass through.
    if (!(linear > 0.0f)) return 0.0f;
    if (!(linear < 1.0f)) return 1.0f;
    const double x = linear;
    // IEC 61966-2-1: a linear segment near black, then a 1/2.4 power with offset.
    const double encoded = x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055;
    return float(encoded);
}

void writePngSrgb(const Image& image, const std::string& path, float exposure, ToneMap toneMap) {
    checkPixelCount(image);
    const double scale = std::exp2(double(exposure));
    std::vector<std::uint8_t> rgb;
    rgb.reserve(image.pixels.size() * 3);
    for (const glm::vec3& pixel : image.pixels) {
        const glm::vec3 display = displayColour(pixel, scale, toneMap);
        for (int c = 0; c < 3; ++c)
            rgb.push_back(srgbByte(display[c]));
    }
    detail::writeFileBytes(path, detail::encodePngRgb8(image.width, image.height, rgb));
}

void writeHdr(const Image& image, const std::string& path) {
    checkPixelCount(image);
    detail::writeFileBytes(path, encodeHdr(image));
}

void writeImage(const Image& image, const std::string& path, float exposure, ToneMap toneMap) {
    writeImageAs(image, path, detail::lowerCaseExtension(path), exposure, toneMap);
}

void writeImageAs(const Image& image, const std::string& path, const std::string& extension,
                  float exposure, ToneMap toneMap) {
    if (extension == ".png")
        writePngSrgb(image, path, exposure, toneMap);
    else if (extension == ".pfm")
        writePfm(image, path);
    else if (extension == ".hdr")
        writeHdr(image, path);
    else
        throw InputError(path + ": unknown image extension '" + extension +
                         "' (use .png, .pfm or .hdr)");
}

} // namespace vkpt
