// scene_features.cpp — the feature set of a loaded scene, from what its triangles and spheres
// actually use: a material, texture or light kind no primitive reaches is not a feature.
#include "scene/scene_features.h"

#include <algorithm>
#include <cstring>
#include <set>
#include <vector>

#include "shared/intersect.h"
#include "shared/sampling.h"

namespace vkpt {
namespace {

// buildEmitters (host/prepare/emitters.h) lists an emitting triangle once however often the
// soup repeats it: same corners in the same cyclic order (compared bit for bit, −0 as +0) and
// same material. The count here applies the same rule, so that it is the length of that list.
using SurfaceKey = std::array<std::uint32_t, 10>;

SurfaceKey surfaceKey(const Scene& scene, std::size_t triangle) {
    std::array<std::array<std::uint32_t, 3>, 3> corners{};
    for (std::size_t k = 0; k < 3; ++k) {
        const glm::vec3 canonical = scene.positions[3 * triangle + k] + glm::vec3(0.0f);
        std::memcpy(corners[k].data(), &canonical, sizeof(corners[k]));
    }
    const auto first = static_cast<std::size_t>(std::min_element(corners.begin(), corners.end()) -
                                                corners.begin());
    SurfaceKey key{};
    for (std::size_t k = 0; k < 3; ++k)
        for (std::size_t c = 0; c < 3; ++c)
            key[3 * k + c] = corners[(first + k) % 3][c];
    key[9] = scene.materialIndices[triangle];
    return key;
}

bool emits(const SceneMaterial& material) {
    return gpu::luminance(material.emission) > 0.0f;
}

std::vector<char> usedMaterials(const Scene& scene) {
    std::vector<char> used(scene.materials.size(), 0);
    for (std::uint32_t material : scene.materialIndices)
        used[material] = 1;
    for (const SceneMesh& mesh : scene.meshes) // the loader keeps only meshes it places
        for (std::uint32_t material : mesh.materialIndices)
            used[material] = 1;
    for (const SceneInstance& instance : scene.instances)
        if (instance.material != SceneInstance::kKeepMaterial) used[instance.material] = 1;
    for (const SceneSphere& sphere : scene.spheres)
        used[sphere.material] = 1;
    return used;
}

void addMaterial(const SceneMaterial& material, SceneFeatures& features) {
    (material.isDiffuseOnly() ? features.diffuseMaterials : features.metallicRoughnessMaterials) =
        true;
    features.baseColorTextures |= material.baseColorTexture.texture >= 0;
    features.metallicRoughnessTextures |= material.metallicRoughnessTexture.texture >= 0;
    features.emissiveTextures |= material.emissiveTexture.texture >= 0;
    features.normalTextures |= material.hasNormalMap();
    features.transmissionTextures |= material.transmissionTexture.texture >= 0;
    // A layer's textures count only with the layer: a zero factor zeroes what they would scale.
    if (material.hasClearcoat()) {
        features.clearcoatMaterials = true;
        features.clearcoatTextures |= material.clearcoatTexture.texture >= 0 ||
                                      material.clearcoatRoughnessTexture.texture >= 0;
    }
    if (material.hasSheen()) {
        features.sheenMaterials = true;
        features.sheenTextures |=
            material.sheenColorTexture.texture >= 0 || material.sheenRoughnessTexture.texture >= 0;
    }
    features.specularTextures |= material.hasSpecularTextures();
    if (material.hasIridescence()) {
        features.iridescence = true;
        features.iridescenceTextures |= material.iridescenceTexture.texture >= 0 ||
                                        material.iridescenceThicknessTexture.texture >= 0;
    }
    if (material.hasDiffuseTransmission()) {
        features.diffuseTransmission = true;
        features.diffuseTransmissionTextures |=
            material.diffuseTransmissionTexture.texture >= 0 ||
            material.diffuseTransmissionColorTexture.texture >= 0;
    }
    features.dispersion |= material.hasDispersion();
    if (material.hasAnisotropy()) {
        features.anisotropy = true;
        features.anisotropyTextures |= material.anisotropyTexture.texture >= 0;
    }
    features.alphaMask |= material.alphaMode == AlphaMode::Mask;
    features.doubleSided |= material.doubleSided;
    features.transmission |= material.usesDielectricExtensions();
}

std::uint32_t emittingTriangles(const Scene& scene) {
    std::set<SurfaceKey> surfaces;
    for (std::size_t t = 0; t < scene.triangleCount(); ++t) {
        if (!emits(scene.materials[scene.materialIndices[t]])) continue;
        const glm::vec3* p = &scene.positions[3 * t];
        if (!(gpu::triangleAreaOf(p[0], p[1], p[2]) > 0.0f)) continue; // never hit, never sampled
        surfaces.insert(surfaceKey(scene, t));
    }
    return static_cast<std::uint32_t>(surfaces.size());
}

std::uint32_t emittingSpheres(const Scene& scene) {
    return static_cast<std::uint32_t>(
        std::count_if(scene.spheres.begin(), scene.spheres.end(), [&](const SceneSphere& s) {
            return s.radius > 0.0f && emits(scene.materials[s.material]);
        }));
}

void addLights(const Scene& scene, SceneFeatures& features) {
    for (const SceneLight& light : scene.lights) {
        features.pointLights |= light.kind == LightKind::Point;
        features.spotLights |= light.kind == LightKind::Spot;
        features.directionalLights |= light.kind == LightKind::Directional;
        // A black light carries no power, so light sampling leaves it out.
        if (gpu::luminance(light.intensity) > 0.0f) ++features.emitterCount;
    }
}

void appendIf(bool condition, const char* name, std::vector<std::string>& names) {
    if (condition) names.emplace_back(name);
}

std::string joined(const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& name : names)
        text += (text.empty() ? "" : ", ") + name;
    return text;
}

} // namespace

