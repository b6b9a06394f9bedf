// decode_png.h — a PNG's 8-bit RGB bytes as stb_image decodes them (any viewer would show the
// same), for tests that check what a program wrote. stb_image's implementation is compiled once
// in vkpt_image, which every user of this header links.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <stb_image.h>

namespace vkpt::test {

// Row-major RGB, top row first; empty when the file does not decode.
inline std::vector<std::uint8_t> decodePng(const std::string& path, int& width, int& height) {
    struct StbFree {
        void operator()(stbi_uc* pixels) const { stbi_image_free(pixels); }
    };
    int channels = 0;
    std::unique_ptr<stbi_uc, StbFree> pixels(
        stbi_load(path.c_str(), &width, &height, &channels, 3));
    if (!pixels) return {};
    return {pixels.get(), pixels.get() + std::size_t(width) * std::size_t(height) * 3};
}

} // namespace vkpt::test
