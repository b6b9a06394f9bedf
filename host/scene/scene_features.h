// scene_features.h — what a scene uses, found once after loading: material kinds and layers,
// textures, spheres, light kinds, the environment. Both renderers build for exactly this set (the
// kernels through specialisation constants, the host through the buffers it creates), and
// --general asks for all of it, for comparison (docs/scene-model.md).
#pragma once

#include <array>
#include <cstdint>
#include <string>

#include "scene/scene.h"
#include "shared/host_device.h"

namespace vkpt {

struct SceneFeatures {
    bool diffuseMaterials = false;           // Lambertian-only materials present
    bool metallicRoughnessMaterials = false; // glTF GGX materials present
    bool baseColorTextures = false;
    bool metallicRoughnessTextures = false;
    bool emissiveTextures = false;
    bool normalTextures = false;       // some material has a normal texture (and so tangents)
    bool transmissionTextures = false; // KHR_materials_transmission's texture
    bool alphaMask = false;            // some material has alphaMode MASK
    bool doubleSided = false;          // some material is double-sided
    // KHR_materials_transmission / _ior / _volume: some material transmits, bounds a volume
    // or has an ior other than 1.5 (shared/bsdf_dielectric.h).
    bool transmission = false;
    bool clearcoatMaterials = false;  // KHR_materials_clearcoat layers present
    bool sheenMaterials = false;      // KHR_materials_sheen layers present
    bool clearcoatTextures = false;   // clearcoat or clearcoat roughness textures
    bool sheenTextures = false;       // sheen colour or sheen roughness textures
    bool specularTextures = false;    // KHR_materials_specular textures on a GGX material
    bool anisotropy = false;          // KHR_materials_anisotropy on a GGX material
    bool anisotropyTextures = false;  // its anisotropyTexture
    bool iridescence = false;         // KHR_materials_iridescence on a GGX material
    bool iridescenceTextures = false; // its factor or thickness texture
    // KHR_materials_diffuse_transmission: some diffuse base transmits (materialLobes)
    bool diffuseTransmission = false;
    bool diffuseTransmissionTextures = false; // its factor or colour texture
    // KHR_materials_dispersion on glass that bounds a volume: paths carry a wavelength
    bool dispersion = false;
    bool triangles = false;
    bool spheres = false;
    // Meshes placed by instances: a two-level BVH. A layout, not an optional feature: --general
    // keeps the scene's own.
    bool instances = false;
    bool emissiveTriangles = false;
    bool emissiveSpheres = false;
    bool pointLights = false;
    bool spotLights = false;
    bool directionalLights = false;
    bool environment = false;       // a constant colour or a map
    bool environmentMap = false;    // --env image.hdr
    std::uint32_t emitterCount = 0; // everything light sampling chooses from
    bool general = false; // --general: all switches on, and the CDF read even for one emitter
    // --light-sampler bvh with several emitters: they are chosen by the light BVH, not the power
    // CDF. A choice of the render, not a feature of the scene: --general keeps it from `used`.
    bool lightTree = false;

    bool textures() const {
        return baseColorTextures || metallicRoughnessTextures || emissiveTextures ||
               normalTextures || transmissionTextures || clearcoatTextures || sheenTextures ||
               specularTextures || anisotropyTextures || iridescenceTextures ||
               diffuseTransmissionTextures;
    }
    // TEXCOORD_0 is needed only to read textures.
    bool textureCoordinates() const { return textures(); }
    // Per-corner tangents are needed only for normal textures and anisotropy's direction.
    bool tangents() const { return normalTextures || anisotropy; }
    // The specularLobes array (shared/host_device.h, SpecularLobeParams).
    bool specularLobes() const { return specularTextures || anisotropy || iridescence; }
    bool punctualLights() const { return pointLights || spotLights || directionalLights; }
    bool emitterCdf() const { return general || emitterCount > 1; }

    // The specialisation constants (FEATURE_* of shared/host_device.h) of this set.
    std::array<bool, FEATURE_COUNT> kernelFeatures() const;
};

// The features `scene` uses; emitterCount counts emitting triangles (a repeated one once),
// emitting spheres, punctual lights and the environment.
SceneFeatures analyseScene(const Scene& scene);

// Everything on (and general set): what the --general pipelines are built for. emitterCount
// is kept from `used`, since it is a count, not a switch.
SceneFeatures generalFeatures(const SceneFeatures& used);

// "diffuse, metallic-roughness, textures (base colour, emissive), spheres, 3 emitters, ...",
// for --verbose.
std::string describeFeatures(const SceneFeatures& features);

} // namespace vkpt
