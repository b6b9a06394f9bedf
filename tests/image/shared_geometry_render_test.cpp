// shared_geometry_render_test.cpp — an instance that places kept geometry with a material of its
// own (docs/scene-model.md, "Shared geometry") renders that geometry as if each of its triangles
// had that material. The Cornell box's non-emitting triangles are kept in one mesh whose
// triangles hold the box's materials, and placed by an instance that carries a metal the box
// does not use; the flattened box with that metal on every such triangle is the same scene. Placed
// by an exact transform (instanced_render_test.cpp), both trace the same paths at one seed, so
// the images agree pixel by pixel in the bound of docs/wavefront.md on vkpt and on vkpt-ref, and
// vkpt agrees with vkpt-ref.
#include <cstdio>
#include <string>

#include "../support/instancing.h"
#include "../support/render_checks.h"
#include "feature_scenes.h"
#include "wavefront_test_support.h"

namespace vkpt::test {
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

class SharedGeometryRender : public GpuTest {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        LoadedTestScene box = loadFeatureTestScene("cornell-box.gltf");
        Scene base = box.scene;
        base.cameras = {selectCamera(base, std::nullopt, 1.0f)};
        base.materials.push_back(instanceMetal());
        const auto metal = static_cast<std::uint32_t>(base.materials.size() - 1);

        Scene flat = base;
        for (std::uint32_t& material : flat.materialIndices)
            if (!flat.materials[material].emits()) material = metal;
        Scene instanced = instanceWholeScene(base, exactSharedPlacement());
        ASSERT_EQ(instanced.instances.size(), 1u);
        Scene ownMaterials = instanced;
        instanced.instances[0].material = metal;
        flat_ = preparedScene(std::move(flat));
        instanced_ = preparedScene(std::move(instanced));
        ownMaterials_ = preparedScene(std::move(ownMaterials));
        ASSERT_TRUE(instanced_.prepared.features.instances);
        ASSERT_FALSE(flat_.prepared.features.instances);
    }

    static RenderSettings settings() {
        RenderSettings s = testSettings(20, 4); // 20², 4 spp: every wall seen, a second
        s.seed = 31;                            // wall for a few bounces
        s.lightSamples = 2;
        return s;
    }

    static double agreement(const std::string& name, const RenderOutput& a, const RenderOutput& b) {
        const SameSeedAgreement same = compareSameSeed(a, b);
        std::printf("%s: %s\n", name.c_str(), same.summary().c_str());
        return same.fraction();
    }

    LoadedTestScene flat_;
    LoadedTestScene instanced_;
    LoadedTestScene ownMaterials_; // the instance without its material: the box's own
};

TEST_F(SharedGeometryRender, InstanceMaterialRendersAsTheFlattenedMaterial) {
    const RenderOutput reference = renderTestScene(instanced_, settings());
    const RenderOutput referenceFlat = renderTestScene(flat_, settings());
    EXPECT_GE(agreement("shared_reference", reference, referenceFlat), kSharedMinimumAgreement)
        << writeComparisonImages("shared_reference", reference, referenceFlat);
    const RenderOutput device = renderOnDevice(context(), instanced_, settings());
    EXPECT_GE(agreement("shared_device_vs_reference", device, reference), kSharedMinimumAgreement)
        << writeComparisonImages("shared_device_vs_reference", device, reference);
    const RenderOutput deviceFlat = renderOnDevice(context(), flat_, settings());
    EXPECT_GE(agreement("shared_device", device, deviceFlat), kSharedMinimumAgreement)
        << writeComparisonImages("shared_device", device, deviceFlat);
    // The check can fail: the box with its own materials is another image.
    EXPECT_LT(agreement("own_materials", renderTestScene(ownMaterials_, settings()), referenceFlat),
              0.5);
}

} // namespace
} // namespace vkpt::test
