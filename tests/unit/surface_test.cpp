// surface_test.cpp — the shared surface, material and light code (shared/surface.h,
// materials.h, lights.h, light_connection.h) on a hand-made SceneView: which side a hit is on
// and what it emits there, textures and the alpha cut-out, emitter selection, and a light
// sample's pdf and shadow ray against the hit that reaches the same point.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "shared/light_connection.h"
#include "shared/lights.h"
#include "shared/materials.h"
#include "shared/surface.h"
#include "shared/volume.h"

namespace vkpt::gpu::surface_test {
namespace {

TextureSlot emptySlot() {
    return {vec3(1.0f, 0.0f, 0.0f), NO_TEXTURE, vec3(0.0f, 1.0f, 0.0f), 0u};
}

// Every field named, so that a field added to Material later starts at zero here rather than
// breaking the initialiser; the texture slots are empty and the extensions at their defaults.
Material diffuse(vec3 baseColor, vec3 emission = vec3(0.0f)) {
    Material m{};
    m.baseColor = vec4(baseColor, 1.0f);
    m.emission = emission;
    m.roughness = 1.0f;
    m.alphaCutoff = 0.5f;
    m.alphaMode = ALPHA_MODE_OPAQUE;
    m.specularColor = vec3(1.0f);
    m.baseColorTexture = m.metallicRoughnessTexture = m.emissiveTexture = emptySlot();
    m.normalTexture = m.transmissionTexture = emptySlot();
    m.clearcoatTexture = m.clearcoatRoughnessTexture = m.clearcoatNormalTexture = emptySlot();
    m.sheenColorTexture = m.sheenRoughnessTexture = emptySlot();
    m.clearcoatNormalScale = 1.0f;
    m.normalScale = 1.0f;
    m.ior = 1.5f;
    m.iorF0 = 0.04f;
    return m;
}

// A one-triangle (or one-sphere) scene: the triangle in z = -1, counter-clockwise seen from
// the origin, so its front faces the origin; it is also the scene's only emitter.
struct TinyScene {
    std::vector<Triangle> primitives{{vec3(-1.0f, -1.0f, -1.0f), 0u, vec3(1.0f, -1.0f, -1.0f), 0u,
                                      vec3(-1.0f, 1.0f, -1.0f), 0u}};
    std::vector<TriangleNormals> normals{
        {vec4(0.0f, 0.0f, 1.0f, 0.0f), vec4(0.0f, 0.0f, 1.0f, 0.0f), vec4(0.0f, 0.0f, 1.0f, 0.0f)}};
    std::vector<vec2> uvs{vec2(0.0f, 0.0f), vec2(1.0f, 0.0f), vec2(0.0f, 1.0f)};
    std::vector<Material> materials{diffuse(vec3(0.5f), vec3(2.0f))};
    std::vector<TextureInfo> textures;
    std::vector<uint> texels;
    std::vector<Emitter> emitters{
        {vec3(0.0f), EMITTER_TRIANGLE, vec3(0.0f), 0u, vec3(0.0f), 0.0f, 2.0f, 1.0f, 0.0f, 0.0f}};
    std::vector<float> emitterCdf;
    std::array<bool, FEATURE_COUNT> features{};

