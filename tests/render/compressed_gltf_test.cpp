// compressed_gltf_test.cpp — the compressed forms of one textured scene (Draco, meshopt,
// KHR_mesh_quantization, EXT_texture_webp), written in the test by the libraries' own encoders
// (tests/support/compressed_gltf.h), load to the geometry and texels of the uncompressed file
// within the quantisation bound of each coding, and render like it.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <unistd.h>

#include "compressed_gltf.h"
#include "image/image_compare.h"
#include "prepare/prepared_scene.h"
#include "reference_render.h"
#include "scene/gltf_loader.h"
#include "scratch_directory.h"

namespace vkpt::compressed_gltf_test {
namespace {

using test::GeometryCoding;
using test::ImageCoding;

// In the process's own scratch folder: ctest runs the cases of this file as parallel processes.
std::string writeScene(const std::string& name, GeometryCoding geometry, ImageCoding image) {
    const std::string path = test::scratchPath("compressed_" + name);
    test::writeTestScene(path, geometry, image);
    return path;
}

Scene load(const std::string& path) {
    LoadOptions options;
    options.warnUnsupportedExtensions = false;
    return loadGltfScene(path, options);
}

const Scene& floatScene() {
    static const Scene scene =
        load(writeScene("floats.glb", GeometryCoding::Floats, ImageCoding::Png));
    return scene;
}

// One triangle corner as the loader stores it.
struct Corner {
    glm::vec3 position;
    glm::vec3 normal;
    glm::vec2 texcoord;
};

Corner corner(const Scene& scene, std::size_t triangle, std::size_t k) {
    const std::size_t i = 3 * triangle + k;
    return {scene.positions[i], scene.normals[i], scene.texcoords[i]};
}

// The largest per-component differences between matched corners, over the whole scene.
struct Differences {
    float position = 0.0f;
    float normal = 0.0f;
    float texcoord = 0.0f;
};

float maxAbs(const glm::vec3& v) {
    return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
}

void accumulate(Differences& d, const Corner& a, const Corner& b) {
    d.position = std::max(d.position, maxAbs(a.position - b.position));
    d.normal = std::max(d.normal, maxAbs(a.normal - b.normal));
    d.texcoord = std::max(d.texcoord, std::max(std::abs(a.texcoord.x - b.texcoord.x),
                                               std::abs(a.texcoord.y - b.texcoord.y)));
}

// Triangle t of `decoded` against triangle u of `original`, its corners rotated by r (a
// rotation keeps the winding, so the front face must match too).
float positionDistance(const Scene& decoded, std::size_t t, const Scene& original, std::size_t u,
                       std::size_t r) {
    float worst = 0.0f;
    for (std::size_t k = 0; k < 3; ++k)
        worst = std::max(
            worst, maxAbs(decoded.positions[3 * t + k] - original.positions[3 * u + (k + r) % 3]));
    return worst;
}

// Draco may reorder points and faces: each decoded triangle is matched with the original
// triangle (and corner rotation) nearest to it, and every original must be matched once.
Differences matchTriangles(const Scene& decoded, const Scene& original) {
    EXPECT_EQ(decoded.triangleCount(), original.triangleCount());
    std::vector<int> matchedBy(original.triangleCount(), -1);
    Differences d;
    for (std::size_t t = 0; t < decoded.triangleCount(); ++t) {
        float best = std::numeric_limits<float>::infinity();
        std::size_t bestU = 0, bestR = 0;
        for (std::size_t u = 0; u < original.triangleCount(); ++u)
            for (std::size_t r = 0; r < 3; ++r) {
                const float distance = positionDistance(decoded, t, original, u, r);
                if (distance < best) {
                    best = distance;
                    bestU = u;
                    bestR = r;
                }
            }
        EXPECT_EQ(matchedBy[bestU], -1) << "original triangle " << bestU << " matched twice";
        matchedBy[bestU] = int(t);
        for (std::size_t k = 0; k < 3; ++k)
            accumulate(d, corner(decoded, t, k), corner(original, bestU, (k + bestR) % 3));
    }
    return d;
}

// Quantized files keep the vertex and triangle order and every corner in place.
Differences compareInOrder(const Scene& decoded, const Scene& original) {
    EXPECT_EQ(decoded.triangleCount(), original.triangleCount());
    Differences d;
    for (std::size_t t = 0; t < std::min(decoded.triangleCount(), original.triangleCount()); ++t)
        for (std::size_t k = 0; k < 3; ++k)
            accumulate(d, corner(decoded, t, k), corner(original, t, k));
    return d;
}

// Half a quantisation step of `bits` over `extent`, plus float rounding in the loader's
// transform and in the decoder's dequantisation.
float halfStep(float extent, int bits) {
    return 0.5f * extent / float((1 << bits) - 1) + 1e-6f;
}

// Octahedral normals (Cigolle et al., "A Survey of Efficient Representations for Independent
// Unit Vectors", JCGT 2014): the square coordinates (s, t) are rounded by at most δ = step/2
// each, which moves the unnormalised vector (s, t, 1 − |s| − |t|) by at most δ·√6; that vector
// has L1 length 1, so L2 length ≥ 1/√3, and normalising stretches a displacement by at most
// √3. A component is therefore off by at most √18·δ.
float octahedralBound(float step) {
    return std::sqrt(18.0f) * 0.5f * step;
}

TEST(CompressedGltf, DracoGeometryIsTheOriginalWithinItsQuantisation) {
    const Scene draco = load(writeScene("draco.glb", GeometryCoding::Draco, ImageCoding::Png));
    const Differences d = matchTriangles(draco, floatScene());
    // Positions: 14 bits over the bounding cube of side 2; texture coordinates: 12 bits over
    // [0, 1]. Normals: see octahedralBound.
    EXPECT_LE(d.position, halfStep(2.0f, test::kDracoPositionBits));
    EXPECT_LE(d.texcoord, halfStep(1.0f, test::kDracoTexcoordBits));
    // Draco's octahedron grid has 2^bits − 1 points per side over [−1, 1] (OctahedronToolBox).
    EXPECT_LE(d.normal, octahedralBound(2.0f / float((1 << test::kDracoNormalBits) - 2)));
    RecordProperty("maxPositionError", std::to_string(d.position));
    RecordProperty("maxNormalError", std::to_string(d.normal));
    RecordProperty("maxTexcoordError", std::to_string(d.texcoord));
}

TEST(CompressedGltf, MeshoptGeometryIsTheOriginalWithinItsFilters) {
    const Scene meshopt =
        load(writeScene("meshopt.glb", GeometryCoding::Meshopt, ImageCoding::Png));
    // The index codec may rotate a triangle's corners (keeping its winding), so triangles are
    // matched as for Draco.
    const Differences d = matchTriangles(meshopt, floatScene());
    // The vertex and index codecs are lossless: positions are bit for bit the original.
    EXPECT_EQ(d.position, 0.0f);
    // OCTAHEDRAL with 12-bit components: the square's step is 1/(2^11 − 1) (meshopt scales
    // [−1, 1] to ±(2^(bits−1) − 1)); then the rounding of the 16-bit normalized SHORT the
    // filter writes.
    EXPECT_LE(d.normal, octahedralBound(1.0f / float((1 << (test::kMeshoptNormalBits - 1)) - 1)) +
                            1.0f / 32767.0f);
    // EXPONENTIAL with a 15-bit mantissa shared by u and v (|u|, |v| ≤ 1): the shared exponent
    // makes the step 2^−(15−1) of the larger component, rounding to the nearest is half that.
    EXPECT_LE(d.texcoord, std::ldexp(1.0f, -(test::kMeshoptTexcoordMantissaBits - 1)));
}

TEST(CompressedGltf, QuantizedGeometryIsTheOriginalWithinItsIntegerSteps) {
    const Scene quantized =
        load(writeScene("quantized.glb", GeometryCoding::Quantized, ImageCoding::Png));
    const Differences d = compareInOrder(quantized, floatScene());
    // Positions: normalized SHORT of p/h, h = 1 (the node's scale undoes it): half a step of
    // 1/32767. Texture coordinates likewise. Normals: normalized BYTE, half a step of 1/127
    // per component, then renormalised by the loader, which at most doubles the error.
    EXPECT_LE(d.position, 0.5f / 32767.0f + 1e-6f);
    EXPECT_LE(d.texcoord, 0.5f / 32767.0f + 1e-6f);
    EXPECT_LE(d.normal, 2.0f * 0.5f / 127.0f);
}

void expectSameTexels(const Scene& a, const Scene& b) {
    ASSERT_EQ(a.images.size(), 1u);
    ASSERT_EQ(b.images.size(), 1u);
    EXPECT_EQ(a.images[0].width, b.images[0].width);
    EXPECT_EQ(a.images[0].height, b.images[0].height);
    EXPECT_EQ(a.images[0].texels, b.images[0].texels);
}

TEST(CompressedGltf, LosslessWebpTextureEqualsThePngTexelForTexel) {
    const Scene webp = load(writeScene("webp.glb", GeometryCoding::Floats, ImageCoding::Webp));
    expectSameTexels(webp, floatScene());
}

TEST(CompressedGltf, WebpSourceIsPreferredToTheCorePngFallback) {
    // The fallback PNG is black: taking it would change every texel.
    const Scene webp = load(
        writeScene("webp_fallback.glb", GeometryCoding::Floats, ImageCoding::WebpOverPngFallback));
    expectSameTexels(webp, floatScene());
}

class CompressedGltfRender : public testing::TestWithParam<GeometryCoding> {};

test::LoadedTestScene prepared(const Scene& scene) {
    test::LoadedTestScene loaded{scene, {}};
    loaded.prepared = prepareScene(loaded.scene, {});
    return loaded;
}

// The compressed scene's image and the uncompressed one's, at different seeds, are equal in
// distribution: Welch's per-pixel test at a family-wise false-alarm rate of 1 %
// (image_compare.h). The geometric differences above (at most ~1e-3 of the sphere's size in
// any normal) are far below what 64 samples per pixel can resolve.
TEST_P(CompressedGltfRender, ImageIsStatisticallyTheUncompressedOne) {
    const Scene compressed = load(writeScene("render.glb", GetParam(), ImageCoding::Webp));
    RenderSettings settings = test::testSettings(32, 64);
    settings.seed = 7;
    const RenderOutput original = test::renderTestScene(prepared(floatScene()), settings);
    settings.seed = 8;
    const RenderOutput decoded = test::renderTestScene(prepared(compressed), settings);
    // A lit sphere, not an empty frame in which any two images agree.
    EXPECT_GT(meanLuminance(original).mean, 0.02);
    const ZTestResult z = zTestPerPixel(original, decoded, 0.01);
    EXPECT_TRUE(z.passed) << z.summary;
}

INSTANTIATE_TEST_SUITE_P(Codings, CompressedGltfRender,
                         testing::Values(GeometryCoding::Draco, GeometryCoding::Meshopt,
                                         GeometryCoding::Quantized),
                         [](const testing::TestParamInfo<GeometryCoding>& test) {
                             switch (test.param) {
                             case GeometryCoding::Draco:
                                 return std::string("Draco");
                             case GeometryCoding::Meshopt:
                                 return std::string("Meshopt");
                             default:
                                 return std::string("Quantized");
                             }
                         });

} // namespace
} // namespace vkpt::compressed_gltf_test
