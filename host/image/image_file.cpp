// image_file.cpp — file access and PNG encoding shared by the image writers, so that every
// format reports a failed write the same way: one InputError naming the path and the reason.
#include "image/image_file.h"

#include <cctype>
#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>

#include <stb_image_write.h>

#include "common/errors.h"

namespace vkpt::detail {

namespace {

struct FileCloser {
    void operator()(std::FILE* file) const { std::fclose(file); }
};
using FilePtr = std::unique_ptr<std::FILE, FileCloser>;

// errno is captured at the failing call; a later library call could overwrite it.
[[noreturn]] void throwFileError(const std::string& path, const char* action, int error) {
    const std::string reason = error != 0 ? std::strerror(error) : "unknown error";
    throw InputError(path + ": cannot " + action + ": " + reason);
}

// stb_image_write hands the encoded bytes to a callback in pieces; collect them in memory.
void appendToVector(void* context, void* data, int size) {
    auto* bytes = static_cast<std::vector<unsigned char>*>(context);
    const auto* first = static_cast<const unsigned char*>(data);
    bytes->insert(bytes->end(), first, first + size);
}

} // namespace

void writeFileBytes(const std::string& path, std::span<const unsigned char> bytes) {
    errno = 0;
    std::FILE* raw = std::fopen(path.c_str(), "wb");
    if (raw == nullptr) throwFileError(path, "write", errno);
    FilePtr file(raw);
    const bool written = std::fwrite(bytes.data(), 1, bytes.size(), raw) == bytes.size();
    // fclose flushes the last buffer, so a full disk may only show up here.
    const bool closed = std::fclose(file.release()) == 0;
    if (written && closed) return;
    const int error = errno;
    std::remove(path.c_str()); // a truncated image could later pass for a result
    throwFileError(path, "write", error);
}

std::vector<unsigned char> readFileBytes(const std::string& path) {
    errno = 0;
    FilePtr file(std::fopen(path.c_str(), "rb"));
    if (!file) throwFileError(path, "read", errno);
    std::vector<unsigned char> bytes;
    unsigned char chunk[1 << 16];
    std::size_t count = 0;
    while ((count = std::fread(chunk, 1, sizeof chunk, file.get())) > 0)
        bytes.insert(bytes.end(), chunk, chunk + count);
    if (std::ferror(file.get())) throwFileError(path, "read", errno);
    return bytes;
}

std::vector<unsigned char> encodePngRgb8(std::uint32_t width, std::uint32_t height,
                                         std::span<const std::uint8_t> rgb) {
    VKPT_ASSERT(width > 0 && height > 0, "PNG cannot hold an empty image");
    VKPT_ASSERT(width <= INT_MAX / 3 && height <= INT_MAX, "image too large for stb_image_write");
    VKPT_ASSERT(rgb.size() == std::size_t(width) * height * 3, "RGB byte count != 3 * pixels");
    std::vector<unsigned char> png;
    const int stride = int(width) * 3;
    const int ok = stbi_write_png_to_func(appendToVector, &png, int(width), int(height), 3,
                                          rgb.data(), stride);
    VKPT_ASSERT(ok != 0, "stb_image_write failed to encode a PNG in memory");
    return png;
}

std::vector<unsigned char> encodeHdrRgb(std::uint32_t width, std::uint32_t height,
                                        std::span<const float> rgb) {
    VKPT_ASSERT(width > 0 && height > 0, "Radiance HDR cannot hold an empty image");
    VKPT_ASSERT(width <= INT_MAX && height <= INT_MAX, "image too large for stb_image_write");
    VKPT_ASSERT(rgb.size() == std::size_t(width) * height * 3, "float count != 3 * pixels");
    std::vector<unsigned char> hdr;
    const int ok =
        stbi_write_hdr_to_func(appendToVector, &hdr, int(width), int(height), 3, rgb.data());
    VKPT_ASSERT(ok != 0, "stb_image_write failed to encode an HDR image in memory");
    return hdr;
}

std::string lowerCaseExtension(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    for (char& c : extension)
        c = char(std::tolower(static_cast<unsigned char>(c)));
    return extension;
}

} // namespace vkpt::detail
