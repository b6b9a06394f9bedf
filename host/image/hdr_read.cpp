// hdr_read.cpp — decodes Radiance RGBE with stb_image (the implementation comes from the
// system's libstb, as stb_image_write's does) after checking that the file holds every byte
// the decoder will read: stb_image reads past the end of a truncated file as zeros, which
// gives a silently wrong image, or, inside a run-length encoded scanline, never finishes.
#include "image/hdr_read.h"

#include <climits>
#include <cstdlib>
#include <memory>
#include <vector>

#include <stb_image.h>

#include "common/errors.h"
#include "image/image_file.h"
#include "image/image_io.h"

namespace vkpt {

namespace {

struct StbFree {
    void operator()(float* pixels) const { stbi_image_free(pixels); }
};

// stb_image would decode a PNG or JPEG named .hdr as well (as gamma-corrected LDR), which is
// never what a radiance map means: the signature is checked first.
void checkRadianceSignature(const std::vector<unsigned char>& bytes, const std::string& path) {
    if (bytes.empty()) throw InputError(path + ": empty file, expected a Radiance HDR image");
    if (stbi_is_hdr_from_memory(bytes.data(), int(bytes.size())) == 0)
        throw InputError(path + ": not a Radiance HDR file (it does not start with "
                                "'#?RADIANCE' or '#?RGBE')");
}

// Walks the file as stb_image's decoder reads it (the header's lines up to the blank one,
// the "-Y height +X width" line, then the scanlines) to find where the pixel data ends.
// Anything the walk does not understand is left for the decoder to report.
class RgbeDataWalk {
public:
    RgbeDataWalk(const std::vector<unsigned char>& bytes, const std::string& path)
        : bytes_(bytes), path_(path) {}

    void checkComplete() {
        nextLine(); // the signature, already checked
        while (!atEnd() && !nextLine().empty()) {
        }
        const std::string resolution = nextLine();
        char* end = nullptr;
        if (resolution.rfind("-Y ", 0) != 0) return;
        const long height = std::strtol(resolution.c_str() + 3, &end, 10);
        while (*end == ' ')
            ++end;
        if (std::string(end).rfind("+X ", 0) != 0) return;
        const long width = std::strtol(end + 3, nullptr, 10);
        if (width <= 0 || height <= 0 || width > (1 << 24) || height > (1 << 24)) return;
        if (width < 8 || width >= 32768) {
            requireFlat(std::size_t(width), std::size_t(height));
        } else {
            walkScanlines(std::size_t(width), std::size_t(height));
        }
    }

private:
    bool atEnd() const { return pos_ >= bytes_.size(); }

    std::string nextLine() {
        std::string line;
        while (!atEnd() && bytes_[pos_] != '\n')
            line += char(bytes_[pos_++]);
        if (!atEnd()) ++pos_;
        return line;
    }

    // `scanline` counts from 0; the message counts from 1, as a person reads it.
    [[noreturn]] void truncated(std::size_t scanline, std::size_t height) const {
        throw InputError(path_ + ": truncated Radiance HDR: the file (" +
                         std::to_string(bytes_.size()) + " bytes) ends in scanline " +
                         std::to_string(scanline + 1) + " of " + std::to_string(height));
    }

    // Flat RGBE from here: 4 bytes a pixel for the whole image.
    void requireFlat(std::size_t width, std::size_t height) const {
        const std::size_t pixels = (bytes_.size() - pos_) / 4;
        if (pixels < width * height) truncated(pixels / width, height);
    }

    void walkScanlines(std::size_t width, std::size_t height) {
        for (std::size_t y = 0; y < height; ++y) {
            if (bytes_.size() - pos_ < 4) truncated(y, height);
            const unsigned char* p = bytes_.data() + pos_;
            if (p[0] != 2 || p[1] != 2 || (p[2] & 0x80) != 0) {
                // Not run-length encoded: stb_image then decodes the whole image as flat
                // pixels starting here (its decoder restarts at row 0).
                requireFlat(width, height);
                return;
            }
            if ((std::size_t(p[2]) << 8 | p[3]) != width) return; // the decoder rejects it
            pos_ += 4;
            for (int component = 0; component < 4; ++component)
                if (!walkRuns(width, y, height)) return;
        }
    }

    // One component of one scanline: runs (count > 128: one value repeated count − 128
    // times) and literal spans (count values). False where the decoder will reject the data.
    bool walkRuns(std::size_t width, std::size_t y, std::size_t height) {
        std::size_t filled = 0;
        while (filled < width) {
            if (atEnd()) truncated(y, height);
            std::size_t count = bytes_[pos_++];
            const bool run = count > 128;
            if (run) count -= 128;
            if (count > width - filled) return false;
            const std::size_t dataBytes = run ? 1 : count;
            if (bytes_.size() - pos_ < dataBytes) truncated(y, height);
            pos_ += dataBytes;
            filled += count;
        }
        return true;
    }

    const std::vector<unsigned char>& bytes_;
    const std::string& path_;
    std::size_t pos_ = 0;
};

} // namespace

Image readRadianceHdr(const std::string& path) {
    const std::vector<unsigned char> bytes = detail::readFileBytes(path);
    if (bytes.size() > std::size_t(INT_MAX))
        throw InputError(path + ": file too large for the Radiance HDR reader (2 GiB at most)");
    checkRadianceSignature(bytes, path);
    RgbeDataWalk(bytes, path).checkComplete();
    int width = 0, height = 0, channels = 0;
    std::unique_ptr<float, StbFree> pixels(
        stbi_loadf_from_memory(bytes.data(), int(bytes.size()), &width, &height, &channels, 3));
    if (!pixels) throw InputError(path + ": cannot decode Radiance HDR: " + stbi_failure_reason());
    if (width <= 0 || height <= 0) throw InputError(path + ": Radiance HDR image has no pixels");
    Image image(static_cast<std::uint32_t>(width), static_cast<std::uint32_t>(height));
    const float* rgb = pixels.get();
    for (glm::vec3& pixel : image.pixels) {
        pixel = glm::vec3(rgb[0], rgb[1], rgb[2]);
        rgb += 3;
    }
    return image;
}

Image readFloatImage(const std::string& path) {
    const std::string extension = detail::lowerCaseExtension(path);
    if (extension == ".hdr") return readRadianceHdr(path);
    if (extension == ".pfm") return readPfm(path);
    const std::string found = extension.empty() ? "no extension" : "'" + extension + "'";
    throw InputError(path + ": unsupported image format " + found +
                     " (expected a linear float image: .hdr or .pfm)");
}

} // namespace vkpt