std::array<bool, FEATURE_COUNT> SceneFeatures::kernelFeatures() const {
    std::array<bool, FEATURE_COUNT> on{};
    on[FEATURE_METALLIC_ROUGHNESS] = metallicRoughnessMaterials;
    on[FEATURE_TEXTURES] = textures();
    on[FEATURE_ALPHA_MASK] = alphaMask;
    on[FEATURE_SPHERES] = spheres;
    on[FEATURE_PUNCTUAL_LIGHTS] = punctualLights();
    on[FEATURE_ENVIRONMENT] = environment;
    on[FEATURE_ENVIRONMENT_MAP] = environmentMap;
    on[FEATURE_EMITTER_CDF] = emitterCdf();
    on[FEATURE_DOUBLE_SIDED] = doubleSided;
    on[FEATURE_NORMAL_MAPS] = normalTextures;
    on[FEATURE_TRANSMISSION] = transmission;
    on[FEATURE_CLEARCOAT] = clearcoatMaterials;
    on[FEATURE_SHEEN] = sheenMaterials;
    on[FEATURE_INSTANCES] = instances;
    on[FEATURE_LIGHT_TREE] = lightTree;
    on[FEATURE_SPECULAR_TEXTURES] = specularTextures;
    on[FEATURE_ANISOTROPY] = anisotropy;
    on[FEATURE_IRIDESCENCE] = iridescence;
    on[FEATURE_DIFFUSE_TRANSMISSION] = diffuseTransmission;
    on[FEATURE_DISPERSION] = dispersion;
    return on;
}

SceneFeatures analyseScene(const Scene& scene) {
    SceneFeatures features;
    const std::vector<char> used = usedMaterials(scene);
    for (std::size_t m = 0; m < scene.materials.size(); ++m)
        if (used[m]) addMaterial(scene.materials[m], features);
    features.triangles = scene.triangleCount() > 0 || !scene.instances.empty();
    features.spheres = !scene.spheres.empty();
    features.instances = !scene.instances.empty();
    const std::uint32_t triangles = emittingTriangles(scene);
    const std::uint32_t spheres = emittingSpheres(scene);
    features.emissiveTriangles = triangles > 0;
    features.emissiveSpheres = spheres > 0;
    features.emitterCount = triangles + spheres;
    addLights(scene, features);
    features.environment = scene.environment.present();
    features.environmentMap = features.environment && scene.environment.hasMap();
    if (features.environment) ++features.emitterCount;
    return features;
}

