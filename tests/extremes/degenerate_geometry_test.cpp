// degenerate_geometry_test.cpp — what the loader does with degenerate vertex data, one policy
// per case (docs/numerical-stability.md): non-finite positions (and negative color factors) are
// rejected with a message naming the place; zero-area triangles (repeated or collinear vertices)
// are skipped and counted; zero, infinite and NaN normals are replaced by the face normal and
// counted; each count is said once on stderr. And what both renderers do with what gets through:
// needle triangles render as the surface they tile, zero-area triangles handed over directly are
// never hit and never emit, a triangle listed twice changes nothing — never a NaN.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "../support/gltf_writer.h"
#include "common/errors.h"
#include "extremes_support.h"
#include "scene/gltf_loader.h"

namespace vkpt::degenerate_geometry_test {
namespace {

const float kNaN = std::numeric_limits<float>::quiet_NaN();
const float kInf = std::numeric_limits<float>::infinity();

// A unit quad facing +z (two triangles over vertices 0..3) and a camera in front of it; `extra`
// adds vertices and triangles after them.
test::MeshData quadMesh() {
    test::MeshData mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    mesh.indices = {0, 1, 2, 0, 2, 3};
    return mesh;
}

struct Loaded {
    Scene scene;
    std::string stderrText;
};

Loaded writeAndLoad(const test::MeshData& mesh, const std::string& name) {
    test::GltfWriter writer;
    writer.addMaterial(glm::vec3(0.5f), glm::vec3(1.0f));
    writer.addMesh(mesh);
    writer.addCamera(glm::vec3(0.5f, 0.5f, 2.0f), 0.8);
    const std::string path = test::testFilePath(name);
    writer.write(path);
    ::testing::internal::CaptureStderr();
    Scene scene = loadGltfScene(path);
    return {std::move(scene), ::testing::internal::GetCapturedStderr()};
}

std::string loadError(const test::MeshData& mesh, const std::string& name) {
    try {
        writeAndLoad(mesh, name);
    } catch (const InputError& error) {
        ::testing::internal::GetCapturedStderr();
        return error.what();
    }
    return "(loaded)";
}

std::size_t lines(const std::string& text) {
    return std::size_t(std::count(text.begin(), text.end(), '\n'));
}

TEST(DegenerateGeometry, ZeroAreaTrianglesAreSkippedAndCounted) {
    test::MeshData mesh = quadMesh();
    mesh.positions.push_back({2, 2, 2});                // 4: a copy of no one
    mesh.positions.push_back({1, 0, 0});                // 5: the same position as vertex 1
    mesh.positions.push_back({3, 3, 3});                // 6
    mesh.positions.push_back({4, 4, 4});                // 7: collinear with 4 and 6
    mesh.indices.insert(mesh.indices.end(), {0, 0, 1,   // a repeated index
                                             1, 5, 2,   // a repeated position
                                             4, 6, 7}); // collinear
    Loaded loaded = writeAndLoad(mesh, "zero_area.gltf");
    EXPECT_EQ(loaded.scene.triangleCount(), 2u);
    EXPECT_EQ(loaded.scene.repairs.zeroAreaTriangles, 3u);
    EXPECT_EQ(lines(loaded.stderrText), 1u) << loaded.stderrText;
    EXPECT_NE(loaded.stderrText.find("skipped 3 triangles of zero area"), std::string::npos)
        << loaded.stderrText;
}

TEST(DegenerateGeometry, OnlyZeroAreaTrianglesIsAnError) {
    test::MeshData mesh;
    mesh.positions = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}};
    mesh.indices = {0, 1, 2, 0, 0, 1};
    EXPECT_NE(loadError(mesh, "all_zero_area.gltf")
                  .find("the scene has no triangles of non-zero area (2 triangles of zero area)"),
              std::string::npos);
}

TEST(DegenerateGeometry, ZeroAndNonFiniteNormalsAreReplacedByTheFaceNormalAndCounted) {
    test::MeshData mesh = quadMesh();
    mesh.normals = {{0, 0, 0}, {kNaN, 0, 1}, {kInf, 0, 0}, {0, 0, 5}};
    Loaded loaded = writeAndLoad(mesh, "bad_normals.gltf");
    EXPECT_EQ(loaded.scene.repairs.invalidNormals, 3u);
    EXPECT_EQ(lines(loaded.stderrText), 1u) << loaded.stderrText;
    EXPECT_NE(loaded.stderrText.find("3 vertex normals were zero or not finite"), std::string::npos)
        << loaded.stderrText;
    for (const glm::vec3& n : loaded.scene.normals)
        EXPECT_EQ(n, glm::vec3(0.0f, 0.0f, 1.0f)); // the face normal, and (0, 0, 5) normalised
}

