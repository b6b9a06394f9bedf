// image_io_test.cpp — image files as other tools read them: PFM bytes and byte orders, PNG
// sRGB values decoded back with stb_image, Radiance HDR within RGBE precision, the heat map,
// and the errors a user sees for a bad path or file.
#include "../support/decode_png.h"
#include "../support/test_directory.h"
#include "image/image_io.h"
#include "image/tone_map.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <unistd.h>

#include "common/errors.h"

namespace vkpt::image_io_test {
namespace {

namespace fs = std::filesystem;
using test::decodePng;

struct StbFree {
    void operator()(void* pixels) const { stbi_image_free(pixels); }
};

class ImageIo : public test::TestDirectory {
protected:
    ImageIo() : TestDirectory("vkpt_image_io") {}
};

std::vector<unsigned char> readBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void writeBytes(const std::string& path, const std::vector<unsigned char>& bytes) {
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

std::vector<unsigned char> textBytes(const std::string& text) {
    return {text.begin(), text.end()};
}

void appendFloat(std::vector<unsigned char>& bytes, float value, bool bigEndian) {
    const auto bits = std::bit_cast<std::uint32_t>(value);
    for (int i = 0; i < 4; ++i) {
        const int shift = bigEndian ? 24 - 8 * i : 8 * i;
        bytes.push_back((unsigned char)(bits >> shift));
    }
}

float floatAt(const std::vector<unsigned char>& bytes, std::size_t offset) {
    std::uint32_t bits = 0;
    for (int i = 0; i < 4; ++i)
        bits |= std::uint32_t(bytes[offset + std::size_t(i)]) << (8 * i);
    return std::bit_cast<float>(bits);
}

std::string errorOf(const std::function<void()>& action) {
    try {
        action();
    } catch (const InputError& error) {
        return error.what();
    }
    return "(no InputError)";
}

Image greyRow(const std::vector<float>& values) {
    Image image(std::uint32_t(values.size()), 1);
    for (std::uint32_t x = 0; x < image.width; ++x)
        image.at(x, 0) = glm::vec3(values[x]);
    return image;
}

// Distinct values everywhere, including ones a lossy path would change.
Image awkwardImage() {
    Image image(5, 3);
    const float special[] = {std::numeric_limits<float>::quiet_NaN(),
                             std::numeric_limits<float>::infinity(),
                             -std::numeric_limits<float>::infinity(),
                             -0.0f,
                             std::numeric_limits<float>::denorm_min(),
                             std::numeric_limits<float>::max(),
                             1.0f / 3.0f};
    for (std::uint32_t i = 0; i < image.pixels.size(); ++i)
        image.pixels[i] = glm::vec3(special[i % 7], float(i) * 0.1f, -float(i));
    return image;
}

TEST_F(ImageIo, PfmRoundTripIsBitExact) {
    const Image image = awkwardImage();
    writeImage(image, path("a.pfm"));
    const Image back = readPfm(path("a.pfm"));
    ASSERT_EQ(back.width, image.width);
    ASSERT_EQ(back.height, image.height);
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c)
            EXPECT_EQ(std::bit_cast<std::uint32_t>(back.pixels[i][c]),
                      std::bit_cast<std::uint32_t>(image.pixels[i][c]))
                << "pixel " << i << " channel " << c;
}

TEST_F(ImageIo, PfmStoresLittleEndianBottomRowFirst) {
    Image image(2, 2);
    image.at(0, 0) = {1, 2, 3};    // top left
    image.at(1, 0) = {4, 5, 6};    // top right
    image.at(0, 1) = {7, 8, 9};    // bottom left
    image.at(1, 1) = {10, 11, 12}; // bottom right
    writePfm(image, path("rows.pfm"));
    const std::vector<unsigned char> bytes = readBytes(path("rows.pfm"));
    const std::string header = "PF\n2 2\n-1.0\n";
    ASSERT_EQ(bytes.size(), header.size() + 4 * 3 * 4);
    EXPECT_EQ(std::string(bytes.begin(), bytes.begin() + std::ptrdiff_t(header.size())), header);
    const float expected[] = {7, 8, 9, 10, 11, 12, 1, 2, 3, 4, 5, 6};
    for (std::size_t i = 0; i < 12; ++i)
        EXPECT_EQ(floatAt(bytes, header.size() + 4 * i), expected[i]) << "float " << i;
}

TEST_F(ImageIo, ReadsBigEndianPfm) {
    std::vector<unsigned char> bytes = textBytes("PF\n2 1\n1.0\n");
    for (float v : {0.5f, -1.25f, 3e20f, 7.0f, 8.0f, 9.0f})
        appendFloat(bytes, v, true);
    writeBytes(path("big.pfm"), bytes);
    const Image image = readPfm(path("big.pfm"));
    ASSERT_EQ(image.width, 2u);
    ASSERT_EQ(image.height, 1u);
    EXPECT_EQ(image.at(0, 0), glm::vec3(0.5f, -1.25f, 3e20f));
    EXPECT_EQ(image.at(1, 0), glm::vec3(7.0f, 8.0f, 9.0f));
}

TEST_F(ImageIo, ReadsGreyscalePfmAsRgbWithRowsFlipped) {
    // The scale's magnitude is not a byte order hint and is not applied.
    std::vector<unsigned char> bytes = textBytes("Pf\n2 2\n-4.0\n");
    for (float v : {1.0f, 2.0f, 3.0f, 4.0f})
        appendFloat(bytes, v, false);
    writeBytes(path("grey.pfm"), bytes);
    const Image image = readPfm(path("grey.pfm"));
    EXPECT_EQ(image.at(0, 1), glm::vec3(1.0f)); // file row 0 is the bottom row
    EXPECT_EQ(image.at(1, 1), glm::vec3(2.0f));
    EXPECT_EQ(image.at(0, 0), glm::vec3(3.0f));
    EXPECT_EQ(image.at(1, 0), glm::vec3(4.0f));
}

TEST_F(ImageIo, PfmHeaderEndsAfterOneWhitespaceByte) {
    // The first float's first byte is 0x20, a space: it must not be taken as header padding.
    std::vector<unsigned char> bytes = textBytes("PF 1 1 -1 ");
    const float first = std::bit_cast<float>(std::uint32_t(0x3F800020)); // just above 1
    for (float v : {first, 2.0f, 3.0f})
        appendFloat(bytes, v, false);
    writeBytes(path("space.pfm"), bytes);
    EXPECT_EQ(readPfm(path("space.pfm")).at(0, 0), glm::vec3(first, 2.0f, 3.0f));
}

TEST_F(ImageIo, MalformedPfmNamesThePathAndTheProblem) {
    const auto readError = [&](const std::string& name, const std::vector<unsigned char>& bytes) {
        writeBytes(path(name), bytes);
        return errorOf([&] { readPfm(path(name)); });
    };
    EXPECT_EQ(readError("magic.pfm", textBytes("P6\n1 1\n255\n...")),
              path("magic.pfm") + ": not a PFM file: starts with 'P6', expected 'PF' or 'Pf'");
    EXPECT_EQ(readError("width.pfm", textBytes("PF\n0 1\n-1\n")),
              path("width.pfm") + ": bad PFM width '0' (expected a positive integer)");
    EXPECT_EQ(readError("height.pfm", textBytes("PF\n1 x\n-1\n")),
              path("height.pfm") + ": bad PFM height 'x' (expected a positive integer)");
    EXPECT_EQ(readError("scale.pfm", textBytes("PF\n1 1\n0.0\n")),
              path("scale.pfm") +
                  ": bad PFM scale '0.0' (expected a non-zero number whose sign gives the byte "
                  "order)");
    EXPECT_EQ(readError("header.pfm", textBytes("PF\n1 1\n")),
              path("header.pfm") + ": truncated PFM header: no scale");
    EXPECT_EQ(readError("empty.pfm", {}), path("empty.pfm") + ": truncated PFM header: no type");
    EXPECT_EQ(readError("end.pfm", textBytes("PF\n1 1\n-1")),
              path("end.pfm") + ": truncated after the header");
    std::vector<unsigned char> shortData = textBytes("PF\n2 2\n-1\n");
    shortData.resize(shortData.size() + 47);
    EXPECT_EQ(readError("short.pfm", shortData),
              path("short.pfm") +
                  ": truncated PFM: 2x2 RGB needs 4 x 12 bytes of pixel data, the file has 47");
    EXPECT_EQ(readError("huge.pfm", textBytes("PF\n4294967295 4294967295\n-1\n")),
              path("huge.pfm") +
                  ": truncated PFM: 4294967295x4294967295 RGB needs 18446744065119617025 x 12 "
                  "bytes of pixel data, the file has 0");
}

TEST_F(ImageIo, MissingPfmNamesThePath) {
    EXPECT_EQ(errorOf([&] { readPfm(path("absent.pfm")); }),
              path("absent.pfm") + ": cannot read: No such file or directory");
}

TEST_F(ImageIo, PngEncodesSrgbOfKnownValues) {
    // 0.0031308 is where the linear segment meets the power curve: 12.92 × 0.0031308 = 0.04045,
    // i.e. 10.3 of 255. 0.5 encodes to 0.7354 (187.5 → 188). 2 clamps to white.
    writeImage(greyRow({0.0f, 0.0031308f, 0.5f, 1.0f, 2.0f}), path("srgb.png"), 0.0f,
               ToneMap::Clamp);
    int width = 0, height = 0;
    const std::vector<std::uint8_t> rgb = decodePng(path("srgb.png"), width, height);
    ASSERT_EQ(width, 5);
    ASSERT_EQ(height, 1);
    const std::uint8_t expected[] = {0, 10, 188, 255, 255};
    for (std::size_t x = 0; x < 5; ++x)
        for (std::size_t c = 0; c < 3; ++c)
            EXPECT_EQ(rgb[3 * x + c], expected[x]) << "x = " << x;
}

TEST_F(ImageIo, PngAppliesExposureAndWritesNonFiniteAsBlack) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    writeImage(greyRow({0.25f, 0.125f, nan, inf, -1.0f}), path("exposure.png"), 1.0f,
               ToneMap::Clamp);
    int width = 0, height = 0;
    const std::vector<std::uint8_t> rgb = decodePng(path("exposure.png"), width, height);
    ASSERT_EQ(rgb.size(), 15u);
    EXPECT_EQ(rgb[0], 188); // 0.25 × 2 = 0.5
    EXPECT_EQ(rgb[3], std::lround(linearToSrgb(0.25f) * 255.0f));
    EXPECT_EQ(rgb[6], 0);  // NaN
    EXPECT_EQ(rgb[9], 0);  // +infinity
    EXPECT_EQ(rgb[12], 0); // negative clamps to black
}

// The default tone map, PBR Neutral, after the exposure: 0.5 × 2 = 1 lies above its start of
// compression (0.76 after the 0.04 toe) and is compressed, 0.25 × 2 = 0.5 passes less the toe.
TEST_F(ImageIo, PngAppliesExposureBeforeTheDefaultToneMap) {
    writeImage(greyRow({0.5f, 0.25f, 0.0f}), path("neutral.png"), 1.0f);
    int width = 0, height = 0;
    const std::vector<std::uint8_t> rgb = decodePng(path("neutral.png"), width, height);
    ASSERT_EQ(rgb.size(), 9u);
    EXPECT_EQ(rgb[0], std::lround(linearToSrgb(pbrNeutralToneMap(glm::vec3(1.0f)).x) * 255.0f));
    EXPECT_LT(rgb[0], 255);
    EXPECT_EQ(rgb[3], std::lround(linearToSrgb(0.5f - 0.04f) * 255.0f));
    EXPECT_EQ(rgb[6], 0);
}

TEST_F(ImageIo, FloatFormatsIgnoreTheToneMap) {
    const Image image = greyRow({0.5f, 3.0f, 100.0f});
    writeImage(image, path("linear.pfm"), 2.0f, ToneMap::PbrNeutral);
    const Image back = readPfm(path("linear.pfm"));
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        EXPECT_EQ(back.pixels[i], image.pixels[i]) << "pixel " << i;
}

TEST_F(ImageIo, PngKeepsRowsTopFirstAndChannelsInOrder) {
    Image image(1, 2);
    image.at(0, 0) = {1, 0, 0};
    image.at(0, 1) = {0, 0, 1};
    writeImage(image, path("order.PNG"), 0.0f, ToneMap::Clamp); // extensions: any case
    int width = 0, height = 0;
    const std::vector<std::uint8_t> rgb = decodePng(path("order.PNG"), width, height);
    EXPECT_EQ(rgb, (std::vector<std::uint8_t>{255, 0, 0, 0, 0, 255}));
}

TEST(CountNonFinitePixels, CountsPixelsWithAnyNanOrInfiniteComponent) {
    EXPECT_EQ(countNonFinitePixels(awkwardImage()), 7u); // pixels 0-2, 7-9 and 14
    EXPECT_EQ(countNonFinitePixels(Image(4, 4)), 0u);
}

TEST(LinearToSrgb, FollowsIec61966) {
    EXPECT_EQ(linearToSrgb(0.0f), 0.0f);
    EXPECT_EQ(linearToSrgb(1.0f), 1.0f);
    EXPECT_NEAR(linearToSrgb(0.0031308f), 0.0404499f, 1e-7f);
    // Continuous where the segments meet: a step of 2e-7 across it moves by slope 12.92 only.
    EXPECT_NEAR(linearToSrgb(0.0031309f) - linearToSrgb(0.0031307f), 12.92f * 2e-7f, 1e-7f);
    EXPECT_NEAR(linearToSrgb(0.18f), 0.461356f, 1e-6f);
    EXPECT_EQ(linearToSrgb(std::numeric_limits<float>::quiet_NaN()), 0.0f);
    EXPECT_EQ(linearToSrgb(-3.0f), 0.0f);
    EXPECT_EQ(linearToSrgb(7.0f), 1.0f);
}

TEST_F(ImageIo, HdrHasARadianceHeaderAndRoundTripsWithinRgbePrecision) {
    Image image(16, 3); // wide enough for stb's run-length encoded scanlines
    for (std::uint32_t y = 0; y < image.height; ++y)
        for (std::uint32_t x = 0; x < image.width; ++x)
            image.at(x, y) =
                glm::vec3(0.01f * float(x + 1), 3.0f * float(y), 1000.0f / float(x + 1));
    writeImage(image, path("a.hdr"));

    const std::vector<unsigned char> bytes = readBytes(path("a.hdr"));
    const std::string text(
        bytes.begin(), bytes.begin() + std::ptrdiff_t(std::min<std::size_t>(bytes.size(), 200)));
    EXPECT_EQ(text.rfind("#?RADIANCE\n", 0), 0u) << text;
    EXPECT_NE(text.find("\nFORMAT=32-bit_rle_rgbe\n"), std::string::npos) << text;
    EXPECT_NE(text.find("\n\n-Y 3 +X 16\n"), std::string::npos) << text; // blank line, size

    int width = 0, height = 0, channels = 0;
    std::unique_ptr<float, StbFree> pixels(
        stbi_loadf(path("a.hdr").c_str(), &width, &height, &channels, 3));
    ASSERT_TRUE(pixels) << stbi_failure_reason();
    ASSERT_EQ(width, 16);
    ASSERT_EQ(height, 3);
    for (std::uint32_t i = 0; i < image.pixels.size(); ++i) {
        const glm::vec3 original = image.pixels[i];
        // Three 8-bit mantissas share the exponent of the largest component, which is kept to
        // 1 part in 128 at worst (stb truncates rather than rounds).
        const float tolerance = std::max({original.x, original.y, original.z}) / 128.0f;
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(pixels.get()[3 * i + std::uint32_t(c)], original[c], tolerance)
                << "pixel " << i << " channel " << c;
    }
}

TEST_F(ImageIo, HdrWritesWhatRgbeCannotHoldAsZero) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    Image image(3, 1);
    image.at(0, 0) = {nan, 1.0f, 2.0f};
    image.at(1, 0) = {-1.0f, 0.5f, 0.25f};
    image.at(2, 0) = {std::numeric_limits<float>::infinity(), 0.0f, 0.0f};
    writeImage(image, path("odd.hdr"));
    int width = 0, height = 0, channels = 0;
    std::unique_ptr<float, StbFree> pixels(
        stbi_loadf(path("odd.hdr").c_str(), &width, &height, &channels, 3));
    ASSERT_TRUE(pixels);
    const float* p = pixels.get();
    EXPECT_EQ(p[0], 0.0f);
    EXPECT_NEAR(p[1], 1.0f, 1.0f / 64.0f);
    EXPECT_NEAR(p[2], 2.0f, 1.0f / 64.0f);
    EXPECT_EQ(p[3], 0.0f);
    EXPECT_NEAR(p[4], 0.5f, 1.0f / 128.0f);
    EXPECT_EQ(p[6], 0.0f);
}

