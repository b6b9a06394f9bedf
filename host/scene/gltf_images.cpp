// gltf_images.cpp — finds an image's encoded bytes (kept by parseGltfFile, or in a buffer view),
// checks that they are PNG or JPEG, the two formats glTF 2.0 allows (section 3.8.2), and decodes
// them with stb_image into the packed RGBA8 layout of SceneImage.
#include "scene/gltf_images.h"

#include <climits>
#include <cstdint>
#include <cstring>
#include <memory>
#include <span>

#include <stb_image.h>

#include "scene/gltf_document.h"
#include "scene/gltf_webp.h"

namespace vkpt::gltf {
namespace {

constexpr std::size_t kMaxLabel = 60;

std::string quoted(const std::string& label) {
    return "'" + (label.size() > kMaxLabel ? label.substr(0, kMaxLabel) + "..." : label) + "'";
}

std::string imageName(int index, const tinygltf::Image& image) {
    const std::string name = "image " + std::to_string(index);
    return image.name.empty() ? name : name + " (" + quoted(image.name) + ")";
}

std::span<const unsigned char> bufferViewBytes(const tinygltf::Model& model, int viewIndex,
                                               const std::string& name) {
    if (static_cast<std::size_t>(viewIndex) >= model.bufferViews.size()) {
        throw GltfProblem(name + ": buffer view " + std::to_string(viewIndex) +
                          " does not exist (the file has " +
                          std::to_string(model.bufferViews.size()) + " buffer views)");
    }
    // checkBufferViews has placed the view inside its buffer.
    const tinygltf::BufferView& view = model.bufferViews[static_cast<std::size_t>(viewIndex)];
    const auto& data = model.buffers[static_cast<std::size_t>(view.buffer)].data;
    return {data.data() + view.byteOffset, view.byteLength};
}

std::span<const unsigned char> encodedBytes(const tinygltf::Model& model, int index,
                                            const std::string& name) {
    const tinygltf::Image& image = model.images[static_cast<std::size_t>(index)];
    if (image.bufferView >= 0) return bufferViewBytes(model, image.bufferView, name);
    // tinygltf leaves a missing external file with its uri and no bytes (and a warning).
    if (!image.as_is || image.image.empty()) {
        throw GltfProblem(name + ": cannot find the image file " + quoted(image.uri));
    }
    return image.image;
}

enum class ImageFormat { Png, Jpeg, Other };

// By the signature, not the mimeType: the bytes are what stb_image will read.
ImageFormat formatOf(std::span<const unsigned char> bytes) {
    static const unsigned char kPng[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    static const unsigned char kJpeg[3] = {0xFF, 0xD8, 0xFF};
    if (bytes.size() >= sizeof(kPng) && std::memcmp(bytes.data(), kPng, sizeof(kPng)) == 0) {
        return ImageFormat::Png;
    }
    if (bytes.size() >= sizeof(kJpeg) && std::memcmp(bytes.data(), kJpeg, sizeof(kJpeg)) == 0) {
        return ImageFormat::Jpeg;
    }
    return ImageFormat::Other;
}

struct StbFree {
    void operator()(unsigned char* pixels) const { stbi_image_free(pixels); }
};

// The file's label for the image: its name, else its file name (not a data: URI).
std::string imageLabel(const tinygltf::Image& image) {
    std::string label = image.name.empty() ? image.uri : image.name;
    if (label.starts_with("data:")) label.clear();
    return label;
}

SceneImage decodeWithStb(std::span<const unsigned char> bytes, ImageFormat format,
                         const std::string& name) {
    const char* formatName = format == ImageFormat::Png ? "PNG" : "JPEG";
    if (bytes.size() > static_cast<std::size_t>(INT_MAX)) {
        throw GltfProblem(name + ": the " + formatName + " data is larger than 2 GiB");
    }
    int width = 0;
    int height = 0;
    int channels = 0;
    constexpr int kRgba = 4;
    std::unique_ptr<unsigned char, StbFree> pixels(stbi_load_from_memory(
        bytes.data(), static_cast<int>(bytes.size()), &width, &height, &channels, kRgba));
    if (!pixels) {
        throw GltfProblem(name + ": cannot decode the " + formatName + " data (" +
                          stbi_failure_reason() + ")");
    }
    SceneImage decoded;
    decoded.width = static_cast<std::uint32_t>(width);
    decoded.height = static_cast<std::uint32_t>(height);
    decoded.texels.resize(std::size_t(decoded.width) * decoded.height);
    // R, G, B, A bytes in memory are one little-endian uint with R in the low byte.
    std::memcpy(decoded.texels.data(), pixels.get(), decoded.texels.size() * sizeof(std::uint32_t));
    return decoded;
}

} // namespace

SceneImage decodeImage(const tinygltf::Model& model, int imageIndex) {
    const tinygltf::Image& image = model.images[static_cast<std::size_t>(imageIndex)];
    const std::string name = imageName(imageIndex, image);
    const std::span<const unsigned char> bytes = encodedBytes(model, imageIndex, name);
    const ImageFormat format = formatOf(bytes);
    if (format == ImageFormat::Other && !isWebp(bytes)) {
        throw GltfProblem(name + ": not a PNG, JPEG or WebP image (the formats glTF 2.0 and "
                                 "EXT_texture_webp allow)");
    }
    SceneImage decoded =
        format == ImageFormat::Other ? decodeWebp(bytes, name) : decodeWithStb(bytes, format, name);
    decoded.name = imageLabel(image);
    return decoded;
}

} // namespace vkpt::gltf
