// light_tree_test.cpp — the light BVH: its pmf over every emitter sums to 1 from any point (less
// the walks that end where no emitter below can reach the point) and is the probability the
// walk reports, the walk's choices follow that pmf (chi-square), and an
// emitter of power 0 (a black emissive texture) is never chosen.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "../support/chi_square.h"
#include "../support/scene_builder.h"
#include "bvh/synthetic_scenes.h"
#include "prepare/prepared_scene.h"
#include "prepare/prepared_scene_view.h"
#include "shared/lights.h"

namespace vkpt::light_tree_test {
namespace {

// Many small emitting triangles of random size, orientation and brightness in a 20 m cube
// (some double-sided, or all of them), with an emitting sphere and one light of every punctual
// kind, under a constant environment: every kind of node the tree can hold.
Scene manyEmitterScene(std::uint32_t triangles, bool allDoubleSided = false) {
    Scene scene;
    synthetic::Rng rng(7);
    std::vector<std::uint32_t> materials;
    for (int m = 0; m < 8; ++m)
        materials.push_back(test::addMaterial(scene, glm::vec3(0.5f),
                                              glm::vec3(rng.uniform(0.1f, 10.0f)),
                                              allDoubleSided || m % 3 == 0));
    for (std::uint32_t i = 0; i < triangles; ++i) {
        const glm::vec3 centre = rng.inBox(glm::vec3(-10.0f), glm::vec3(10.0f));
        const float size = rng.uniform(0.02f, 0.5f);
        test::addTriangle(scene, centre + size * rng.unitVector(), centre + size * rng.unitVector(),
                          centre + size * rng.unitVector(), materials[rng.below(8)]);
    }
    scene.spheres.push_back({glm::vec3(3.0f, -2.0f, 1.0f), 0.5f, materials[1]});
    SceneLight point;
    point.position = glm::vec3(-4.0f, 5.0f, 2.0f);
    point.intensity = glm::vec3(20.0f);
    SceneLight spot = point;
    spot.kind = LightKind::Spot;
    spot.position = glm::vec3(6.0f, 6.0f, -6.0f);
    spot.direction = glm::normalize(glm::vec3(-1.0f, -1.0f, 1.0f));
    spot.innerConeAngle = 0.3f;
    spot.outerConeAngle = 0.6f;
    SceneLight directional = point;
    directional.kind = LightKind::Directional;
    directional.direction = glm::normalize(glm::vec3(0.2f, -1.0f, 0.1f));
    directional.intensity = glm::vec3(0.5f);
    scene.lights = {point, spot, directional};
    scene.environment.radiance = glm::vec3(0.05f);
    return scene;
}

PreparedScene prepareWithLightTree(const Scene& scene) {
    PrepareOptions options;
    options.lightSampler = LightSampler::Bvh;
    return prepareScene(scene, options);
}

double pmfSum(const PreparedScene& prepared, const gpu::SceneView& view, glm::vec3 p) {
    double sum = 0.0;
    for (std::uint32_t e = 0; e < prepared.emitters.size(); ++e)
        sum += gpu::emitterSelectProbability(e, prepared.emitters[e], p, view);
    return sum;
}

// The chance that the walk from p reaches a node both of whose children have weight 0 there
// (each child's bounds can send p nothing, though their union could): such a walk chooses no
// emitter, and its light sample contributes nothing, as pbrt-v4's does. Found by visiting every
// node the walk can reach, independently of lightTreePmf's walk up the parent links.
double deadEndMass(const gpu::SceneView& view, std::uint32_t index, double reach, glm::vec3 p) {
    const gpu::LightTreeNode node = view.lightTree[index];
    if ((node.flags & LIGHT_NODE_LEAF) != 0u || reach == 0.0) return 0.0;
    const float w0 = gpu::lightChildWeight(node, node.child0, p, view);
    const float w1 = gpu::lightChildWeight(node, node.child1, p, view);
    if (!(w0 + w1 > 0.0f)) return reach;
    const double p0 = double(gpu::firstChildProbability(w0, w1));
    double mass = deadEndMass(view, node.child0, reach * p0, p);
    if (node.child1 != NO_LIGHT_NODE) mass += deadEndMass(view, node.child1, reach * (1.0 - p0), p);
    return mass;
}

void expectPmfSumsToOne(const PreparedScene& prepared, bool allDoubleSided) {
    ASSERT_TRUE(prepared.features.lightTree);
    // Every emitter has power: its leaf, the root, and one inner node for each other leaf.
    ASSERT_EQ(prepared.lightTree.size(), 2 * prepared.emitters.size() - 1);
    const gpu::SceneView view = makeSceneView(prepared);
    const auto root = std::uint32_t(prepared.emitters.size());
    synthetic::Rng rng(11);
    int withoutDeadEnds = 0;
    // Each pmf is a product of about 25 float factors, each rounded once (relative 6e-8), so
    // the sum in double is 1 within a few 1e-6; 1e-4 leaves room without hiding a lost subtree
    // (a node's share of the walks is far above 1e-4 here).
    for (int i = 0; i < 200; ++i) {
        const glm::vec3 p = rng.inBox(glm::vec3(-14.0f), glm::vec3(14.0f));
        const double deadEnds = deadEndMass(view, root, 1.0, p);
        withoutDeadEnds += deadEnds == 0.0;
        EXPECT_NEAR(pmfSum(prepared, view, p) + deadEnds, 1.0, 1e-4) << "at point " << i;
    }
    // Emitters seen from both sides have importance 0 only in their planes: no dead ends, so
    // that the sums are 1 on their own.
    if (allDoubleSided) {
        EXPECT_EQ(withoutDeadEnds, 200);
    }
}

TEST(LightTree, PmfSumsToOneOverAllEmittersFromRandomPoints) {
    for (bool allDoubleSided : {false, true})
        expectPmfSumsToOne(prepareWithLightTree(manyEmitterScene(3000, allDoubleSided)),
                           allDoubleSided);
}

TEST(LightTree, SampledProbabilityIsThePmfOfTheChosenEmitter) {
    const PreparedScene prepared = prepareWithLightTree(manyEmitterScene(3000));
    const gpu::SceneView view = makeSceneView(prepared);
    synthetic::Rng rng(12);
    for (int i = 0; i < 5000; ++i) {
        const glm::vec3 p = rng.inBox(glm::vec3(-14.0f), glm::vec3(14.0f));
        const gpu::EmitterChoice choice = gpu::chooseEmitter(p, rng.uniform(), view);
        if (choice.index == NO_EMITTER) continue; // a dead end (deadEndMass above)
        const gpu::Emitter& emitter = prepared.emitters[choice.index];
        if (gpu::isInfiniteEmitter(emitter)) continue; // reported as selectProbability
        // The walk multiplies its factors from the root down, the pmf from the leaf up.
        EXPECT_NEAR(gpu::emitterSelectProbability(choice.index, emitter, p, view),
                    choice.probability, 1e-5 * choice.probability)
            << "draw " << i;
    }
}

TEST(LightTree, ChoicesFollowThePmf) {
    const PreparedScene prepared = prepareWithLightTree(manyEmitterScene(40));
    const gpu::SceneView view = makeSceneView(prepared);
    const glm::vec3 p(0.5f, -0.25f, 1.0f);
    const std::size_t n = prepared.emitters.size();
    constexpr int kDraws = 200000;
    std::vector<double> observed(n, 0.0), expected(n, 0.0);
    for (int i = 0; i < kDraws; ++i) {
        const float u = (float(i) + 0.5f) / float(kDraws); // stratified: exact frequencies
        observed[gpu::chooseEmitter(p, u, view).index] += 1.0;
    }
    for (std::uint32_t e = 0; e < n; ++e)
        expected[e] = kDraws * double(gpu::lightTreePmf(e, p, view));
    // Stratified draws meet each emitter's interval almost exactly, so a large p-value is
    // expected; 1e-3 only catches a walk whose choices are not the pmf's.
    EXPECT_GT(test::chiSquareTest(observed, expected).pValue, 1e-3);
}

// Two emitting quads with one emissive texture: the left half of the texture black, the right
// half white. The quad mapped onto the black half has power 0.
Scene halfBlackTexturedScene() {
    Scene scene;
    const std::uint32_t material =
        test::addMaterial(scene, glm::vec3(0.5f), glm::vec3(2.0f), false);
    SceneImage image;
    image.width = 4;
    image.height = 4;
    for (std::uint32_t y = 0; y < 4; ++y)
        for (std::uint32_t x = 0; x < 4; ++x)
            image.texels.push_back(x < 2 ? 0xff000000u : 0xffffffffu);
    scene.images.push_back(image);
    SceneTexture texture;
    texture.wrapS = texture.wrapT = TextureWrap::ClampToEdge;
    texture.nearest = true;
    scene.textures.push_back(texture);
    scene.materials[material].emissiveTexture.texture = 0;
    for (int quad = 0; quad < 2; ++quad) {
        const float x = float(quad) * 2.0f;
        // u in [0, 0.4] (black texels) for the first quad, [0.6, 1] (white) for the second.
        const float u0 = quad == 0 ? 0.0f : 0.6f;
        const glm::vec3 c[4] = {{x, 0, 0}, {x + 1, 0, 0}, {x + 1, 1, 0}, {x, 1, 0}};
        const glm::vec2 t[4] = {{u0, 0}, {u0 + 0.4f, 0}, {u0 + 0.4f, 1}, {u0, 1}};
        for (int tri : {0, 1}) {
            const int k[3] = {0, 1 + tri, 2 + tri};
            test::addTriangle(scene, c[k[0]], c[k[1]], c[k[2]], material);
            for (int corner : k)
                scene.texcoords.push_back(t[corner]);
        }
    }
    return scene;
}

TEST(LightTree, BlackTexturedEmittersHaveNoPowerAndAreNeverChosen) {
    for (bool tree : {false, true}) {
        PrepareOptions options;
        options.lightSampler = tree ? LightSampler::Bvh : LightSampler::Power;
        const PreparedScene prepared = prepareScene(halfBlackTexturedScene(), options);
        ASSERT_EQ(prepared.emitters.size(), 4u);
        const gpu::SceneView view = makeSceneView(prepared);
        synthetic::Rng rng(13);
        for (int i = 0; i < 20000; ++i) {
            const glm::vec3 p = rng.inBox(glm::vec3(-2.0f, -2.0f, 0.1f), glm::vec3(4.0f));
            const gpu::EmitterChoice choice = gpu::chooseEmitter(p, rng.uniform(), view);
            ASSERT_NE(choice.index, NO_EMITTER);
            const gpu::Triangle& t = prepared.triangles[prepared.emitters[choice.index].primitive];
            ASSERT_GT(t.v0.x + t.v1.x + t.v2.x, 4.5f) << "a black quad's triangle was chosen";
            ASSERT_GT(choice.probability, 0.0f);
        }
        for (std::uint32_t e = 0; e < 4; ++e) {
            const gpu::Triangle& t = prepared.triangles[prepared.emitters[e].primitive];
            if (t.v0.x + t.v1.x + t.v2.x < 4.5f) {
                EXPECT_EQ(prepared.emitters[e].selectProbability, 0.0f);
                EXPECT_EQ(gpu::emitterSelectProbability(e, prepared.emitters[e],
                                                        glm::vec3(0.5f, 0.5f, 1.0f), view),
                          0.0f);
            }
        }
    }
}

} // namespace
} // namespace vkpt::light_tree_test
