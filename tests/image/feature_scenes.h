// feature_scenes.h — small scenes built in memory, each exercising some of the scene model's
// features (docs/scene-model.md): metallic-roughness materials, spheres (lit, lighting and
// textured), textures (base colour, metallic-roughness, emissive, transformed, nearest and
// bilinear), alpha MASK cut-outs, punctual lights, and the environment (constant and map).
// The image tests render them on both executors and with specialised and general kernels.
// The builders live in their own namespace: tests/support/scene_builder.h has functions of the
// same names for untextured scenes.
#pragma once

#include <cmath>
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "../support/reference_render.h"
#include "prepare/prepared_scene.h"
#include "scene/camera.h"
#include "scene/scene.h"

namespace vkpt::test::feature_scenes {

struct MaterialSpec {
    glm::vec3 baseColor{0.7f};
    glm::vec3 emission{0.0f};
    float metallic = 0.0f;
    float roughness = 1.0f;
    float specular = 0.0f; // 0 with metallic 0: the Lambertian kind
    bool doubleSided = false;
};

inline std::uint32_t addMaterial(Scene& scene, const MaterialSpec& spec) {
    SceneMaterial m;
    m.name = "material " + std::to_string(scene.materials.size());
    m.baseColor = glm::vec4(spec.baseColor, 1.0f);
    m.emission = spec.emission;
    m.metallic = spec.metallic;
    m.roughness = spec.roughness;
    m.specular = spec.specular;
    m.doubleSided = spec.doubleSided;
    scene.materials.push_back(m);
    return std::uint32_t(scene.materials.size() - 1);
}

// One triangle with flat normals and the given texture coordinates (texcoords are kept only
// once some triangle has them; earlier triangles get (0, 0)).
inline void addTriangle(Scene& scene, glm::vec3 a, glm::vec3 b, glm::vec3 c, std::uint32_t material,
                        glm::vec2 ta = glm::vec2(0.0f), glm::vec2 tb = glm::vec2(0.0f),
                        glm::vec2 tc = glm::vec2(0.0f)) {
    glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
    for (glm::vec3 p : {a, b, c}) {
        scene.positions.push_back(p);
        scene.normals.push_back(n);
    }
    scene.materialIndices.push_back(material);
    scene.texcoords.insert(scene.texcoords.end(), {ta, tb, tc});
}

// A quad a b c d, counter-clockwise seen from its front, uv (0,0) (1,0) (1,1) (0,1) × uvScale.
inline void addQuad(Scene& scene, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d,
                    std::uint32_t material, float uvScale = 1.0f) {
    glm::vec2 ta(0.0f), tb(uvScale, 0.0f), tc(uvScale), td(0.0f, uvScale);
    addTriangle(scene, a, b, c, material, ta, tb, tc);
    addTriangle(scene, a, c, d, material, ta, tc, td);
}

inline void addSphere(Scene& scene, glm::vec3 centre, float radius, std::uint32_t material) {
    scene.spheres.push_back({centre, radius, material});
}

// width × height RGBA8 texels from a function of (x, y), packed R in the low byte.
template <typename F>
int addTexture(Scene& scene, std::uint32_t width, std::uint32_t height, F texel,
               bool nearest = false, TextureWrap wrap = TextureWrap::Repeat) {
    SceneImage image;
    image.name = "image " + std::to_string(scene.images.size());
    image.width = width;
    image.height = height;
    for (std::uint32_t y = 0; y < height; ++y)
        for (std::uint32_t x = 0; x < width; ++x) {
            glm::uvec4 c = texel(x, y);
            image.texels.push_back(c.r | (c.g << 8) | (c.b << 16) | (c.a << 24));
        }
    scene.images.push_back(image);
    SceneTexture texture;
    texture.image = int(scene.images.size() - 1);
    texture.wrapS = wrap;
    texture.wrapT = wrap == TextureWrap::Repeat ? TextureWrap::MirroredRepeat : wrap;
    texture.nearest = nearest;
    scene.textures.push_back(texture);
    return int(scene.textures.size() - 1);
}

inline int addChecker(Scene& scene, glm::uvec4 a, glm::uvec4 b, std::uint32_t size = 8,
                      bool nearest = false) {
    return addTexture(
        scene, size, size, [=](std::uint32_t x, std::uint32_t y) { return (x + y) % 2 ? a : b; },
        nearest);
}

// A floor (y = 0, facing up) and a back wall (z = -2, facing +z) in [-2, 2], and a camera on
// +z looking at them slightly from above.
inline Scene openCorner(std::uint32_t floorMaterial, std::uint32_t wallMaterial,
                        std::vector<SceneMaterial> materials) {
    Scene scene;
    scene.materials = std::move(materials);
    addQuad(scene, {-2, 0, 2}, {2, 0, 2}, {2, 0, -2}, {-2, 0, -2}, floorMaterial, 3.0f);
    addQuad(scene, {-2, 0, -2}, {2, 0, -2}, {2, 4, -2}, {-2, 4, -2}, wallMaterial, 2.0f);
    SceneCamera camera;
    camera.position = {0.0f, 1.6f, 5.5f};
    camera.forward = glm::normalize(glm::vec3(0.0f, -0.25f, -1.0f));
    camera.up =
        glm::normalize(glm::cross(glm::cross(camera.forward, glm::vec3(0, 1, 0)), camera.forward));
    camera.yfov = 0.9f;
    scene.cameras.push_back(camera);
    return scene;
}

inline Scene cornerWithMaterials() {
    Scene scene;
    std::uint32_t floor = addMaterial(scene, {{0.6f, 0.6f, 0.55f}});
    std::uint32_t wall = addMaterial(scene, {{0.5f, 0.55f, 0.7f}});
    return openCorner(floor, wall, scene.materials);
}

// Spheres: a Lambertian one, a rough metal, a glossy dielectric, and an emitting sphere that
// lights them with a small emitting quad (two emitters: the selection CDF).
inline Scene sphereScene() {
    Scene scene = cornerWithMaterials();
    std::uint32_t diffuse = addMaterial(scene, {{0.8f, 0.3f, 0.2f}});
    std::uint32_t metal = addMaterial(scene, {{0.9f, 0.8f, 0.5f}, {}, 1.0f, 0.35f, 1.0f});
    std::uint32_t glossy = addMaterial(scene, {{0.2f, 0.4f, 0.8f}, {}, 0.0f, 0.2f, 1.0f});
    std::uint32_t lamp = addMaterial(scene, {glm::vec3(0.0f), {6.0f, 5.5f, 5.0f}});
    std::uint32_t panel =
        addMaterial(scene, {glm::vec3(0.0f), {3.0f, 3.0f, 4.0f}, 0.0f, 1.0f, 0.0f, true});
    addSphere(scene, {-1.1f, 0.6f, -0.4f}, 0.6f, diffuse);
    addSphere(scene, {0.3f, 0.5f, 0.3f}, 0.5f, metal);
    addSphere(scene, {1.3f, 0.45f, -0.8f}, 0.45f, glossy);
    addSphere(scene, {0.0f, 2.8f, -0.5f}, 0.3f, lamp);
    addQuad(scene, {-1.8f, 3.0f, 1.0f}, {-1.0f, 3.0f, 1.0f}, {-1.0f, 2.2f, 1.0f},
            {-1.8f, 2.2f, 1.0f}, panel);
    scene.texcoords.clear(); // no textures
    return scene;
}

// Textures: a bilinear checker on the floor (repeat, mirrored), a nearest checker with a
// transform on the wall, metallic-roughness from a texture on a sphere, an emissive texture on
// the light panel and a textured emitting sphere.
inline Scene textureScene() {
    Scene scene = cornerWithMaterials();
    int checker = addChecker(scene, {230, 220, 200, 255}, {40, 60, 90, 255});
    int stripes = addChecker(scene, {200, 30, 30, 255}, {250, 250, 250, 255}, 4, true);
    int metalRough = addTexture(scene, 8, 8, [](std::uint32_t x, std::uint32_t y) {
        return glm::uvec4(0, 30 * x, 255 - 30 * y, 255); // G roughness, B metallic
    });
    int glow = addTexture(scene, 4, 4, [](std::uint32_t x, std::uint32_t y) {
        return glm::uvec4(60 * x + 50, 255, 60 * y + 50, 255);
    });
    scene.materials[0].baseColorTexture.texture = checker;
    scene.materials[1].baseColorTexture.texture = stripes;
    // KHR_texture_transform: a rotation and scale of the wall's coordinates.
    scene.materials[1].baseColorTexture.transform = glm::mat3(
        glm::vec3(0.8f, 0.6f, 0.0f), glm::vec3(-0.6f, 0.8f, 0.0f), glm::vec3(0.25f, 0.1f, 1.0f));
    std::uint32_t metal = addMaterial(scene, {{0.9f, 0.9f, 0.9f}, {}, 1.0f, 1.0f, 1.0f});
    scene.materials[metal].metallicRoughnessTexture.texture = metalRough;
    std::uint32_t ball = addMaterial(scene, {glm::vec3(1.0f)});
    scene.materials[ball].baseColorTexture.texture = checker;
    std::uint32_t panel = addMaterial(scene, {glm::vec3(0.0f), {4.0f, 4.0f, 4.0f}});
    scene.materials[panel].emissiveTexture.texture = glow;
    std::uint32_t lamp = addMaterial(scene, {glm::vec3(0.0f), {5.0f, 5.0f, 5.0f}});
    scene.materials[lamp].emissiveTexture.texture = stripes;
    addSphere(scene, {0.6f, 0.7f, -0.3f}, 0.7f, metal);
    addSphere(scene, {-1.2f, 0.5f, 0.2f}, 0.5f, ball);
    addSphere(scene, {1.5f, 2.6f, 0.0f}, 0.35f, lamp);
    addQuad(scene, {-1.8f, 3.2f, -0.7f}, {-0.6f, 3.2f, -0.7f}, {-0.6f, 3.2f, 0.5f},
            {-1.8f, 3.2f, 0.5f}, panel); // facing down
    return scene;
}

// Alpha MASK: a cut-out screen (textured alpha) between a light and the floor, a cut-out sphere,
// and a factor-only masked quad that is wholly transparent.
inline Scene alphaMaskScene() {
    Scene scene = cornerWithMaterials();
    int holes = addTexture(
        scene, 8, 8,
        [](std::uint32_t x, std::uint32_t y) {
            return glm::uvec4(200, 200, 200, (x / 2 + y / 2) % 2 ? 255 : 0);
        },
        true);
    std::uint32_t screen = addMaterial(scene, {{0.9f, 0.9f, 0.9f}, {}, 0.0f, 1.0f, 0.0f, true});
    scene.materials[screen].alphaMode = AlphaMode::Mask;
    scene.materials[screen].baseColorTexture.texture = holes;
    std::uint32_t ghost = addMaterial(scene, {{0.9f, 0.1f, 0.1f}});
    scene.materials[ghost].alphaMode = AlphaMode::Mask;
    scene.materials[ghost].baseColor.a = 0.2f;
    std::uint32_t light = addMaterial(scene, {glm::vec3(0.0f), {8.0f, 8.0f, 8.0f}});
    addQuad(scene, {-1.5f, 1.6f, 1.0f}, {1.5f, 1.6f, 1.0f}, {1.5f, 1.6f, -1.5f},
            {-1.5f, 1.6f, -1.5f}, screen, 2.0f);
    addQuad(scene, {-1.0f, 0.3f, 1.6f}, {1.0f, 0.3f, 1.6f}, {1.0f, 1.3f, 1.6f}, {-1.0f, 1.3f, 1.6f},
            ghost);
    addSphere(scene, {0.8f, 0.5f, -0.2f}, 0.5f, screen);
    addQuad(scene, {-0.7f, 3.0f, -0.9f}, {0.7f, 3.0f, -0.9f}, {0.7f, 3.0f, 0.5f},
            {-0.7f, 3.0f, 0.5f}, light); // facing down
    return scene;
}

// KHR_lights_punctual only: a point light, a spot light with a soft edge and range, and a
// directional light, over Lambertian and glossy surfaces.
inline Scene punctualScene() {
    Scene scene = cornerWithMaterials();
    std::uint32_t glossy = addMaterial(scene, {{0.7f, 0.7f, 0.7f}, {}, 0.3f, 0.4f, 1.0f});
    addSphere(scene, {0.0f, 0.7f, -0.5f}, 0.7f, glossy);
    scene.texcoords.clear();
    SceneLight point;
    point.kind = LightKind::Point;
    point.position = {-1.2f, 2.0f, 1.0f};
    point.intensity = {4.0f, 3.0f, 2.0f};
    SceneLight spot;
    spot.kind = LightKind::Spot;
    spot.position = {1.4f, 3.0f, 0.5f};
    spot.direction = glm::normalize(glm::vec3(-0.3f, -1.0f, -0.4f));
    spot.intensity = {10.0f, 10.0f, 14.0f};
    spot.range = 6.0f;
    spot.innerConeAngle = 0.2f;
    spot.outerConeAngle = 0.5f;
    SceneLight sun;
    sun.kind = LightKind::Directional;
    sun.direction = glm::normalize(glm::vec3(0.4f, -1.0f, -0.6f));
    sun.intensity = {0.8f, 0.7f, 0.6f};
    scene.lights = {point, spot, sun};
    return scene;
}

// The environment alone (constant colour) or as a map with a bright sun-like spot, lighting
// an open corner with spheres; `withMap` picks which.
inline Scene environmentScene(bool withMap) {
    Scene scene = cornerWithMaterials();
    std::uint32_t metal = addMaterial(scene, {{0.95f, 0.9f, 0.8f}, {}, 1.0f, 0.25f, 1.0f});
    std::uint32_t diffuse = addMaterial(scene, {{0.3f, 0.7f, 0.3f}});
    addSphere(scene, {0.7f, 0.6f, -0.2f}, 0.6f, metal);
    addSphere(scene, {-0.9f, 0.5f, 0.4f}, 0.5f, diffuse);
    scene.texcoords.clear();
    if (!withMap) {
        scene.environment.radiance = {0.6f, 0.7f, 0.9f};
        return scene;
    }
    scene.environment.radiance = glm::vec3(1.0f);
    scene.environment.width = 32;
    scene.environment.height = 16;
    for (std::uint32_t y = 0; y < 16; ++y)
        for (std::uint32_t x = 0; x < 32; ++x) {
            float sky = 0.2f + 0.05f * float(y);
            bool sun = x >= 20 && x <= 21 && y >= 3 && y <= 4;
            scene.environment.texels.push_back(sun ? glm::vec3(60.0f, 55.0f, 45.0f)
                                                   : glm::vec3(sky * 0.8f, sky * 0.9f, sky));
        }
    return scene;
}

// Everything at once: the texture scene under punctual lights and an environment map.
inline Scene everythingScene() {
    Scene scene = textureScene();
    Scene lights = punctualScene();
    scene.lights = lights.lights;
    Scene sky = environmentScene(true);
    scene.environment = sky.environment;
    scene.environment.radiance = glm::vec3(0.3f);
    scene.materials[0].alphaMode = AlphaMode::Mask; // the floor's dark squares stay (alpha 1)
    return scene;
}

struct NamedScene {
    std::string name;
    Scene (*make)();
};

// For gtest's messages: the scene's name rather than its bytes.
inline void PrintTo(const NamedScene& scene, std::ostream* out) {
    *out << scene.name;
}

inline std::vector<NamedScene> featureScenes() {
    return {{"spheres", sphereScene},
            {"textures", textureScene},
            {"alpha_mask", alphaMaskScene},
            {"punctual", punctualScene},
            {"environment_colour", [] { return environmentScene(false); }},
            {"environment_map", [] { return environmentScene(true); }},
            {"everything", everythingScene}};
}

// As loadTestScene does for a file: prepared specialised or general.
inline LoadedTestScene prepareTestScene(Scene scene, bool general = false) {
    LoadedTestScene loaded{std::move(scene), {}};
    PrepareOptions options;
    options.general = general;
    loaded.prepared = prepareScene(loaded.scene, options);
    return loaded;
}

} // namespace vkpt::test::feature_scenes
