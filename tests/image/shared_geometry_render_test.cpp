// shared_geometry_render_test.cpp — an instance that places kept geometry with a material of its
// own (docs/scene-model.md, "Shared geometry") renders that geometry as if each of its triangles
// had that material. The Cornell box's non-emitting triangles are kept in one mesh whose
// triangles hold the box's materials, and placed by an instance that carries a metal the box
// does not use; the flattened box with that metal on every such triangle is the same scene. Placed
// by an exact transform (instanced_render_test.cpp), both trace the same paths at one seed, so
// the images agree pixel by pixel in the bound of docs/wavefront.md on vkpt and on vkpt-ref, and
// vkpt agrees with vkpt-ref. The same with alpha-masked materials, whose cut-outs the walks take
// from the instance's material.
#include <cstdio>
#include <string>

#include "../support/instancing.h"
#include "../support/render_checks.h"
#include "feature_scenes.h"
#include "wavefront_test_support.h"

namespace vkpt::test::shared_geometry_render_test {
namespace {

// As instanced_render_test.cpp: paths that diverge on a last-bit difference stay rare.
constexpr double kSharedMinimumAgreement = 0.99;

// A quarter turn about y, scaled by (2, −0.5, 1) (a mirror) and moved by dyadic steps: every
// entry and its inverse's is exact in float.
glm::dmat4 exactSharedPlacement() {
    glm::dmat4 t(0.0);
    t[0] = glm::dvec4(0.0, 0.0, -2.0, 0.0);
    t[1] = glm::dvec4(0.0, -0.5, 0.0, 0.0);
    t[2] = glm::dvec4(1.0, 0.0, 0.0, 0.0);
    t[3] = glm::dvec4(0.25, -0.5, 0.125, 1.0);
    return t;
}

// A rough gold metal: no triangle of the box has it, so only the instance brings it (and its
// GGX lobe) into the scene.
SceneMaterial instanceMetal() {
    SceneMaterial metal;
    metal.name = "instance metal";
    metal.baseColor = glm::vec4(0.9f, 0.6f, 0.2f, 1.0f);
    metal.metallic = 1.0f;
    metal.roughness = 0.4f;
    return metal;
}

LoadedTestScene preparedScene(Scene scene) {
    LoadedTestScene loaded{std::move(scene), {}};
    loaded.prepared = prepareScene(loaded.scene);
    return loaded;
}

// `base` with material `material` on every non-emitting triangle (flat), and as one mesh of its
// own materials placed by an instance that carries `material` (instanced) or not (own).
struct SharedScenes {
    LoadedTestScene flat;
    LoadedTestScene instanced;
    LoadedTestScene own;
};

SharedScenes sharedScenes(Scene base, std::uint32_t material) {
    base.cameras = {selectCamera(base, std::nullopt, 1.0f)};
    Scene flat = base;
    for (std::uint32_t& m : flat.materialIndices)
        if (!flat.materials[m].emits()) m = material;
    Scene instanced = instanceWholeScene(base, exactSharedPlacement());
    EXPECT_EQ(instanced.instances.size(), 1u);
    Scene own = instanced;
    instanced.instances[0].material = material;
    return {preparedScene(std::move(flat)), preparedScene(std::move(instanced)),
            preparedScene(std::move(own))};
}

// The Cornell box with its non-emitting triangles in one mesh of the box's materials; the
// instance carries a metal that no triangle has.
SharedScenes metalBox() {
    Scene box = loadFeatureTestScene("cornell-box.gltf").scene;
    const auto metal = static_cast<std::uint32_t>(box.materials.size());
    box.materials.push_back(instanceMetal());
    return sharedScenes(std::move(box), metal);
}

// The alpha-mask scene with every non-emitting triangle of its screen (a masked material with a
// texture of holes); the instance carries another masked material, green, whose holes are half
// the size (the texture transform doubles uv): the walks' alpha test must read the instance's.
SharedScenes finerHoles() {
    Scene scene = feature_scenes::alphaMaskScene();
    std::uint32_t screen = 0;
    while (scene.materials[screen].alphaMode != AlphaMode::Mask ||
           scene.materials[screen].baseColorTexture.texture < 0)
        ++screen;
    for (std::uint32_t& m : scene.materialIndices)
        if (!scene.materials[m].emits()) m = screen;
    SceneMaterial finer = scene.materials[screen];
    finer.name = "finer holes";
    finer.baseColor = glm::vec4(0.3f, 0.9f, 0.3f, 1.0f);
    finer.baseColorTexture.transform =
        glm::mat3(2.0f, 0.0f, 0.0f, 0.0f, 2.0f, 0.0f, 0.0f, 0.0f, 1.0f);
    const auto finerIndex = static_cast<std::uint32_t>(scene.materials.size());
    scene.materials.push_back(finer);
    return sharedScenes(std::move(scene), finerIndex);
}

struct SharedCase {
    std::string name;
    SharedScenes (*make)();
};

void PrintTo(const SharedCase& c, std::ostream* out) {
    *out << c.name;
}

std::string sharedCaseName(const ::testing::TestParamInfo<SharedCase>& info) {
    return info.param.name;
}

class SharedGeometryRender : public GpuTest, public ::testing::WithParamInterface<SharedCase> {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        scenes_ = GetParam().make();
        ASSERT_TRUE(scenes_.instanced.prepared.features.instances);
        ASSERT_FALSE(scenes_.flat.prepared.features.instances);
    }

    static RenderSettings settings() {
        RenderSettings s = testSettings(20, 4); // 20², 4 spp: every wall seen, a second
        s.seed = 31;                            // wall for a few bounces
        s.lightSamples = 2;
        return s;
    }

    double agreement(const std::string& what, const RenderOutput& a, const RenderOutput& b) {
        const std::string name = GetParam().name + "_" + what;
        const SameSeedAgreement same = compareSameSeed(a, b);
        std::printf("%s: %s\n", name.c_str(), same.summary().c_str());
        if (same.fraction() < kSharedMinimumAgreement && what != "own_materials")
            ADD_FAILURE() << writeComparisonImages(name, a, b);
        return same.fraction();
    }

    SharedScenes scenes_;
};

TEST_P(SharedGeometryRender, InstanceMaterialRendersAsTheFlattenedMaterial) {
    const RenderOutput reference = renderTestScene(scenes_.instanced, settings());
    const RenderOutput referenceFlat = renderTestScene(scenes_.flat, settings());
    EXPECT_GE(agreement("reference", reference, referenceFlat), kSharedMinimumAgreement);
    const RenderOutput device = renderOnDevice(context(), scenes_.instanced, settings());
    EXPECT_GE(agreement("device_vs_reference", device, reference), kSharedMinimumAgreement);
    const RenderOutput deviceFlat = renderOnDevice(context(), scenes_.flat, settings());
    EXPECT_GE(agreement("device", device, deviceFlat), kSharedMinimumAgreement);
    // The check can fail: the scene with the mesh's own materials is another image (measured:
    // 2 % of the metal box's pixels agree, 55 % of the alpha scene's).
    EXPECT_LT(agreement("own_materials", renderTestScene(scenes_.own, settings()), referenceFlat),
              0.9);
}

INSTANTIATE_TEST_SUITE_P(SharedGeometry, SharedGeometryRender,
                         ::testing::Values(SharedCase{"metal_box", metalBox},
                                           SharedCase{"finer_holes", finerHoles}),
                         sharedCaseName);

} // namespace
} // namespace vkpt::test::shared_geometry_render_test