SceneFeatures generalFeatures(const SceneFeatures& used) {
    SceneFeatures all;
    all.diffuseMaterials = all.metallicRoughnessMaterials = true;
    all.baseColorTextures = all.metallicRoughnessTextures = all.emissiveTextures = true;
    all.normalTextures = all.transmissionTextures = true;
    all.alphaMask = all.doubleSided = all.transmission = true;
    all.clearcoatMaterials = all.sheenMaterials = true;
    all.clearcoatTextures = all.sheenTextures = all.specularTextures = true;
    all.anisotropy = all.anisotropyTextures = true;
    all.iridescence = all.iridescenceTextures = true;
    all.diffuseTransmission = all.diffuseTransmissionTextures = all.dispersion = true;
    all.triangles = all.spheres = true;
    all.emissiveTriangles = all.emissiveSpheres = true;
    all.pointLights = all.spotLights = all.directionalLights = true;
    all.environment = all.environmentMap = true;
    all.instances = used.instances;
    all.lightTree = used.lightTree;
    all.emitterCount = used.emitterCount;
    all.general = true;
    return all;
}

std::string describeFeatures(const SceneFeatures& features) {
    std::vector<std::string> names;
    appendIf(features.diffuseMaterials, "diffuse", names);
    appendIf(features.metallicRoughnessMaterials, "metallic-roughness", names);
    appendIf(features.clearcoatMaterials, "clearcoat", names);
    appendIf(features.sheenMaterials, "sheen", names);
    appendIf(features.anisotropy, "anisotropy", names);
    appendIf(features.iridescence, "iridescence", names);
    appendIf(features.diffuseTransmission, "diffuse transmission", names);
    appendIf(features.dispersion, "dispersion", names);
    std::vector<std::string> textures;
    appendIf(features.baseColorTextures, "base colour", textures);
    appendIf(features.metallicRoughnessTextures, "metallic-roughness", textures);
    appendIf(features.emissiveTextures, "emissive", textures);
    appendIf(features.normalTextures, "normal", textures);
    appendIf(features.transmissionTextures, "transmission", textures);
    appendIf(features.clearcoatTextures, "clearcoat", textures);
    appendIf(features.sheenTextures, "sheen", textures);
    appendIf(features.specularTextures, "specular", textures);
    appendIf(features.anisotropyTextures, "anisotropy", textures);
    appendIf(features.iridescenceTextures, "iridescence", textures);
    appendIf(features.diffuseTransmissionTextures, "diffuse transmission", textures);
    if (!textures.empty()) names.push_back("textures (" + joined(textures) + ")");
    appendIf(features.alphaMask, "alpha mask", names);
    appendIf(features.doubleSided, "double-sided", names);
    appendIf(features.transmission, "transmission", names);
    appendIf(features.triangles, "triangles", names);
    appendIf(features.spheres, "spheres", names);
    appendIf(features.instances, "instances", names);
    appendIf(features.emissiveTriangles, "emissive triangles", names);
    appendIf(features.emissiveSpheres, "emissive spheres", names);
    appendIf(features.pointLights, "point lights", names);
    appendIf(features.spotLights, "spot lights", names);
    appendIf(features.directionalLights, "directional lights", names);
    appendIf(features.environment && !features.environmentMap, "environment colour", names);
    appendIf(features.environmentMap, "environment map", names);
    names.push_back(std::to_string(features.emitterCount) +
                    (features.emitterCount == 1 ? " emitter" : " emitters") +
                    (features.lightTree ? " (light BVH)" : ""));
    return joined(names);
}

} // namespace vkpt