TEST_F(ImageIo, UnknownExtensionIsNamed) {
    const Image image(1, 1);
    EXPECT_EQ(errorOf([&] { writeImage(image, path("x.xyz")); }),
              path("x.xyz") + ": unknown image extension '.xyz' (use .png, .pfm or .hdr)");
    EXPECT_EQ(errorOf([&] { writeImage(image, path("noextension")); }),
              path("noextension") + ": unknown image extension '' (use .png, .pfm or .hdr)");
}

TEST_F(ImageIo, WriteFailureNamesThePath) {
    const Image image(2, 2);
    for (const char* name : {"missing/x.png", "missing/x.pfm", "missing/x.hdr"})
        EXPECT_EQ(errorOf([&] { writeImage(image, path(name)); }),
                  path(name) + ": cannot write: No such file or directory");
}

TEST(HeatMapPath, AddsRateSuffixAndPngExtension) {
    EXPECT_EQ(heatMapPathFor("out/cornell.png"), "out/cornell_rate.png");
    EXPECT_EQ(heatMapPathFor("dir/x.png"), "dir/x_rate.png");
    EXPECT_EQ(heatMapPathFor("x.pfm"), "x_rate.png");
    EXPECT_EQ(heatMapPathFor("renders/v1.2/box.hdr"), "renders/v1.2/box_rate.png");
    EXPECT_EQ(heatMapPathFor("/abs/plain"), "/abs/plain_rate.png");
}

