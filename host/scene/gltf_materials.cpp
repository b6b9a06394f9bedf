// gltf_materials.cpp — reads the core material factors, the base colour, metallic-roughness and
// emissive textures, KHR_materials_emissive_strength, KHR_materials_specular,
// KHR_materials_clearcoat (not its clearcoatNormalTexture) and KHR_materials_sheen.
#include "scene/gltf_materials.h"

#include <algorithm>
#include <cmath>

#include "scene/gltf_document.h"
#include "scene/gltf_values.h"

namespace vkpt::gltf {
namespace {

constexpr const char* kEmissiveStrength = "KHR_materials_emissive_strength";
constexpr const char* kSpecular = "KHR_materials_specular";
constexpr const char* kClearcoat = "KHR_materials_clearcoat";
constexpr const char* kSheen = "KHR_materials_sheen";

std::string materialName(std::size_t index) {
    return "material " + std::to_string(index);
}

// KHR_materials_emissive_strength scales emissiveFactor past the core range [0, 1].
double emissiveStrength(const tinygltf::Material& material, std::size_t index) {
    const auto extension = material.extensions.find(kEmissiveStrength);
    if (extension == material.extensions.end()) return 1.0;
    // Has() before Get(): Get() asserts that the value is an object.
    if (!extension->second.Has("emissiveStrength")) return 1.0; // the extension's default
    const tinygltf::Value& strength = extension->second.Get("emissiveStrength");
    const double value = strength.IsNumber() ? strength.GetNumberAsDouble() : -1.0;
    if (!(value >= 0.0)) {
        throw GltfProblem(materialName(index) + ": " + kEmissiveStrength +
                          ": emissiveStrength must be a number >= 0");
    }
    return value;
}

AlphaMode alphaModeOf(const tinygltf::Material& material, std::size_t index) {
    if (material.alphaMode == "OPAQUE") return AlphaMode::Opaque;
    if (material.alphaMode == "MASK") return AlphaMode::Mask;
    if (material.alphaMode == "BLEND") return AlphaMode::Blend;
    throw GltfProblem(materialName(index) + ": unknown alphaMode '" + material.alphaMode + "'");
}

glm::vec3 emissionOf(const tinygltf::Material& material, std::size_t index) {
    const std::vector<double>& factor = material.emissiveFactor; // tinygltf ensures 3 entries
    const double strength = emissiveStrength(material, index);
    return glm::vec3(glm::dvec3(factor[0], factor[1], factor[2]) * strength);
}

template <typename Vec> bool isFinite(const Vec& v) {
    return !glm::any(glm::isnan(v)) && !glm::any(glm::isinf(v));
}

// Emission and albedo feed light sampling; an infinity there would poison every pixel.
void checkFinite(const SceneMaterial& material, std::size_t index) {
    const bool finite = isFinite(material.baseColor) && isFinite(material.emission) &&
                        std::isfinite(material.metallic) && std::isfinite(material.roughness) &&
                        std::isfinite(material.alphaCutoff);
    if (!finite) throw GltfProblem(materialName(index) + ": a factor is not a finite float");
    // Negative albedo or emission has no physical meaning and makes radiance negative, which
    // the luminance statistics of adaptive sampling cannot take.
    if (glm::any(glm::lessThan(material.baseColor, glm::vec4(0.0f))) ||
        glm::any(glm::lessThan(material.emission, glm::vec3(0.0f)))) {
        throw GltfProblem(materialName(index) + ": a color factor is negative");
    }
}

// KHR_materials_specular: the strength (specularFactor, in [0, 1]) and colour
// (specularColorFactor, >= 0) of the dielectric specular layer; absent, both are 1, the core
// glTF model. Its textures are not read (materialNotes says so).
void readSpecular(const tinygltf::Material& material, std::size_t index, SceneMaterial& converted) {
    const tinygltf::Value* extension = findExtension(material.extensions, kSpecular);
    if (extension == nullptr) return;
    const std::string where = materialName(index) + ": " + kSpecular;
    const double factor = readNumber(*extension, "specularFactor", 1.0, where);
    if (factor < 0.0 || factor > 1.0) {
        throw GltfProblem(where + ": specularFactor must be in [0, 1]");
    }
    const std::vector<double> color =
        readNumbers(*extension, "specularColorFactor", {1.0, 1.0, 1.0}, where);
    if (color[0] < 0.0 || color[1] < 0.0 || color[2] < 0.0) {
        throw GltfProblem(where + ": specularColorFactor must not be negative");
    }
    converted.specular = static_cast<float>(factor);
    converted.specularColor = glm::vec3(glm::dvec3(color[0], color[1], color[2]));
}

double readUnitNumber(const tinygltf::Value& extension, const std::string& key,
                      const std::string& where) {
    const double value = readNumber(extension, key, 0.0, where);
    if (value < 0.0 || value > 1.0) throw GltfProblem(where + ": " + key + " must be in [0, 1]");
    return value;
}

// A textureInfo inside an extension, which tinygltf leaves as JSON, read like the core ones.
TextureReference readExtensionTexture(const tinygltf::Value& extension, const std::string& key,
                                      TextureTable& textures, const std::string& where) {
    const tinygltf::Value* member = findMember(extension, key);
    if (member == nullptr) return {};
    const std::string place = where + ": " + key;
    tinygltf::TextureInfo info;
    info.index = readIndex(*member, "index", place);
    if (info.index < 0) throw GltfProblem(place + ": index is missing");
    info.texCoord = std::max(0, readIndex(*member, "texCoord", place));
    if (const tinygltf::Value* extensions = findMember(*member, "extensions")) {
        for (const std::string& name : extensions->Keys())
            info.extensions[name] = extensions->Get(name);
    }
    return readTextureReference(info, textures, place);
}

// KHR_materials_clearcoat: the layer's strength (R of its texture) and roughness (G of its
// texture). clearcoatNormalTexture is not read (materialNotes says so).
void readClearcoat(const tinygltf::Material& material, std::size_t index, TextureTable& textures,
                   SceneMaterial& converted) {
    const tinygltf::Value* extension = findExtension(material.extensions, kClearcoat);
    if (extension == nullptr) return;
    const std::string where = materialName(index) + ": " + kClearcoat;
    converted.clearcoat = float(readUnitNumber(*extension, "clearcoatFactor", where));
    converted.clearcoatRoughness =
        float(readUnitNumber(*extension, "clearcoatRoughnessFactor", where));
    converted.clearcoatTexture =
        readExtensionTexture(*extension, "clearcoatTexture", textures, where);
    converted.clearcoatRoughnessTexture =
        readExtensionTexture(*extension, "clearcoatRoughnessTexture", textures, where);
}

// KHR_materials_sheen: the sheen colour (RGB of its sRGB texture) and roughness (A of its
// texture), each in [0, 1].
void readSheen(const tinygltf::Material& material, std::size_t index, TextureTable& textures,
               SceneMaterial& converted) {
    const tinygltf::Value* extension = findExtension(material.extensions, kSheen);
    if (extension == nullptr) return;
    const std::string where = materialName(index) + ": " + kSheen;
    const std::vector<double> color =
        readNumbers(*extension, "sheenColorFactor", {0.0, 0.0, 0.0}, where);
    for (double c : color)
        if (c < 0.0 || c > 1.0) throw GltfProblem(where + ": sheenColorFactor must be in [0, 1]");
    converted.sheenColor = glm::vec3(glm::dvec3(color[0], color[1], color[2]));
    converted.sheenRoughness = float(readUnitNumber(*extension, "sheenRoughnessFactor", where));
    converted.sheenColorTexture =
        readExtensionTexture(*extension, "sheenColorTexture", textures, where);
    converted.sheenRoughnessTexture =
        readExtensionTexture(*extension, "sheenRoughnessTexture", textures, where);
}

void readTextures(const tinygltf::Material& material, std::size_t index, TextureTable& textures,
                  SceneMaterial& converted) {
    const std::string where = materialName(index) + ": ";
    const tinygltf::PbrMetallicRoughness& pbr = material.pbrMetallicRoughness;
    converted.baseColorTexture =
        readTextureReference(pbr.baseColorTexture, textures, where + "baseColorTexture");
    converted.metallicRoughnessTexture = readTextureReference(
        pbr.metallicRoughnessTexture, textures, where + "metallicRoughnessTexture");
    converted.emissiveTexture =
        readTextureReference(material.emissiveTexture, textures, where + "emissiveTexture");
}

SceneMaterial convertMaterial(const tinygltf::Material& material, std::size_t index,
                              TextureTable& textures) {
    const tinygltf::PbrMetallicRoughness& pbr = material.pbrMetallicRoughness;
    const std::vector<double>& base = pbr.baseColorFactor; // tinygltf ensures 4 entries
    SceneMaterial converted;
    converted.name = material.name;
    converted.baseColor = glm::vec4(glm::dvec4(base[0], base[1], base[2], base[3]));
    converted.emission = emissionOf(material, index);
    converted.metallic = static_cast<float>(pbr.metallicFactor);
    converted.roughness = static_cast<float>(pbr.roughnessFactor);
    converted.doubleSided = material.doubleSided;
    converted.alphaMode = alphaModeOf(material, index);
    converted.alphaCutoff = static_cast<float>(material.alphaCutoff);
    checkFinite(converted, index);
    readSpecular(material, index, converted);
    readTextures(material, index, textures, converted);
    readClearcoat(material, index, textures, converted);
    readSheen(material, index, textures, converted);
    return converted;
}

bool hasSpecularTexture(const tinygltf::Material& material) {
    const tinygltf::Value* extension = findExtension(material.extensions, kSpecular);
    return extension != nullptr && (findMember(*extension, "specularTexture") != nullptr ||
                                    findMember(*extension, "specularColorTexture") != nullptr);
}

bool hasClearcoatNormalTexture(const tinygltf::Material& material) {
    const tinygltf::Value* extension = findExtension(material.extensions, kClearcoat);
    return extension != nullptr && findMember(*extension, "clearcoatNormalTexture") != nullptr;
}

std::string materialCount(std::size_t count) {
    return std::to_string(count) + (count == 1 ? " material" : " materials");
}

} // namespace

std::vector<SceneMaterial> convertMaterials(const tinygltf::Model& model, TextureTable& textures) {
    std::vector<SceneMaterial> materials;
    materials.reserve(model.materials.size());
    for (std::size_t i = 0; i < model.materials.size(); ++i) {
        materials.push_back(convertMaterial(model.materials[i], i, textures));
    }
    return materials;
}

std::vector<std::string> materialNotes(const tinygltf::Model& model) {
    std::size_t specularTextures = 0, clearcoatNormals = 0;
    for (const tinygltf::Material& material : model.materials) {
        specularTextures += hasSpecularTexture(material) ? 1 : 0;
        clearcoatNormals += hasClearcoatNormalTexture(material) ? 1 : 0;
    }
    std::vector<std::string> notes;
    if (specularTextures > 0)
        notes.push_back("ignoring the " + std::string(kSpecular) + " textures of " +
                        materialCount(specularTextures) + " (only its factors are supported)");
    if (clearcoatNormals > 0)
        notes.push_back("ignoring the " + std::string(kClearcoat) + " clearcoatNormalTexture of " +
                        materialCount(clearcoatNormals) +
                        " (not supported: the clearcoat uses the surface's shading normal)");
    return notes;
}

SceneMaterial defaultMaterial() {
    SceneMaterial material; // SceneMaterial's defaults are the glTF defaults
    material.name = "glTF default material";
    return material;
}

} // namespace vkpt::gltf
