// gltf_textures.h — the textures materials use: glTF texture + sampler + image to SceneTexture and
// SceneImage (each decoded once, only when used), and a textureInfo's KHR_texture_transform.
#pragma once

#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "scene/scene.h"

namespace vkpt::gltf {

// Gathers textures on first use, so that Scene::textures and Scene::images hold only what some
// material reads: an image no material uses is never decoded.
class TextureTable {
public:
    TextureTable(const tinygltf::Model& model, std::vector<SceneTexture>& textures,
                 std::vector<SceneImage>& images);

    // The index in Scene::textures of glTF texture `gltfTexture`, added (with its image) the
    // first time. `where` names the use ("material 2: baseColorTexture").
    int use(int gltfTexture, const std::string& where);

private:
    int useImage(int gltfImage, const std::string& where);
    SceneTexture convertTexture(const tinygltf::Texture& texture, int gltfTexture,
                                const std::string& where);

    const tinygltf::Model& model_;
    std::vector<SceneTexture>& textures_;
    std::vector<SceneImage>& images_;
    std::vector<int> sceneTexture_; // per glTF texture: its index in textures_, -1 until used
    std::vector<int> sceneImage_;   // per glTF image: its index in images_, -1 until decoded
};

// The 3×3 matrix of KHR_texture_transform, T(offset) · R(rotation) · S(scale), mapping
// (u, v, 1) to the transformed (u', v', 1). See gltf_textures.cpp for the rotation's sign.
glm::mat3 textureTransformMatrix(glm::dvec2 offset, double rotation, glm::dvec2 scale);

// A material's textureInfo (index -1: none) as a TextureReference, its texture added to
// `table`. Only TEXCOORD_0 is read: a texCoord of 1 or more is a GltfProblem.
TextureReference readTextureReference(const tinygltf::TextureInfo& info, TextureTable& table,
                                      const std::string& where);

} // namespace vkpt::gltf