TEST(Viridis, EndsAtThePublishedColoursAndBrightensMonotonically) {
    EXPECT_EQ(viridisColour(0.0f), glm::vec3(0.267004f, 0.004874f, 0.329415f));
    EXPECT_EQ(viridisColour(1.0f), glm::vec3(0.993248f, 0.906157f, 0.143936f));
    EXPECT_EQ(viridisColour(128.0f / 255.0f), glm::vec3(0.127568f, 0.566949f, 0.550556f));
    EXPECT_EQ(viridisColour(-1.0f), viridisColour(0.0f));
    EXPECT_EQ(viridisColour(2.0f), viridisColour(1.0f));
    float previous = -1.0f;
    for (int i = 0; i <= 100; ++i) {
        const glm::vec3 c = viridisColour(float(i) / 100.0f);
        const float luma = 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; // display-space proxy
        EXPECT_GT(luma, previous) << "t = " << float(i) / 100.0f;
        previous = luma;
    }
}

TEST_F(ImageIo, HeatMapIsBlackForNoSamplesAndBrightestAtTheMaximum) {
    const std::vector<std::uint32_t> counts = {0, 1, 50, 100, 100, 25};
    writeSampleCountHeatMap(counts, 3, 2, path("x_rate.png"));
    int width = 0, height = 0;
    const std::vector<std::uint8_t> rgb = decodePng(path("x_rate.png"), width, height);
    ASSERT_EQ(width, 3);
    ASSERT_EQ(height, 2);
    const auto pixel = [&](std::size_t i) {
        return std::vector<int>{rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2]};
    };
    EXPECT_EQ(pixel(0), (std::vector<int>{0, 0, 0}));
    EXPECT_EQ(pixel(3), (std::vector<int>{253, 231, 37})); // viridis(1) = #FDE725
    EXPECT_EQ(pixel(4), pixel(3));
    // t = 0.01 is 16 % of the way from #440154 (entry 0) to entry 16: (69, 5, 88).
    EXPECT_EQ(pixel(1), (std::vector<int>{69, 5, 88}));
    EXPECT_NE(pixel(1), pixel(0));
}

TEST_F(ImageIo, HeatMapOfAnUnsampledImageIsBlackAndMustBeAPng) {
    writeSampleCountHeatMap(std::vector<std::uint32_t>(4, 0), 2, 2, path("none.png"));
    int width = 0, height = 0;
    EXPECT_EQ(decodePng(path("none.png"), width, height), std::vector<std::uint8_t>(12, 0));
    EXPECT_EQ(errorOf([&] { writeSampleCountHeatMap({}, 0, 0, path("rate.pfm")); }),
              path("rate.pfm") + ": the sample-count heat map is a PNG; give it a .png name");
}

} // namespace
} // namespace vkpt::image_io_test