    SceneView view() const {
        SceneView v{};
        v.triangles = primitives;
        v.normals = normals;
        v.uvs = uvs;
        v.materials = materials;
        v.textures = textures;
        v.texels = texels;
        v.emitters = emitters;
        v.emitterCdf = emitterCdf;
        v.environment = {vec3(0.0f), 0u, 0u, NO_EMITTER, 0u, 0u};
        v.features = features;
        return v;
    }
};

SurfacePoint hitFrom(const TinyScene& scene, vec3 origin, vec3 target) {
    vec3 direction = target - origin;
    TriangleHit hit{1.0f, 0.25f, 0.25f, true};
    return makeSurfacePoint(0u, NO_INSTANCE, hit, origin, direction, scene.view());
}

TEST(SharedSurface, FrontHitFacesTheRayAndEmits) {
    TinyScene scene;
    SurfacePoint s = hitFrom(scene, vec3(0.0f), vec3(-0.5f, -0.5f, -1.0f));
    EXPECT_TRUE(s.frontFace);
    EXPECT_EQ(s.position, vec3(-0.5f, -0.5f, -1.0f));
    EXPECT_EQ(s.geometricNormal, vec3(0.0f, 0.0f, 1.0f));
    EXPECT_EQ(s.shadingNormal, vec3(0.0f, 0.0f, 1.0f));
    EXPECT_EQ(emittedRadiance(s), vec3(2.0f));
    EXPECT_EQ(s.shading.baseColor, vec3(0.5f));
}

// Both normals turn towards the ray; the back face emits only for a double-sided material,
// and only where the scene's features include double-sided materials.
TEST(SharedSurface, BackHitFlipsNormalsAndEmitsOnlyWhenDoubleSided) {
    TinyScene scene;
    const vec3 below(0.0f, 0.0f, -2.0f);
    SurfacePoint s = hitFrom(scene, below, vec3(-0.5f, -0.5f, -1.0f));
    EXPECT_FALSE(s.frontFace);
    EXPECT_EQ(s.geometricNormal, vec3(0.0f, 0.0f, -1.0f));
    EXPECT_EQ(s.shadingNormal, vec3(0.0f, 0.0f, -1.0f));
    EXPECT_EQ(emittedRadiance(s), vec3(0.0f));
    scene.materials[0].flags |= MATERIAL_DOUBLE_SIDED;
    EXPECT_EQ(emittedRadiance(hitFrom(scene, below, vec3(-0.5f, -0.5f, -1.0f))), vec3(0.0f));
    scene.features[FEATURE_DOUBLE_SIDED] = true;
    EXPECT_EQ(emittedRadiance(hitFrom(scene, below, vec3(-0.5f, -0.5f, -1.0f))), vec3(2.0f));
}

// A probe's emissionTowards agrees with the full surface point on both sides.
TEST(SharedSurface, EmissionTowardsMatchesTheSurfacePoint) {
    TinyScene scene;
    const TriangleHit hit{1.0f, 0.25f, 0.25f, true};
    for (vec3 origin : {vec3(0.0f), vec3(0.0f, 0.0f, -2.0f)}) {
        vec3 direction = vec3(-0.5f, -0.5f, -1.0f) - origin;
        EXPECT_EQ(emissionTowards(0u, hit, origin, direction, scene.view()),
                  emittedRadiance(hitFrom(scene, origin, vec3(-0.5f, -0.5f, -1.0f))));
    }
}

// A sphere hit lies on the sphere along its outward normal; seen from inside it is a back face.
TEST(SharedSurface, SphereHitIsPutBackOnTheSphere) {
    TinyScene scene;
    scene.primitives[0] = {vec3(0.0f, 0.0f, -5.0f), 0u, vec3(2.0f, 0.0f, 0.0f), 0u, vec3(0.0f),
                           PRIMITIVE_SPHERE};
    scene.features[FEATURE_SPHERES] = true;
    TriangleHit hit{3.0f, 0.0f, 0.0f, true};
    SurfacePoint outside =
        makeSurfacePoint(0u, NO_INSTANCE, hit, vec3(0.0f), vec3(0.0f, 0.0f, -1.0f), scene.view());
    EXPECT_TRUE(outside.frontFace);
    EXPECT_EQ(outside.position, vec3(0.0f, 0.0f, -3.0f));
    EXPECT_EQ(outside.geometricNormal, vec3(0.0f, 0.0f, 1.0f));
    SurfacePoint inside =
        makeSurfacePoint(0u, NO_INSTANCE, TriangleHit{2.0f, 0.0f, 0.0f, true},
                         vec3(0.0f, 0.0f, -5.0f), vec3(0.0f, 0.0f, 1.0f), scene.view());
    EXPECT_FALSE(inside.frontFace);
    EXPECT_EQ(inside.geometricNormal, vec3(0.0f, 0.0f, -1.0f));
    EXPECT_EQ(inside.rawShadingNormal, vec3(0.0f, 0.0f, 1.0f));
}

// A 2×1 nearest-filtered texture: u < 1/2 reads the left texel. The base colour texture scales
// the factor and its alpha decides the cut-out; without the textures feature the factor alone
// applies.
TEST(SharedSurface, TexturesScaleFactorsAndCutOutByAlpha) {
    TinyScene scene;
    scene.textures = {{0u, 2u, 1u, TEXTURE_FILTER_NEAREST}};
    scene.texels = {0x000000ffu, 0xffffffffu}; // left: red, alpha 0; right: white, alpha 1
    Material& m = scene.materials[0];
    m.baseColorTexture.texture = 0u;
    m.alphaMode = ALPHA_MODE_MASK;
    const TriangleHit left{1.0f, 0.1f, 0.1f, true};  // uv (0.1, 0.1)
    const TriangleHit right{1.0f, 0.8f, 0.1f, true}; // uv (0.8, 0.1)
    const vec3 origin(0.0f), direction(-0.5f, -0.5f, -1.0f);
    EXPECT_FALSE(isCutOut(0u, NO_INSTANCE, left, origin, direction, scene.view()));
    scene.features[FEATURE_TEXTURES] = true;
    EXPECT_TRUE(isCutOut(0u, NO_INSTANCE, left, origin, direction, scene.view()));
    EXPECT_FALSE(isCutOut(0u, NO_INSTANCE, right, origin, direction, scene.view()));
    SurfacePoint s = makeSurfacePoint(0u, NO_INSTANCE, left, origin, direction, scene.view());
    EXPECT_EQ(s.shading.baseColor, vec3(0.5f, 0.0f, 0.0f));
}

// selectEmitter is std::upper_bound over the inclusive CDF: an entry equal to its predecessor
// (weight 0) is never chosen, u at or past the end takes the last emitter, and without the CDF
// feature (one emitter) the CDF is never read.
TEST(SharedLights, SelectEmitterIsAnUpperBound) {
    TinyScene scene;
    const Emitter first = scene.emitters[0];
    scene.emitters.assign(3, first);
    scene.emitterCdf = {0.25f, 0.25f, 1.0f};
    EXPECT_EQ(selectEmitter(0.9f, scene.view()), 0u);
    scene.features[FEATURE_EMITTER_CDF] = true;
    EXPECT_EQ(selectEmitter(0.0f, scene.view()), 0u);
    EXPECT_EQ(selectEmitter(0.25f, scene.view()), 2u);
    EXPECT_EQ(selectEmitter(1.0f, scene.view()), 2u);
}

// The triangle light seen from the origin: the sample's pdf is lightPdf at the point it
// reaches, and the shadow ray is a segment from the offset receiver to the offset light point.
TEST(SharedLights, LightSampleMatchesLightPdfAndConnectsBothEnds) {
    TinyScene scene;
    scene.materials.push_back(diffuse(vec3(0.8f)));
    // The receiver: a point of a second, non-emitting triangle in z = 0, hit from below so
    // that it faces the light.
    scene.primitives.push_back({vec3(-1.0f, -1.0f, 0.0f), 1u, vec3(-1.0f, 1.0f, 0.0f), NO_EMITTER,
                                vec3(1.0f, -1.0f, 0.0f), 1u});
    scene.normals.push_back(scene.normals[0]);
    SurfacePoint receiver =
        makeSurfacePoint(1u, NO_INSTANCE, TriangleHit{0.5f, 0.5f, 0.0f, true},
                         vec3(-1.0f, 0.0f, -0.5f), vec3(0.0f, 0.0f, 1.0f), scene.view());
    ASSERT_EQ(receiver.position, vec3(-1.0f, 0.0f, 0.0f));
    ASSERT_EQ(receiver.geometricNormal, vec3(0.0f, 0.0f, -1.0f));
    const vec4 u(0.5f, 0.3f, 0.6f, 0.0f);
    // The light's front face (+z) faces the receiver.
    LightSample light = sampleLight(receiver.position, u, scene.view());
    ASSERT_TRUE(light.valid);
    EXPECT_EQ(light.radiance, vec3(2.0f));
    EXPECT_EQ(light.towardsReceiver, vec3(0.0f, 0.0f, 1.0f));
    vec3 toLight = light.position - receiver.position;
    SurfacePoint reached = makeSurfacePoint(0u, NO_INSTANCE, TriangleHit{1.0f, 0.0f, 0.0f, true},
                                            receiver.position, toLight, scene.view());
    reached.position = light.position;
    EXPECT_NEAR(lightPdf(reached, receiver.position, scene.view()), light.pdfSolidAngle,
                1e-5f * light.pdfSolidAngle);
    LightConnection c = connectLightSample(receiver, u, scene.view());
    ASSERT_TRUE(c.valid);
    EXPECT_EQ(c.tMax, 1.0f);
    EXPECT_LT(c.origin.z, receiver.position.z); // moved off the receiver, towards the light
    EXPECT_GT((c.origin + c.direction).z, light.position.z); // and off the light
    EXPECT_EQ(c.lightPdf, light.pdfSolidAngle);
    EXPECT_GT(c.bsdfPdf, 0.0f);
    // Seen from behind, a single-sided light sends nothing and there is nothing to trace.
    scene.primitives[0] = {vec3(-1.0f, -1.0f, -1.0f), 0u, vec3(-1.0f, 1.0f, -1.0f), 0u,
                           vec3(1.0f, -1.0f, -1.0f),  0u};
    light = sampleLight(receiver.position, u, scene.view());
    EXPECT_TRUE(light.valid);
    EXPECT_EQ(light.radiance, vec3(0.0f));
    EXPECT_FALSE(connectLightSample(receiver, u, scene.view()).valid);
}

// KHR_materials_transmission, _ior, _volume at a hit, only where the scene's features include
// them: a volume's front face refracts with η = ior and enters its medium, its back face with
// 1/ior and leaves it; a thin wall keeps η = ior and the medium it is in.
TEST(SharedSurface, GlassSetsEtaByTheSideAndTheMediumAfterTransmission) {
    TinyScene scene;
    Material& m = scene.materials[0];
    m.flags |= MATERIAL_METALLIC_ROUGHNESS;
    m.transmission = 0.75f;
    m.ior = 1.25f;
    m.iorF0 = 0.0123f;
    m.thickness = 1.0f;
    m.attenuationCoefficient = vec3(0.5f, 1.0f, 2.0f);
    const vec3 target(-0.5f, -0.5f, -1.0f), above(0.0f), below(0.0f, 0.0f, -2.0f);
    EXPECT_EQ(hitFrom(scene, above, target).shading.transmission, 0.0f); // feature off
    scene.features[FEATURE_METALLIC_ROUGHNESS] = true;
    scene.features[FEATURE_TRANSMISSION] = true;
    SurfacePoint front = hitFrom(scene, above, target);
    EXPECT_EQ(front.shading.transmission, 0.75f);
    EXPECT_EQ(front.shading.iorF0, 0.0123f);
    EXPECT_EQ(front.shading.eta, 1.25f);
    EXPECT_FALSE(front.shading.thinWalled);
    const vec3 outside(0.0f), inside(0.5f, 1.0f, 2.0f);
    EXPECT_EQ(mediumAfterTransmission(outside, front, scene.view()), inside);
    SurfacePoint back = hitFrom(scene, below, target);
    EXPECT_EQ(back.shading.eta, 1.0f / 1.25f);
    EXPECT_EQ(mediumAfterTransmission(inside, back, scene.view()), outside);
    scene.materials[0].thickness = 0.0f;
    SurfacePoint thin = hitFrom(scene, below, target);
    EXPECT_TRUE(thin.shading.thinWalled);
    EXPECT_EQ(thin.shading.eta, 1.25f);
    EXPECT_EQ(mediumAfterTransmission(inside, thin, scene.view()), inside);
}

// Beer–Lambert: e^(−σd) per channel, 1 for a clear medium even to infinity, 0 for an absorbing
// one to infinity.
TEST(SharedSurface, BeerLambertTransmittance) {
    const vec3 t = beerLambertTransmittance(vec3(0.0f, 1.0f, 2.0f), 0.5f);
    EXPECT_EQ(t.x, 1.0f);
    EXPECT_NEAR(t.y, std::exp(-0.5f), 1e-7f);
    EXPECT_NEAR(t.z, std::exp(-1.0f), 1e-7f);
    EXPECT_EQ(beerLambertTransmittance(vec3(0.0f), VKPT_FAR), vec3(1.0f));
    EXPECT_EQ(beerLambertTransmittance(vec3(1e-3f), VKPT_FAR), vec3(0.0f));
    EXPECT_EQ(segmentLength(vec3(0.0f, 3.0f, 4.0f), 0.5f), 2.5f);
    EXPECT_EQ(segmentLength(vec3(1.0f, 0.0f, 0.0f), VKPT_FAR), VKPT_FAR);
}

} // namespace
} // namespace vkpt::gpu::surface_test