TEST(DegenerateGeometry, TinyButValidNormalsAreKept) {
    test::MeshData mesh = quadMesh();
    // |n|² underflows to 0 in float; the direction is still well defined.
    mesh.normals = {{1e-30f, 0, 1e-30f}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    Loaded loaded = writeAndLoad(mesh, "tiny_normal.gltf");
    EXPECT_EQ(loaded.scene.repairs.invalidNormals, 0u);
    EXPECT_NEAR(loaded.scene.normals[0].x, std::sqrt(0.5f), 1e-6f);
}

TEST(DegenerateGeometry, NonFinitePositionsAreRejectedNamingTheVertex) {
    for (float bad : {kNaN, kInf, -kInf}) {
        test::MeshData mesh = quadMesh();
        mesh.positions[2].y = bad;
        EXPECT_NE(loadError(mesh, "bad_position.gltf")
                      .find("mesh 0, primitive 0: vertex 2 has a non-finite position"),
                  std::string::npos)
            << bad;
    }
}

// Negative albedo or emission makes radiance negative, which no luminance statistic can take.
TEST(DegenerateGeometry, NegativeColorFactorsAreRejected) {
    for (glm::vec3 albedo : {glm::vec3(-0.1f, 0.5f, 0.5f), glm::vec3(0.5f)}) {
        test::GltfWriter writer;
        writer.addMaterial(albedo,
                           albedo.x < 0.0f ? glm::vec3(1.0f) : glm::vec3(1.0f, -1e-3f, 0.0f));
        writer.addMesh(quadMesh());
        const std::string path = test::testFilePath("negative_factor.gltf");
        writer.write(path);
        try {
            loadGltfScene(path);
            ADD_FAILURE() << "loaded";
        } catch (const InputError& error) {
            EXPECT_EQ(std::string(error.what()), path + ": material 0: a color factor is negative");
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Rendering what gets through.

// A floor tiled by a fan of 2,000 slivers from one corner (aspect ratios up to 1,400:1) and lit
// from above renders as the same floor made of two triangles.
Scene litFloor(bool needles) {
    Scene scene;
    std::uint32_t white = test::addMaterial(scene, glm::vec3(0.7f));
    std::uint32_t light = test::addMaterial(scene, glm::vec3(0.0f), glm::vec3(10.0f));
    const glm::vec3 apex(-1.0f, 0.0f, -1.0f);
    if (needles) {
        const int n = 1000;
        for (int i = 0; i < n; ++i) { // along the far edges x = 1, then z = 1
            auto edge = [&](int k, bool second) {
                float f = -1.0f + 2.0f * float(k) / float(n);
                return second ? glm::vec3(f, 0.0f, 1.0f) : glm::vec3(1.0f, 0.0f, -f);
            };
            // Both halves face up, as the two-triangle floor does: the material is
            // single-sided, and the camera sees through a back face (docs/scene-model.md).
            test::addTriangle(scene, apex, edge(i, false), edge(i + 1, false), white);
            test::addTriangle(scene, apex, edge(i, true), edge(i + 1, true), white);
        }
    } else {
        test::addHorizontalGrid(scene, glm::vec2(-1.0f), glm::vec2(1.0f), 0.0f, true, 1, white);
    }
    test::addQuad(scene, {-0.2f, 1.0f, -0.2f}, {0.2f, 1.0f, -0.2f}, {0.2f, 1.0f, 0.2f},
                  {-0.2f, 1.0f, 0.2f}, light);
    scene.cameras.push_back(test::lookAt(glm::vec3(0.0f, 2.5f, 0.01f), glm::vec3(0.0f),
                                         glm::vec3(0.0f, 0.0f, -1.0f), 50.0f));
    return scene;
}

class DegenerateRendering : public test::GpuTest {
protected:
    // Renders `scene` on both executors (seed 2) and requires each image finite and the same
    // within noise as vkpt-ref's render of the plain Cornell box (seed 1).
    test::BothRenders expectPlainCornellBox(const test::LoadedTestScene& scene) {
        RenderSettings settings = test::testSettings(24, 64);
        settings.seed = 2;
        test::BothRenders r = test::renderBoth(context(), scene, settings);
        RenderSettings unitSettings = test::testSettings(24, 64);
        unitSettings.seed = 1;
        RenderOutput unit =
            test::renderTestScene(test::prepareTestScene(test::cornellBoxScene()), unitSettings);
        for (const RenderOutput* out : {&r.cpu, &r.gpu}) {
            EXPECT_TRUE(test::outputIsFinite(*out));
            EXPECT_TRUE(test::sameWithinNoise(*out, unit, out == &r.cpu ? "vkpt-ref" : "vkpt"));
        }
        return r;
    }
};

TEST_F(DegenerateRendering, NeedleFanRendersAsTheFloorItTiles) {
    RenderSettings settings = test::testSettings(24, 64);
    RenderOutput plain = test::renderTestScene(test::prepareTestScene(litFloor(false)), settings);
    settings.seed = 1;
    test::BothRenders r =
        test::renderBoth(context(), test::prepareTestScene(litFloor(true)), settings);
    for (const RenderOutput* out : {&r.cpu, &r.gpu}) {
        EXPECT_TRUE(test::outputIsFinite(*out));
        EXPECT_TRUE(test::sameWithinNoise(*out, plain, out == &r.cpu ? "vkpt-ref" : "vkpt"));
    }
    EXPECT_EQ(r.cpuStats.nonFiniteSamples + r.gpuStats.nonFiniteSamples, 0u);
    EXPECT_TRUE(test::devicesAgree(r.gpu, r.cpu));
}

// Triangles of zero area that reach the renderers without the loader (a scene built in
// memory): one collapsed onto a point, one onto a line, and a zero-area emitter. None may be
// hit, sampled or divide by zero: the image is the Cornell box's.
TEST_F(DegenerateRendering, ZeroAreaTrianglesInMemoryChangeNothing) {
    Scene scene = test::cornellBoxScene();
    std::uint32_t light = test::addMaterial(scene, glm::vec3(0.5f), glm::vec3(1e6f));
    const glm::vec3 p(0.3f, 0.3f, 0.3f);
    for (glm::vec3 q : {p, p + glm::vec3(0.1f)}) { // a point and a line segment
        scene.positions.insert(scene.positions.end(), {p, q, q});
        scene.normals.insert(scene.normals.end(), 3, glm::vec3(0.0f)); // as degenerate as it gets
        scene.materialIndices.push_back(light);
    }
    test::LoadedTestScene prepared = test::prepareTestScene(scene);
    EXPECT_EQ(prepared.prepared.emitters.size(), 2u) << "only the Cornell light's two triangles";
    test::BothRenders r = expectPlainCornellBox(prepared);
    EXPECT_EQ(r.cpuStats.nonFiniteSamples + r.gpuStats.nonFiniteSamples, 0u);
}

// Every triangle of the Cornell box twice (an exporter that writes a mesh twice): ties between
// the copies go to whichever the walk meets first, and the two copies of the light share one
// emitter record, so light sampling picks the light once, as a ray finds it once. With a record
// per copy the light counted twice in light sampling (measured: 212 of 576 pixels brighter,
// worst z = 15.7).
TEST_F(DegenerateRendering, DuplicatedTrianglesChangeNothing) {
    Scene scene = test::cornellBoxScene();
    const std::size_t n = scene.triangleCount();
    for (std::size_t t = 0; t < n; ++t) {
        for (std::size_t k = 0; k < 3; ++k) {
            // The copy starts from another corner: still the same surface.
            scene.positions.push_back(scene.positions[3 * t + (k + 1) % 3]);
            scene.normals.push_back(scene.normals[3 * t + (k + 1) % 3]);
        }
        scene.materialIndices.push_back(scene.materialIndices[t]);
    }
    test::LoadedTestScene prepared = test::prepareTestScene(scene);
    EXPECT_EQ(prepared.prepared.emitters.size(), 2u);
    test::BothRenders r = expectPlainCornellBox(prepared);
    EXPECT_TRUE(test::devicesAgree(r.gpu, r.cpu));
}

} // namespace
} // namespace vkpt::degenerate_geometry_test
