// image_file.h — internal to vkpt_image: whole-file reads and writes that report failures as
// InputError naming the path, and the stb_image_write encoders the writers share.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace vkpt::detail {

// Throws InputError "<path>: cannot write: <reason>" when the file cannot be written completely.
void writeFileBytes(const std::string& path, std::span<const unsigned char> bytes);

// Throws InputError "<path>: cannot read: <reason>".
std::vector<unsigned char> readFileBytes(const std::string& path);

// 8-bit RGB, rows top first, width * height * 3 bytes, encoded as PNG in memory.
std::vector<unsigned char> encodePngRgb8(std::uint32_t width, std::uint32_t height,
                                         std::span<const std::uint8_t> rgb);

// Linear RGB floats, rows top first, each finite and >= 0, encoded as Radiance RGBE in memory.
std::vector<unsigned char> encodeHdrRgb(std::uint32_t width, std::uint32_t height,
                                        std::span<const float> rgb);

// The file name's extension in lower case with its dot (".png"), or "" when it has none.
std::string lowerCaseExtension(const std::string& path);

} // namespace vkpt::detail
