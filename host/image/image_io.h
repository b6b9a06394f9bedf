// image_io.h — writing rendered images (.png sRGB 8-bit, .pfm and .hdr linear float, chosen by
// extension), reading .pfm back for comparisons, and the sample-count heat map.
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "common/render_settings.h"
#include "image/image.h"

namespace vkpt {

// Writes by extension; for .png, exposure (EV) scales by 2^EV, then the tone map brings the
// colour into [0, 1] (tone_map.h; the programs' default, PBR Neutral, here too), then the 8-bit
// sRGB encoding; float formats ignore both and stay linear. Throws InputError for an unknown
// extension or a write failure, naming the path. Values a format cannot hold are never left to
// chance: PFM keeps NaN and infinity exactly; PNG writes a non-finite or negative component as
// 0; HDR (RGBE) writes non-finite and negative components as 0.
void writeImage(const Image& image, const std::string& path, float exposure = 0.0f,
                ToneMap toneMap = ToneMap::PbrNeutral);

// The same in the format of `extension` (".png", ".pfm", ".hdr"), whatever `path` ends in: for a
// temporary file that is renamed to the real name once written (atomic_write.h).
void writeImageAs(const Image& image, const std::string& path, const std::string& extension,
                  float exposure = 0.0f, ToneMap toneMap = ToneMap::PbrNeutral);

void writePfm(const Image& image, const std::string& path);
void writeHdr(const Image& image, const std::string& path);
void writePngSrgb(const Image& image, const std::string& path, float exposure = 0.0f,
                  ToneMap toneMap = ToneMap::PbrNeutral);

// PFM ("PF" RGB or "Pf" greyscale, expanded to RGB; little- or big-endian by the scale's sign;
// bottom row first in the file, top row first in the Image). Throws InputError naming the path
// and the problem for a missing, malformed or truncated file.
Image readPfm(const std::string& path);

// Samples per pixel as a colour-mapped PNG (viridis): 0 is black, the image's largest count the
// brightest colour of the map. The path must end in .png (InputError otherwise).
void writeSampleCountHeatMap(std::span<const std::uint32_t> counts, std::uint32_t width,
                             std::uint32_t height, const std::string& path);

// "out/cornell.png" → "out/cornell_rate.png"; also "out/cornell.pfm" → "out/cornell_rate.png".
std::string heatMapPathFor(const std::string& outputPath);

// The viridis colour map at t in [0, 1] (clamped), as display sRGB values in [0, 1].
glm::vec3 viridisColour(float t);

// Pixels with a NaN or infinite component, for a warning before an image is written: the PNG
// would show them as black, and a comparison would reject them.
std::uint64_t countNonFinitePixels(const Image& image);

// IEC 61966-2-1 sRGB transfer function of a linear value clamped to [0, 1].
float linearToSrgb(float linear);

} // namespace vkpt
