// pfm_io.cpp — Portable Float Map, the lossless float format in which renders are kept and
// compared: written little-endian RGB, read in either byte order and as RGB or greyscale.
#include <bit>
#include <charconv>
#include <cmath>
#include <string_view>
#include <vector>

#include "common/errors.h"
#include "image/image_file.h"
#include "image/image_io.h"

namespace vkpt {

namespace {

// The PFM header is three whitespace-separated lines of text: "PF" (RGB) or "Pf" (grey),
// "<width> <height>", and a scale whose sign gives the byte order (negative: little-endian).
// Exactly one whitespace byte follows the scale; the binary rows start right after it, bottom
// row first.
struct PfmHeader {
    int channels = 3;
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    bool littleEndian = true;
    std::size_t dataOffset = 0;
};

bool isPfmSpace(unsigned char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}

// Reads the header a token at a time and names the path and the token in every complaint.
class PfmHeaderParser {
public:
    PfmHeaderParser(std::span<const unsigned char> bytes, const std::string& path)
        : bytes_(bytes), path_(path) {}

    PfmHeader parse() {
        PfmHeader header;
        header.channels = parseMagic(nextToken("type"));
        header.width = parseDimension(nextToken("width"), "width");
        header.height = parseDimension(nextToken("height"), "height");
        header.littleEndian = parseScale(nextToken("scale")) < 0.0;
        if (pos_ >= bytes_.size()) fail("truncated after the header");
        header.dataOffset = pos_ + 1; // the single whitespace byte that ends the header
        return header;
    }

private:
    [[noreturn]] void fail(const std::string& problem) const {
        throw InputError(path_ + ": " + problem);
    }

    std::string_view nextToken(const char* what) {
        while (pos_ < bytes_.size() && isPfmSpace(bytes_[pos_]))
            ++pos_;
        const std::size_t start = pos_;
        while (pos_ < bytes_.size() && !isPfmSpace(bytes_[pos_]))
            ++pos_;
        if (pos_ == start) fail(std::string("truncated PFM header: no ") + what);
        return {reinterpret_cast<const char*>(bytes_.data()) + start, pos_ - start};
    }

    int parseMagic(std::string_view token) const {
        if (token == "PF") return 3;
        if (token == "Pf") return 1;
        fail("not a PFM file: starts with '" + printable(token) + "', expected 'PF' or 'Pf'");
    }

    std::uint32_t parseDimension(std::string_view token, const char* what) const {
        std::uint32_t value = 0;
        const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
        if (error != std::errc() || end != token.data() + token.size() || value == 0)
            fail(std::string("bad PFM ") + what + " '" + printable(token) +
                 "' (expected a positive integer)");
        return value;
    }

    double parseScale(std::string_view token) const {
        double value = 0.0;
        const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
        if (error != std::errc() || end != token.data() + token.size() || !std::isfinite(value) ||
            value == 0.0)
            fail("bad PFM scale '" + printable(token) +
                 "' (expected a non-zero number whose sign gives the byte order)");
        return value;
    }

    // Binary junk in an error message would garble the terminal; a long token is cut short.
    static std::string printable(std::string_view token) {
        constexpr std::size_t kMaxShown = 24;
        std::string text;
        for (char c : token.substr(0, kMaxShown))
            text += (c >= 0x20 && c < 0x7F) ? c : '?';
        if (token.size() > kMaxShown) text += "...";
        return text;
    }

    std::span<const unsigned char> bytes_;
    const std::string& path_;
    std::size_t pos_ = 0;
};

// Byte order is handled by assembling the 32-bit pattern explicitly, so the code does not
// depend on the host's own order.
float decodeFloat(const unsigned char* p, bool littleEndian) {
    const std::uint32_t b0 = p[0], b1 = p[1], b2 = p[2], b3 = p[3];
    const std::uint32_t bits =
        littleEndian ? b0 | b1 << 8 | b2 << 16 | b3 << 24 : b3 | b2 << 8 | b1 << 16 | b0 << 24;
    return std::bit_cast<float>(bits);
}

void appendLittleEndian(std::vector<unsigned char>& bytes, float value) {
    const auto bits = std::bit_cast<std::uint32_t>(value);
    for (int shift = 0; shift < 32; shift += 8)
        bytes.push_back((unsigned char)(bits >> shift));
}

void checkPixelDataSize(const PfmHeader& header, std::size_t available, const std::string& path) {
    const std::size_t bytesPerPixel = std::size_t(header.channels) * 4;
    const std::uint64_t pixels = std::uint64_t(header.width) * header.height;
    // Compared by division first: width * height * 12 can overflow 64 bits for a hostile header.
    if (pixels > available / bytesPerPixel || pixels * bytesPerPixel > available)
        throw InputError(path + ": truncated PFM: " + std::to_string(header.width) + "x" +
                         std::to_string(header.height) + (header.channels == 3 ? " RGB" : " grey") +
                         " needs " + std::to_string(pixels) + " x " +
                         std::to_string(bytesPerPixel) + " bytes of pixel data, the file has " +
                         std::to_string(available));
}

// Greyscale ("Pf") is expanded to equal RGB; file row 0 is the bottom row of our image.
Image decodePixels(const PfmHeader& header, const unsigned char* data) {
    Image image(header.width, header.height);
    const std::size_t stride = std::size_t(header.channels) * 4;
    for (std::uint32_t fileRow = 0; fileRow < header.height; ++fileRow) {
        const std::uint32_t y = header.height - 1 - fileRow;
        for (std::uint32_t x = 0; x < header.width; ++x) {
            const unsigned char* p = data + (std::size_t(fileRow) * header.width + x) * stride;
            glm::vec3& pixel = image.at(x, y);
            for (int c = 0; c < 3; ++c)
                pixel[c] = decodeFloat(p + (header.channels == 3 ? 4 * c : 0), header.littleEndian);
        }
    }
    return image;
}

} // namespace

void writePfm(const Image& image, const std::string& path) {
    VKPT_ASSERT(image.pixels.size() == std::size_t(image.width) * image.height,
                "image pixel count != width * height");
    const std::string header =
        "PF\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n-1.0\n";
    std::vector<unsigned char> bytes(header.begin(), header.end());
    bytes.reserve(bytes.size() + image.pixels.size() * 12);
    // Non-finite values are kept as they are: the float file is the faithful record.
    for (std::uint32_t fileRow = 0; fileRow < image.height; ++fileRow)
        for (std::uint32_t x = 0; x < image.width; ++x)
            for (int c = 0; c < 3; ++c)
                appendLittleEndian(bytes, image.at(x, image.height - 1 - fileRow)[c]);
    detail::writeFileBytes(path, bytes);
}

// The scale's magnitude (a brightness hint some tools apply) is ignored: the values are
// radiance as rendered. Bytes after the last row are ignored too, as other readers do.
Image readPfm(const std::string& path) {
    const std::vector<unsigned char> bytes = detail::readFileBytes(path);
    const PfmHeader header = PfmHeaderParser(bytes, path).parse();
    checkPixelDataSize(header, bytes.size() - header.dataOffset, path);
    return decodePixels(header, bytes.data() + header.dataOffset);
}

} // namespace vkpt
