// gltf_textures.cpp — textures, samplers and KHR_texture_transform, read only for the textures
// that materials use.
#include "scene/gltf_textures.h"

#include <cmath>

#include "scene/gltf_document.h"
#include "scene/gltf_images.h"
#include "scene/gltf_values.h"

namespace vkpt::gltf {
namespace {

constexpr const char* kTextureTransform = "KHR_texture_transform";

constexpr const char* kTextureWebp = "EXT_texture_webp";

// Image sources other than the core `source` (PNG or JPEG) and EXT_texture_webp's that files
// use; none is decoded.
const char* const kExtensionSources[] = {"KHR_texture_basisu", "EXT_texture_avif",
                                         "MSFT_texture_dds"};

std::string textureName(int index) {
    return "texture " + std::to_string(index);
}

// A texture whose only image is in a format vkpt cannot decode would render as its factor
// alone: reported instead, naming the format.
[[noreturn]] void failWithoutSource(const tinygltf::Texture& texture, int index,
                                    const std::string& where) {
    const std::string name = where + ": " + textureName(index);
    for (const char* extension : kExtensionSources) {
        if (findExtension(texture.extensions, extension) != nullptr) {
            throw GltfProblem(name + " has only a " + extension +
                              " image, which vkpt does not decode; convert it to PNG, JPEG or "
                              "WebP");
        }
    }
    throw GltfProblem(name + " has no source image");
}

TextureWrap wrapOf(int mode, const char* property, int sampler) {
    switch (mode) {
    case TINYGLTF_TEXTURE_WRAP_REPEAT:
        return TextureWrap::Repeat;
    case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE:
        return TextureWrap::ClampToEdge;
    case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT:
        return TextureWrap::MirroredRepeat;
    default:
        throw GltfProblem("sampler " + std::to_string(sampler) + ": " + property + " " +
                          std::to_string(mode) + " is not a glTF wrap mode");
    }
}

// glTF sampler defaults (section 5.26): REPEAT both ways, the filters left to the renderer,
// which here means bilinear.
void applySampler(const tinygltf::Model& model, int samplerIndex, const std::string& where,
                  SceneTexture& texture) {
    if (samplerIndex == -1) return;
    if (samplerIndex < 0 || static_cast<std::size_t>(samplerIndex) >= model.samplers.size()) {
        throw GltfProblem(where + ": sampler " + std::to_string(samplerIndex) +
                          " does not exist (the file has " + std::to_string(model.samplers.size()) +
                          " samplers)");
    }
    const tinygltf::Sampler& sampler = model.samplers[static_cast<std::size_t>(samplerIndex)];
    texture.wrapS = wrapOf(sampler.wrapS, "wrapS", samplerIndex);
    texture.wrapT = wrapOf(sampler.wrapT, "wrapT", samplerIndex);
    // Magnification decides what a path tracer sees up close; without mipmaps the minification
    // filter has nothing to choose between.
    texture.nearest = sampler.magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST;
}

} // namespace

TextureTable::TextureTable(const tinygltf::Model& model, std::vector<SceneTexture>& textures,
                           std::vector<SceneImage>& images)
    : model_(model), textures_(textures), images_(images), sceneTexture_(model.textures.size(), -1),
      sceneImage_(model.images.size(), -1) {}

int TextureTable::use(int gltfTexture, const std::string& where) {
    if (gltfTexture < 0 || static_cast<std::size_t>(gltfTexture) >= model_.textures.size()) {
        throw GltfProblem(where + ": " + textureName(gltfTexture) +
                          " does not exist (the file has " +
                          std::to_string(model_.textures.size()) + " textures)");
    }
    int& slot = sceneTexture_[static_cast<std::size_t>(gltfTexture)];
    if (slot < 0) {
        const tinygltf::Texture& texture = model_.textures[static_cast<std::size_t>(gltfTexture)];
        SceneTexture converted = convertTexture(texture, gltfTexture, where);
        slot = static_cast<int>(textures_.size());
        textures_.push_back(converted);
    }
    return slot;
}

namespace {

// EXT_texture_webp names the image to use; the core `source`, when there is one, is the PNG or
// JPEG fallback for viewers without WebP, used here only when the extension names none.
int imageSource(const tinygltf::Texture& texture, const std::string& where) {
    if (const tinygltf::Value* webp = findExtension(texture.extensions, kTextureWebp)) {
        const int source = readIndex(*webp, "source", where + ": " + kTextureWebp);
        if (source >= 0) return source;
    }
    return texture.source;
}

} // namespace

SceneTexture TextureTable::convertTexture(const tinygltf::Texture& texture, int gltfTexture,
                                          const std::string& where) {
    const std::string name = where + ": " + textureName(gltfTexture);
    const int source = imageSource(texture, name);
    if (source == -1) failWithoutSource(texture, gltfTexture, where);
    SceneTexture converted;
    applySampler(model_, texture.sampler, name, converted);
    converted.image = useImage(source, name);
    return converted;
}

int TextureTable::useImage(int gltfImage, const std::string& where) {
    if (gltfImage < 0 || static_cast<std::size_t>(gltfImage) >= model_.images.size()) {
        throw GltfProblem(where + ": image " + std::to_string(gltfImage) +
                          " does not exist (the file has " + std::to_string(model_.images.size()) +
                          " images)");
    }
    int& slot = sceneImage_[static_cast<std::size_t>(gltfImage)];
    if (slot < 0) {
        images_.push_back(decodeImage(model_, gltfImage));
        slot = static_cast<int>(images_.size()) - 1;
    }
    return slot;
}

// KHR_texture_transform defines uv' = T · R · S · (u, v, 1) with glTF's v pointing down the
// image. The rotation turns the UVs counter-clockwise as seen in that v-down space:
//   u' = cos θ · u + sin θ · v,  v' = −sin θ · u + cos θ · v.
// That is the sign of the extension's prose, of its own example (offset [0, 1], rotation π/2,
// scale 0.5 selects the lower-left quadrant), of the TextureTransformTest sample model and of
// the Khronos glTF-Sample-Viewer; the GLSL listing in the README has the transpose, a known
// erratum (KhronosGroup/glTF issue 1563).
glm::mat3 textureTransformMatrix(glm::dvec2 offset, double rotation, glm::dvec2 scale) {
    const double c = std::cos(rotation);
    const double s = std::sin(rotation);
    const glm::dmat3 translate(1, 0, 0, 0, 1, 0, offset.x, offset.y, 1); // column-major
    const glm::dmat3 rotate(c, -s, 0, s, c, 0, 0, 0, 1);
    const glm::dmat3 scaling(scale.x, 0, 0, 0, scale.y, 0, 0, 0, 1);
    return glm::mat3(translate * rotate * scaling);
}

// Only TEXCOORD_0 reaches the renderers (Scene::texcoords). A texture on another set is refused
// rather than read at TEXCOORD_0: that would put the image in the wrong place without a word.
TextureReference readTextureReference(const tinygltf::TextureInfo& info, TextureTable& table,
                                      const std::string& where) {
    TextureReference reference;
    if (info.index == -1) return reference;
    int texCoord = info.texCoord;
    if (const tinygltf::Value* transform = findExtension(info.extensions, kTextureTransform)) {
        const std::string place = where + ": " + kTextureTransform;
        const std::vector<double> offset = readNumbers(*transform, "offset", {0.0, 0.0}, place);
        const double rotation = readNumber(*transform, "rotation", 0.0, place);
        const std::vector<double> scale = readNumbers(*transform, "scale", {1.0, 1.0}, place);
        reference.transform =
            textureTransformMatrix({offset[0], offset[1]}, rotation, {scale[0], scale[1]});
        // The extension's texCoord replaces the textureInfo's (its README).
        if (const int set = readIndex(*transform, "texCoord", place); set >= 0) {
            texCoord = set;
        }
    }
    if (texCoord != 0) {
        throw GltfProblem(where + ": reads TEXCOORD_" + std::to_string(texCoord) +
                          "; only TEXCOORD_0 is supported");
    }
    reference.texture = table.use(info.index, where);
    return reference;
}

} // namespace vkpt::gltf
