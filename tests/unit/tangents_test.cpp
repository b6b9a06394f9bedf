// tangents_test.cpp — generated tangent frames (scene/tangents.h): a UV-mapped quad's known
// tangent, mirrored texture coordinates flipping the handedness, agreement with a smooth mesh's
// analytic TANGENT, and valid frames where texture coordinates are degenerate.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "scene/tangents.h"

namespace vkpt::tangents_test {
namespace {

struct Soup {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<glm::vec2> texcoords;

    void corner(const glm::vec3& p, const glm::vec3& n, const glm::vec2& t) {
        positions.push_back(p);
        normals.push_back(n);
        texcoords.push_back(t);
    }
    std::vector<glm::vec4> tangents() const {
        return generateTangents(positions, normals, texcoords);
    }
};

// A unit square in the plane z = 0 facing +Z, texture coordinate u along +X and glTF's v
// (down the image) along −Y, as an exporter writes an unmirrored quad; `mirror` flips u.
Soup quad(bool mirror) {
    const glm::vec3 n(0, 0, 1);
    const glm::vec3 p[4] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    Soup soup;
    for (int i : {0, 1, 2, 0, 2, 3}) {
        const float u = mirror ? 1.0f - p[i].x : p[i].x;
        soup.corner(p[i], n, {u, 1.0f - p[i].y});
    }
    return soup;
}

void expectOrthonormalFrame(const glm::vec4& t, const glm::vec3& n, const char* what) {
    EXPECT_NEAR(glm::length(glm::vec3(t)), 1.0f, 1e-5f) << what;
    EXPECT_NEAR(glm::dot(glm::vec3(t), n), 0.0f, 1e-5f) << what;
    EXPECT_TRUE(t.w == 1.0f || t.w == -1.0f) << what << ": w = " << t.w;
}

TEST(Tangents, QuadTangentRunsAlongUWithPositiveHandedness) {
    for (const glm::vec4& t : quad(false).tangents()) {
        EXPECT_NEAR(t.x, 1.0f, 1e-6f);
        EXPECT_NEAR(t.y, 0.0f, 1e-6f);
        EXPECT_NEAR(t.z, 0.0f, 1e-6f);
        // bitangent w·cross(n, t) = +Y: the texture's up, towards smaller v.
        EXPECT_EQ(t.w, 1.0f);
    }
}

TEST(Tangents, MirroredTextureCoordinatesFlipTheHandedness) {
    for (const glm::vec4& t : quad(true).tangents()) {
        EXPECT_NEAR(t.x, -1.0f, 1e-6f); // u now grows along −X
        EXPECT_NEAR(t.y, 0.0f, 1e-6f);
        EXPECT_EQ(t.w, -1.0f); // w·cross(n, t) = w·(−Y) must still point up the texture (+Y)
    }
}

// Two quads sharing an edge, the second with mirrored u (a symmetric model's seam): the shared
// vertices have equal position, normal and texture coordinate, yet each side keeps its own frame.
TEST(Tangents, AMirroredSeamKeepsBothFrames) {
    Soup soup = quad(false);
    const Soup mirrored = quad(true);
    for (std::size_t i = 0; i < mirrored.positions.size(); ++i) {
        // The quad reflected to x in [1, 2] with u = 2 − x: u = 1 on the shared edge x = 1.
        const glm::vec3 p = mirrored.positions[i];
        soup.corner({2.0f - p.x, p.y, p.z}, mirrored.normals[i], {p.x, mirrored.texcoords[i].y});
    }
    const std::vector<glm::vec4> t = soup.tangents();
    for (std::size_t c = 0; c < 6; ++c) {
        EXPECT_NEAR(t[c].x, 1.0f, 1e-6f) << c;
        EXPECT_EQ(t[c].w, 1.0f) << c;
    }
    for (std::size_t c = 6; c < 12; ++c) {
        EXPECT_NEAR(t[c].x, -1.0f, 1e-6f) << c;
        EXPECT_EQ(t[c].w, -1.0f) << c;
    }
}

// A UV sphere as an exporter writes it: u = φ/2π around +Y, v = θ/π from the top, and TANGENT the
// unit ∂p/∂u with w = +1. Away from the poles (where ∂p/∂u vanishes) the generated frames must
// agree with it within the faceting: a face's ∂p/∂u runs along its chord, half a segment
// (Δφ/2 = π/64, 2.81°) off the tangent at either corner. Inside the mesh the fans on both sides
// of a corner cancel that; on the u = 0 / u = 1 seam, where the corners are different vertices,
// one side remains. 3° bounds both.
TEST(Tangents, GeneratedFramesAgreeWithASmoothMeshsTangents) {
    constexpr int kRings = 32;
    constexpr int kSegments = 64;
    const float pi = std::numbers::pi_v<float>;
    auto vertex = [&](int ring, int segment, Soup& soup) {
        const float theta = pi * float(ring) / kRings;
        const float phi = 2.0f * pi * float(segment) / kSegments;
        const glm::vec3 n(std::sin(theta) * std::sin(phi), std::cos(theta),
                          std::sin(theta) * std::cos(phi));
        soup.corner(n, n, {float(segment) / kSegments, float(ring) / kRings});
    };
    Soup soup;
    for (int r = 0; r < kRings; ++r)
        for (int s = 0; s < kSegments; ++s) {
            // Counter-clockwise seen from outside.
            for (auto [dr, ds] : {std::pair{0, 0}, {1, 0}, {1, 1}, {0, 0}, {1, 1}, {0, 1}})
                vertex(r + dr, s + ds, soup);
        }
    const std::vector<glm::vec4> t = soup.tangents();
    const float bound = std::cos(3.0f * pi / 180.0f);
    std::size_t compared = 0;
    float smallestInside = 1.0f; // cosine, away from the seam
    for (std::size_t c = 0; c < t.size(); ++c) {
        const glm::vec3 n = soup.normals[c];
        if (std::abs(n.y) > 0.99f) continue; // the poles: no ∂p/∂u
        const glm::vec3 analytic = glm::normalize(glm::vec3(n.z, 0.0f, -n.x)); // ∂p/∂φ
        expectOrthonormalFrame(t[c], n, "sphere corner");
        ASSERT_GT(glm::dot(glm::vec3(t[c]), analytic), bound) << "corner " << c;
        ASSERT_EQ(t[c].w, 1.0f) << "corner " << c;
        const float u = soup.texcoords[c].x;
        if (u > 0.0f && u < 1.0f)
            smallestInside = std::min(smallestInside, glm::dot(glm::vec3(t[c]), analytic));
        ++compared;
    }
    EXPECT_GT(compared, t.size() * 9 / 10);
    // Off the seam the two sides cancel: within 0.1°.
    EXPECT_GT(smallestInside, std::cos(0.1f * pi / 180.0f));
}

TEST(Tangents, DegenerateTextureCoordinatesStillGiveAnOrthonormalFrame) {
    Soup collapsed = quad(false);
    for (glm::vec2& uv : collapsed.texcoords)
        uv = glm::vec2(0.25f); // every corner at one texel: no area
    Soup missing = quad(false);
    missing.texcoords.clear(); // a primitive without TEXCOORD_0
    Soup tilted;
    const glm::vec3 n = glm::normalize(glm::vec3(0.3f, -0.8f, 0.5f));
    for (int i = 0; i < 3; ++i) // collinear texture coordinates
        tilted.corner(glm::vec3(float(i == 1), float(i == 2), 0.0f), n, glm::vec2(float(i)));
    for (const Soup* soup : {&collapsed, &missing, &tilted}) {
        const std::vector<glm::vec4> t = soup->tangents();
        ASSERT_EQ(t.size(), soup->positions.size());
        for (std::size_t c = 0; c < t.size(); ++c)
            expectOrthonormalFrame(t[c], soup->normals[c], "degenerate corner");
    }
}

// A degenerate triangle's corners take the frame of the good triangles at the same vertex.
TEST(Tangents, DegenerateTriangleBorrowsItsVertexsFrame) {
    Soup soup = quad(false);
    const glm::vec3 n(0, 0, 1);
    soup.corner({0, 0, 0}, n, {0, 1});
    soup.corner({1, 0, 0}, n, {1, 1});
    soup.corner({0.5f, 0, 0}, n, {0.5f, 1}); // collinear texture coordinates
    const std::vector<glm::vec4> t = soup.tangents();
    for (std::size_t c = 6; c < 8; ++c) {
        EXPECT_NEAR(t[c].x, 1.0f, 1e-6f) << c;
        EXPECT_EQ(t[c].w, 1.0f) << c;
    }
}

TEST(Tangents, AnyOrthogonalIsUnitAndOrthogonal) {
    for (const glm::vec3& n : {glm::vec3(0, 0, 1), glm::vec3(0, 0, -1), glm::vec3(1, 0, 0),
                               glm::normalize(glm::vec3(1, 2, -3))}) {
        const glm::vec3 t = anyOrthogonal(n);
        EXPECT_NEAR(glm::length(t), 1.0f, 1e-6f);
        EXPECT_NEAR(glm::dot(t, n), 0.0f, 1e-6f);
    }
}

} // namespace
} // namespace vkpt::tangents_test
