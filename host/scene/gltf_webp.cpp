// gltf_webp.cpp — checks the RIFF/WEBP signature and decodes with libwebp's WebPDecodeRGBA,
// whose byte order (R, G, B, A) is the texel layout of SceneImage.
#include "scene/gltf_webp.h"

#include <cstring>
#include <memory>

#include <webp/decode.h>

#include "scene/gltf_document.h"

namespace vkpt::gltf {
namespace {

struct WebpFree {
    void operator()(std::uint8_t* pixels) const { WebPFree(pixels); }
};

} // namespace

bool isWebp(std::span<const unsigned char> bytes) {
    return bytes.size() >= 12 && std::memcmp(bytes.data(), "RIFF", 4) == 0 &&
           std::memcmp(bytes.data() + 8, "WEBP", 4) == 0;
}

SceneImage decodeWebp(std::span<const unsigned char> bytes, const std::string& name) {
    int width = 0;
    int height = 0;
    std::unique_ptr<std::uint8_t, WebpFree> pixels(
        WebPDecodeRGBA(bytes.data(), bytes.size(), &width, &height));
    if (!pixels || width <= 0 || height <= 0) {
        throw GltfProblem(name + ": cannot decode the WebP data");
    }
    SceneImage decoded;
    decoded.width = static_cast<std::uint32_t>(width);
    decoded.height = static_cast<std::uint32_t>(height);
    decoded.texels.resize(std::size_t(decoded.width) * decoded.height);
    // R, G, B, A bytes in memory are one little-endian uint with R in the low byte.
    std::memcpy(decoded.texels.data(), pixels.get(), decoded.texels.size() * sizeof(std::uint32_t));
    return decoded;
}

} // namespace vkpt::gltf
