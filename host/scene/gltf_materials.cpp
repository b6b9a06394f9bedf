// gltf_materials.cpp — reads the core material factors, the base colour, metallic-roughness,
// emissive and normal textures, KHR_materials_emissive_strength, KHR_materials_specular (factors
// and textures), the glass of KHR_materials_transmission, KHR_materials_ior and
// KHR_materials_volume, the layers of KHR_materials_clearcoat and KHR_materials_sheen, and
// KHR_materials_unlit as an emitter of the base colour that reflects nothing.
#include "scene/gltf_materials.h"

#include <algorithm>
#include <cmath>

#include "scene/gltf_document.h"
#include "scene/gltf_values.h"

namespace vkpt::gltf {
namespace {

constexpr const char* kEmissiveStrength = "KHR_materials_emissive_strength";
constexpr const char* kSpecular = "KHR_materials_specular";
constexpr const char* kTransmission = "KHR_materials_transmission";
constexpr const char* kIor = "KHR_materials_ior";
constexpr const char* kVolume = "KHR_materials_volume";
constexpr const char* kClearcoat = "KHR_materials_clearcoat";
constexpr const char* kSheen = "KHR_materials_sheen";
constexpr const char* kUnlit = "KHR_materials_unlit";
constexpr const char* kAnisotropy = "KHR_materials_anisotropy";
constexpr const char* kIridescence = "KHR_materials_iridescence";
constexpr const char* kDiffuseTransmission = "KHR_materials_diffuse_transmission";
constexpr const char* kDispersion = "KHR_materials_dispersion";

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

// glTF normalTexture: a textureInfo with a scale for the X and Y of the decoded normals.
void readNormalTexture(const tinygltf::NormalTextureInfo& normal, TextureTable& textures,
                       const std::string& where, SceneMaterial& converted) {
    tinygltf::TextureInfo info;
    info.index = normal.index;
    info.texCoord = normal.texCoord;
    info.extensions = normal.extensions;
    converted.normalTexture = readTextureReference(info, textures, where);
    if (!std::isfinite(normal.scale)) throw GltfProblem(where + ": scale is not a finite number");
    converted.normalScale = static_cast<float>(normal.scale);
}

// An extension's textureInfo object as tinygltf's TextureInfo, so that the core reader checks
// its index, texCoord and KHR_texture_transform.
tinygltf::TextureInfo textureInfoOf(const tinygltf::Value& object, const std::string& where) {
    tinygltf::TextureInfo info;
    info.index = readIndex(object, "index", where);
    info.texCoord = std::max(0, readIndex(object, "texCoord", where));
    if (const tinygltf::Value* extensions = findMember(object, "extensions")) {
        if (const tinygltf::Value* transform = findMember(*extensions, "KHR_texture_transform"))
            info.extensions["KHR_texture_transform"] = *transform;
    }
    return info;
}

// The textureInfo at `key` of an extension object, or no texture when the key is absent.
TextureReference readExtensionTexture(const tinygltf::Value& extension, const std::string& key,
                                      TextureTable& textures, const std::string& where) {
    const tinygltf::Value* member = findMember(extension, key);
    if (member == nullptr) return {};
    const std::string place = where + ": " + key;
    return readTextureReference(textureInfoOf(*member, place), textures, place);
}

double readUnitNumber(const tinygltf::Value& object, const std::string& key, double fallback,
                      const std::string& where) {
    const double value = readNumber(object, key, fallback, where);
    if (value < 0.0 || value > 1.0) throw GltfProblem(where + ": " + key + " must be in [0, 1]");
    return value;
}

// KHR_materials_specular: the strength (specularFactor, in [0, 1], times the A channel of
// specularTexture) and colour (specularColorFactor, >= 0, times the RGB of the sRGB
// specularColorTexture) of the dielectric specular layer; absent, both are 1, the core glTF
// model.
void readSpecular(const tinygltf::Material& material, std::size_t index, TextureTable& textures,
                  SceneMaterial& converted) {
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
    converted.specularTexture =
        readExtensionTexture(*extension, "specularTexture", textures, where);
    converted.specularColorTexture =
        readExtensionTexture(*extension, "specularColorTexture", textures, where);
}

// KHR_materials_transmission: the share of the non-metal part that is glass
// (transmissionFactor × transmissionTexture.r, both in [0, 1]).
void readTransmission(const tinygltf::Material& material, std::size_t index, TextureTable& textures,
                      SceneMaterial& converted) {
    const tinygltf::Value* extension = findExtension(material.extensions, kTransmission);
    if (extension == nullptr) return;
    const std::string where = materialName(index) + ": " + kTransmission;
    converted.transmission =
        static_cast<float>(readUnitNumber(*extension, "transmissionFactor", 0.0, where));
    converted.transmissionTexture =
        readExtensionTexture(*extension, "transmissionTexture", textures, where);
}

// KHR_materials_ior: ior >= 1 (the extension also allows 0, meaning "not a dielectric", for
// compatibility with other formats; vkpt reads it as 1.5, the glTF default).
void readIor(const tinygltf::Material& material, std::size_t index, SceneMaterial& converted) {
    const tinygltf::Value* extension = findExtension(material.extensions, kIor);
    if (extension == nullptr) return;
    const std::string where = materialName(index) + ": " + kIor;
    const double ior = readNumber(*extension, "ior", 1.5, where);
    if (ior == 0.0) return;
    if (!(ior >= 1.0)) throw GltfProblem(where + ": ior must be >= 1 (or 0)");
    converted.ior = static_cast<float>(ior);
}

// KHR_materials_volume: thicknessFactor > 0 makes the mesh the boundary of a volume whose
// medium attenuates light by Beer–Lambert's law. thicknessTexture is a rasteriser's hint for
// the distance light travels inside; a path tracer measures that distance on the geometry, so
// it is not read (materialNotes says so).
void readVolume(const tinygltf::Material& material, std::size_t index, SceneMaterial& converted) {
    const tinygltf::Value* extension = findExtension(material.extensions, kVolume);
    if (extension == nullptr) return;
    const std::string where = materialName(index) + ": " + kVolume;
    const double thickness = readNumber(*extension, "thicknessFactor", 0.0, where);
    if (thickness < 0.0) throw GltfProblem(where + ": thicknessFactor must be >= 0");
    const std::vector<double> color =
        readNumbers(*extension, "attenuationColor", {1.0, 1.0, 1.0}, where);
    for (double c : color)
        if (c < 0.0 || c > 1.0) throw GltfProblem(where + ": attenuationColor must be in [0, 1]");
    converted.thickness = static_cast<float>(thickness);
    converted.attenuationColor = glm::vec3(glm::dvec3(color[0], color[1], color[2]));
    if (findMember(*extension, "attenuationDistance") != nullptr) {
        const double distance = readNumber(*extension, "attenuationDistance", 0.0, where);
        if (!(distance > 0.0)) throw GltfProblem(where + ": attenuationDistance must be > 0");
        converted.attenuationDistance = static_cast<float>(distance);
    }
}

// KHR_materials_clearcoat: the layer's strength (R of its texture), roughness (G of its texture)
// and normal texture, a normalTextureInfo with its own scale.
void readClearcoat(const tinygltf::Material& material, std::size_t index, TextureTable& textures,
                   SceneMaterial& converted) {
    const tinygltf::Value* extension = findExtension(material.extensions, kClearcoat);
    if (extension == nullptr) return;
    const std::string where = materialName(index) + ": " + kClearcoat;
    converted.clearcoat =
        static_cast<float>(readUnitNumber(*extension, "clearcoatFactor", 0.0, where));
    converted.clearcoatRoughness =
        static_cast<float>(readUnitNumber(*extension, "clearcoatRoughnessFactor", 0.0, where));
    converted.clearcoatTexture =
        readExtensionTexture(*extension, "clearcoatTexture", textures, where);
    converted.clearcoatRoughnessTexture =
        readExtensionTexture(*extension, "clearcoatRoughnessTexture", textures, where);
    converted.clearcoatNormalTexture =
        readExtensionTexture(*extension, "clearcoatNormalTexture", textures, where);
    if (const tinygltf::Value* normal = findMember(*extension, "clearcoatNormalTexture")) {
        const double scale = readNumber(*normal, "scale", 1.0, where + ": clearcoatNormalTexture");
        if (!std::isfinite(scale))
            throw GltfProblem(where + ": clearcoatNormalTexture: scale is not a finite number");
        converted.clearcoatNormalScale = static_cast<float>(scale);
    }
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
    converted.sheenRoughness =
        static_cast<float>(readUnitNumber(*extension, "sheenRoughnessFactor", 0.0, where));
    converted.sheenColorTexture =
        readExtensionTexture(*extension, "sheenColorTexture", textures, where);
    converted.sheenRoughnessTexture =
        readExtensionTexture(*extension, "sheenRoughnessTexture", textures, where);
}

// KHR_materials_anisotropy: the strength in [0, 1], the rotation (radians, any finite number)
// and the texture of direction (RG) and strength (B).
void readAnisotropy(const tinygltf::Material& material, std::size_t index, TextureTable& textures,
                    SceneMaterial& converted) {
    const tinygltf::Value* extension = findExtension(material.extensions, kAnisotropy);
    if (extension == nullptr) return;
    const std::string where = materialName(index) + ": " + kAnisotropy;
    converted.anisotropyStrength =
        static_cast<float>(readUnitNumber(*extension, "anisotropyStrength", 0.0, where));
    converted.anisotropyRotation =
        static_cast<float>(readNumber(*extension, "anisotropyRotation", 0.0, where));
    converted.anisotropyTexture =
        readExtensionTexture(*extension, "anisotropyTexture", textures, where);
}

// KHR_materials_iridescence: the film's factor in [0, 1] (R of its texture), ior >= 1 and
// thickness range in nm (>= 0; G of the thickness texture interpolates it).
void readIridescence(const tinygltf::Material& material, std::size_t index, TextureTable& textures,
                     SceneMaterial& converted) {
    const tinygltf::Value* extension = findExtension(material.extensions, kIridescence);
    if (extension == nullptr) return;
    const std::string where = materialName(index) + ": " + kIridescence;
    converted.iridescence =
        static_cast<float>(readUnitNumber(*extension, "iridescenceFactor", 0.0, where));
    const double ior = readNumber(*extension, "iridescenceIor", 1.3, where);
    if (!(ior >= 1.0)) throw GltfProblem(where + ": iridescenceIor must be >= 1");
    converted.iridescenceIor = static_cast<float>(ior);
    const double minimum = readNumber(*extension, "iridescenceThicknessMinimum", 100.0, where);
    const double maximum = readNumber(*extension, "iridescenceThicknessMaximum", 400.0, where);
    if (minimum < 0.0 || maximum < 0.0)
        throw GltfProblem(where + ": the thickness range must not be negative");
    converted.iridescenceThicknessMinimum = static_cast<float>(minimum);
    converted.iridescenceThicknessMaximum = static_cast<float>(maximum);
    converted.iridescenceTexture =
        readExtensionTexture(*extension, "iridescenceTexture", textures, where);
    converted.iridescenceThicknessTexture =
        readExtensionTexture(*extension, "iridescenceThicknessTexture", textures, where);
}

// KHR_materials_diffuse_transmission: the share of the diffuse base transmitted, in [0, 1] (A of
// its texture), and its colour, each channel in [0, 1] (RGB of its sRGB texture).
void readDiffuseTransmission(const tinygltf::Material& material, std::size_t index,
                             TextureTable& textures, SceneMaterial& converted) {
    const tinygltf::Value* extension = findExtension(material.extensions, kDiffuseTransmission);
    if (extension == nullptr) return;
    const std::string where = materialName(index) + ": " + kDiffuseTransmission;
    converted.diffuseTransmission =
        static_cast<float>(readUnitNumber(*extension, "diffuseTransmissionFactor", 0.0, where));
    const std::vector<double> color =
        readNumbers(*extension, "diffuseTransmissionColorFactor", {1.0, 1.0, 1.0}, where);
    for (double c : color)
        if (c < 0.0 || c > 1.0)
            throw GltfProblem(where + ": diffuseTransmissionColorFactor must be in [0, 1]");
    converted.diffuseTransmissionColor = glm::vec3(glm::dvec3(color[0], color[1], color[2]));
    converted.diffuseTransmissionTexture =
        readExtensionTexture(*extension, "diffuseTransmissionTexture", textures, where);
    converted.diffuseTransmissionColorTexture =
        readExtensionTexture(*extension, "diffuseTransmissionColorTexture", textures, where);
}

// KHR_materials_dispersion: 20/V_d, at least 0 (0: none).
void readDispersion(const tinygltf::Material& material, std::size_t index,
                    SceneMaterial& converted) {
    const tinygltf::Value* extension = findExtension(material.extensions, kDispersion);
    if (extension == nullptr) return;
    const std::string where = materialName(index) + ": " + kDispersion;
    const double dispersion = readNumber(*extension, "dispersion", 0.0, where);
    if (!(dispersion >= 0.0) || !std::isfinite(dispersion))
        throw GltfProblem(where + ": dispersion must be a finite number >= 0");
    converted.dispersion = static_cast<float>(dispersion);
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
    readNormalTexture(material.normalTexture, textures, where + "normalTexture", converted);
}

// KHR_materials_unlit: the surface shows its base colour (factor × texture), whatever lights
// it. vkpt makes that colour the radiance it emits, from the front face (both faces when
// double-sided), and lets it reflect nothing (a black Lambertian base), so every ray sees the
// same colour and light sampling finds it like any emitter (docs/scene-model.md, "Unlit").
// The base colour texture moves to the emissive slot (both sRGB); it stays the base colour's
// too only for alphaMode MASK, whose cut-outs it decides. The extension's other properties,
// and every other material extension, do not apply to an unlit surface and are not read.
SceneMaterial unlitMaterial(const tinygltf::Material& material, std::size_t index,
                            TextureTable& textures, const SceneMaterial& core) {
    SceneMaterial unlit;
    unlit.name = core.name;
    unlit.unlit = true;
    unlit.emission = glm::vec3(core.baseColor);
    unlit.emissiveTexture =
        readTextureReference(material.pbrMetallicRoughness.baseColorTexture, textures,
                             materialName(index) + ": baseColorTexture");
    unlit.baseColor = glm::vec4(0.0f, 0.0f, 0.0f, core.baseColor.a);
    unlit.metallic = 0.0f;
    unlit.specular = 0.0f;
    unlit.doubleSided = core.doubleSided;
    unlit.alphaMode = core.alphaMode;
    unlit.alphaCutoff = core.alphaCutoff;
    if (unlit.alphaMode == AlphaMode::Mask) unlit.baseColorTexture = unlit.emissiveTexture;
    return unlit;
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
    if (findExtension(material.extensions, kUnlit) != nullptr)
        return unlitMaterial(material, index, textures, converted);
    readTextures(material, index, textures, converted);
    readSpecular(material, index, textures, converted);
    readTransmission(material, index, textures, converted);
    readIor(material, index, converted);
    readVolume(material, index, converted);
    readClearcoat(material, index, textures, converted);
    readSheen(material, index, textures, converted);
    readAnisotropy(material, index, textures, converted);
    readIridescence(material, index, textures, converted);
    readDiffuseTransmission(material, index, textures, converted);
    readDispersion(material, index, converted);
    return converted;
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

bool hasThicknessTexture(const tinygltf::Material& material) {
    const tinygltf::Value* extension = findExtension(material.extensions, kVolume);
    return extension != nullptr && findMember(*extension, "thicknessTexture") != nullptr;
}

std::string materialCount(std::size_t count) {
    return std::to_string(count) + (count == 1 ? " material" : " materials");
}

std::vector<std::string> materialNotes(const tinygltf::Model& model) {
    std::size_t thicknessTextures = 0;
    for (const tinygltf::Material& material : model.materials)
        thicknessTextures += hasThicknessTexture(material) ? 1 : 0;
    std::vector<std::string> notes;
    if (thicknessTextures > 0)
        notes.push_back("ignoring the " + std::string(kVolume) + " thicknessTexture of " +
                        materialCount(thicknessTextures) +
                        " (a rasteriser's hint: the path tracer measures thickness on the mesh)");
    return notes;
}

SceneMaterial defaultMaterial() {
    SceneMaterial material; // SceneMaterial's defaults are the glTF defaults
    material.name = "glTF default material";
    return material;
}

} // namespace vkpt::gltf
