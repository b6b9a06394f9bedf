// scene.h — the loaded scene as plain structs: world-space triangles, meshes placed by
// instances, materials, cameras.
// No Vulkan and no BVH here; everything downstream starts from this.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace vkpt {

enum class AlphaMode : std::uint32_t { Opaque = 0, Mask = 1, Blend = 2 };

// A material's use of a texture: Scene::textures[texture] read at TEXCOORD_0 moved by the
// KHR_texture_transform matrix (identity when absent).
struct TextureReference {
    int texture = -1;          // -1: none
    glm::mat3 transform{1.0f}; // uv' = (transform · (u, v, 1)).xy
};

struct SceneMaterial {
    std::string name;
    glm::vec4 baseColor{1.0f}; // linear RGBA
    glm::vec3 emission{0.0f};  // emissiveFactor × KHR_materials_emissive_strength
    float metallic = 1.0f;     // glTF defaults
    float roughness = 1.0f;
    bool doubleSided = false;
    AlphaMode alphaMode = AlphaMode::Opaque;
    float alphaCutoff = 0.5f;
    float specular = 1.0f;                     // KHR_materials_specular specularFactor
    glm::vec3 specularColor{1.0f};             // KHR_materials_specular specularColorFactor
    TextureReference specularTexture;          // linear: A strength (KHR_materials_specular)
    TextureReference specularColorTexture;     // sRGB-encoded RGB colour (KHR_materials_specular)
    TextureReference baseColorTexture;         // sRGB-encoded RGBA
    TextureReference metallicRoughnessTexture; // linear: G roughness, B metallic
    TextureReference emissiveTexture;          // sRGB-encoded RGB
    TextureReference normalTexture;            // linear tangent-space normals (glTF normalTexture)
    float normalScale = 1.0f;                  // normalTexture.scale

    // KHR_materials_transmission, KHR_materials_ior, KHR_materials_volume (the extensions'
    // defaults: opaque, ior 1.5, thin-walled, no attenuation).
    float transmission = 0.0f;            // transmissionFactor
    TextureReference transmissionTexture; // linear, transmission in R
    float ior = 1.5f;
    float thickness = 0.0f;           // thicknessFactor; 0: thin-walled
    glm::vec3 attenuationColor{1.0f}; // transmittance after attenuationDistance
    float attenuationDistance = std::numeric_limits<float>::infinity();

    // KHR_materials_clearcoat (0: no clearcoat; the extension's defaults)
    float clearcoat = 0.0f;                     // clearcoatFactor
    float clearcoatRoughness = 0.0f;            // clearcoatRoughnessFactor
    TextureReference clearcoatTexture;          // linear: R factor
    TextureReference clearcoatRoughnessTexture; // linear: G roughness
    TextureReference clearcoatNormalTexture;    // linear tangent-space normals of the layer
    float clearcoatNormalScale = 1.0f;          // clearcoatNormalTexture.scale
    // KHR_materials_sheen (black: no sheen; the extension's defaults)
    glm::vec3 sheenColor{0.0f};             // sheenColorFactor
    float sheenRoughness = 0.0f;            // sheenRoughnessFactor
    TextureReference sheenColorTexture;     // sRGB-encoded RGB
    TextureReference sheenRoughnessTexture; // linear: A roughness
    // KHR_materials_anisotropy (strength 0: isotropic; the extension's defaults)
    float anisotropyStrength = 0.0f;    // anisotropyStrength
    float anisotropyRotation = 0.0f;    // anisotropyRotation, radians counter-clockwise
    TextureReference anisotropyTexture; // linear: RG direction (2x − 1), B strength
    // KHR_materials_iridescence (factor 0: no film; the extension's defaults)
    float iridescence = 0.0f;                     // iridescenceFactor
    float iridescenceIor = 1.3f;                  // iridescenceIor
    float iridescenceThicknessMinimum = 100.0f;   // nm
    float iridescenceThicknessMaximum = 400.0f;   // nm
    TextureReference iridescenceTexture;          // linear: R factor
    TextureReference iridescenceThicknessTexture; // linear: G thickness
    // KHR_materials_diffuse_transmission (factor 0: the diffuse base only reflects)
    float diffuseTransmission = 0.0f;                 // diffuseTransmissionFactor
    glm::vec3 diffuseTransmissionColor{1.0f};         // diffuseTransmissionColorFactor
    TextureReference diffuseTransmissionTexture;      // linear: A factor
    TextureReference diffuseTransmissionColorTexture; // sRGB: RGB colour
    // KHR_materials_dispersion: 20/V_d (0: none)
    float dispersion = 0.0f;
    // KHR_materials_unlit: the loader made the base colour the emission and the rest black
    // (gltf_materials.cpp); kept for reports and tests, shading needs nothing else.
    bool unlit = false;

    bool hasClearcoat() const { return clearcoat > 0.0f; }
    // Some colour of emission: such a material's triangles are never instanced (Scene::meshes).
    bool emits() const { return emission.r > 0.0f || emission.g > 0.0f || emission.b > 0.0f; }
    // Some normal texture shades the material (its own, or its clearcoat's): tangents needed.
    bool hasNormalMap() const {
        return normalTexture.texture >= 0 ||
               (hasClearcoat() && clearcoatNormalTexture.texture >= 0);
    }
    // KHR_materials_specular textures that shade: on a GGX material (a Lambertian one has
    // specular 0, which they multiply).
    bool hasSpecularTextures() const {
        return !isDiffuseOnly() &&
               (specularTexture.texture >= 0 || specularColorTexture.texture >= 0);
    }
    // An anisotropic GGX lobe: a Lambertian material has none to stretch.
    bool hasAnisotropy() const { return !isDiffuseOnly() && anisotropyStrength > 0.0f; }
    // Tangent frames are needed: for a normal texture, or for the anisotropy's direction.
    bool needsTangents() const { return hasNormalMap() || hasAnisotropy(); }
    // A thin film over the GGX lobe: a Lambertian material has none to colour.
    bool hasIridescence() const { return !isDiffuseOnly() && iridescence > 0.0f; }
    bool hasDiffuseTransmission() const { return diffuseTransmission > 0.0f && !unlit; }
    // Dispersion shows where glass refracts into a volume (shared/bsdf.h, hasDispersion).
    bool hasDispersion() const { return dispersion > 0.0f && transmits() && thickness > 0.0f; }
    bool hasSheen() const { return glm::any(glm::greaterThan(sheenColor, glm::vec3(0.0f))); }

    // Lambertian only: the glTF model with no metal, no specular layer, no glass and no
    // clearcoat or sheen.
    bool isDiffuseOnly() const {
        return metallic == 0.0f && specular == 0.0f && metallicRoughnessTexture.texture < 0 &&
               !transmits() && !hasClearcoat() && !hasSheen() && !hasDiffuseTransmission();
    }
    bool transmits() const { return transmission > 0.0f || transmissionTexture.texture >= 0; }
    // Whether shading needs the dielectric extensions' data (FEATURE_TRANSMISSION).
    bool usesDielectricExtensions() const { return transmits() || ior != 1.5f || thickness > 0.0f; }
};

// Decoded image pixels, 8 bits per channel, RGBA packed R in the low byte, row 0 first
// (the image's top row, which glTF maps to v = 0).
struct SceneImage {
    std::string name;
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    std::vector<std::uint32_t> texels;
};

enum class TextureWrap : std::uint32_t { Repeat = 0, ClampToEdge = 1, MirroredRepeat = 2 };

struct SceneTexture {
    int image = 0; // index into Scene::images
    TextureWrap wrapS = TextureWrap::Repeat;
    TextureWrap wrapT = TextureWrap::Repeat;
    bool nearest = false; // magFilter NEAREST; bilinear otherwise (no mipmaps)
};

// A KHR_implicit_shapes sphere placed by a node (docs/scene-model.md), in world space.
struct SceneSphere {
    glm::vec3 centre{0.0f};
    float radius = 1.0f;
    std::uint32_t material = 0;
};

enum class LightKind : std::uint32_t { Point, Spot, Directional };

// A KHR_lights_punctual light placed by a node, in world space.
struct SceneLight {
    std::string name;
    LightKind kind = LightKind::Point;
    glm::vec3 position{0.0f};
    glm::vec3 direction{0.0f, 0.0f, -1.0f}; // unit, the way the light travels (node's -Z)
    glm::vec3 intensity{1.0f};   // colour × intensity: candela (point, spot) or lux (directional)
    float range = 0.0f;          // 0: unlimited
    float innerConeAngle = 0.0f; // radians, spot lights
    float outerConeAngle = 0.78539816f; // π/4, the extension's default
};

// What rays that leave the scene see: set from the command line (--env, --env-color), not
// from the glTF file. An empty map means the constant radiance alone.
struct SceneEnvironment {
    glm::vec3 radiance{0.0f}; // constant colour, or the map's scale
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    std::vector<glm::vec3> texels; // equirectangular, row 0 at the top (+Y)
    std::string sourcePath;

    bool present() const { return radiance != glm::vec3(0.0f); }
    bool hasMap() const { return width > 0 && height > 0; }
};

enum class CameraProjection : std::uint32_t { Perspective, Orthographic };

// A camera placed by the node tree. forward and up are unit and orthogonal.
struct SceneCamera {
    std::string name;
    glm::vec3 position{0.0f};
    glm::vec3 forward{0.0f, 0.0f, -1.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    CameraProjection projection = CameraProjection::Perspective;
    float yfov = 0.8f; // perspective: vertical field of view, radians
    // Orthographic: glTF's half-height (ymag) and half-width (xmag) of the view in world units.
    // ymag is kept and the image's width/height sets the horizontal extent, as yfov is kept
    // for a perspective camera (docs/conventions.md); xmag is recorded for the log.
    float ymag = 1.0f;
    float xmag = 1.0f;
};

struct Bounds {
    glm::vec3 min{std::numeric_limits<float>::max()};
    glm::vec3 max{std::numeric_limits<float>::lowest()};
};

// What the loader repaired or left out of the file's geometry, counted so that it can say so
// (docs/numerical-stability.md, "Degenerate geometry").
struct GeometryRepairs {
    std::size_t zeroAreaTriangles = 0; // skipped: no area in float, so no ray can hit them
    std::size_t invalidNormals = 0;    // zero-length or non-finite vertex normals: face normal used
    std::size_t renormalisedSkinWeights = 0; // skinned vertices whose weights did not sum to one
};

// A triangle soup: triangle i has vertices positions[3i .. 3i+2] (counter-clockwise seen from
// its front face), shading normals normals[3i .. 3i+2] and material materialIndices[i].
struct TriangleSoup {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<std::uint32_t> materialIndices;
    // TEXCOORD_0, three per triangle like positions; empty unless some material has a texture
    // (then (0, 0) for primitives without the attribute).
    std::vector<glm::vec2> texcoords;
    // Tangents (xyz unit, w the bitangent sign as glTF's TANGENT), three per triangle like
    // positions; empty unless some material has a normal texture (then zero for the triangles
    // of materials without one: no tangent frame). From the file's TANGENT, else generated
    // (scene/tangents.h).
    std::vector<glm::vec4> tangents;

    std::size_t triangleCount() const { return materialIndices.size(); }
};

// A glTF mesh kept once, in its own space, and placed by instances (docs/scene-model.md,
// "Instancing"). Its emitting primitives are not here: light sampling needs every placed
// emitter in world space, so they are flattened into the scene's own soup at each placement.
struct SceneMesh : TriangleSoup {
    std::string name; // "mesh 3 (name)", for messages and statistics
    // The point of the file's mesh space that positions are measured from: the mesh's centre
    // when it lies far from its own origin relative to its size (as the loader recentres a
    // whole scene: Scene::worldOrigin), so that rays moved into this space keep float
    // precision. Instances place the recentred mesh (their transforms include the move).
    glm::dvec3 origin{0.0};
};

// One placement of a SceneMesh: its vertices are objectToWorld × the mesh's positions.
// Invertible (a placement that flattens a dimension is flattened instead: its triangles have no
// area and are skipped, as the loader does for any zero-area triangle).
struct SceneInstance {
    std::uint32_t mesh = 0;        // index into Scene::meshes
    glm::dmat4 objectToWorld{1.0}; // affine; after the recentring (worldOrigin)
    // The material of every triangle of this placement, for a mesh of one material whose
    // geometry other glTF meshes share with other materials ("Shared geometry"); kKeepMaterial:
    // each triangle's own.
    std::uint32_t material = kKeepMaterial;
    static constexpr std::uint32_t kKeepMaterial = 0xffffffffu;
};

// An animation of the file (docs/scene-model.md, "Animation"), for listing: the loader has
// posed the scene at the requested time already.
struct SceneAnimation {
    std::string name;
    double start = 0.0; // seconds: its earliest and latest keyframe
    double end = 0.0;
    std::size_t channels = 0;
};

// The loaded scene: its world-space triangle soup (every placement the loader flattened),
// spheres, the meshes it kept once and their placements, and what lights and frames it.
struct Scene : TriangleSoup {
    std::string sourcePath;
    std::vector<SceneMaterial> materials;
    std::vector<SceneImage> images;
    std::vector<SceneTexture> textures;
    std::vector<SceneSphere> spheres;
    std::vector<SceneMesh> meshes;        // empty unless some mesh is instanced
    std::vector<SceneInstance> instances; // placements of meshes, in node-walk order
    std::vector<SceneLight> lights;
    SceneEnvironment environment;
    std::vector<SceneCamera> cameras;       // in depth-first node-walk order
    std::vector<SceneAnimation> animations; // the file's, posed or not
    // The file's world-space point that positions and cameras are measured from. The loader
    // moves it to the centre of a scene that lies far from the origin (relative to its size),
    // so that floats keep their precision there; rendering does not depend on it.
    glm::dvec3 worldOrigin{0.0};
    // A scene posed at a time: its bounds at rest (as the origin is chosen, gltf_origin.h), which
    // the default camera frames instead of the posed bounds, so that an animation's frames (and a
    // still at any time) are seen from one place, not from one that follows the motion.
    std::optional<Bounds> framingBounds;
    GeometryRepairs repairs;
    // KHR_materials_variants: the file's variant names, and the one whose materials the
    // primitives show (-1: the default materials).
    std::vector<std::string> materialVariants;
    int materialVariant = -1;

    // The triangles a render sees: the soup's and every instance's mesh's.
    std::uint64_t placedTriangleCount() const;
    // The triangles kept in memory: the soup's and each mesh's once.
    std::uint64_t storedTriangleCount() const;
};

// World-space bounds of the soup, the spheres and every instance (its mesh's box, transformed:
// a box around the placed vertices, not the tightest one).
Bounds computeBounds(const Scene& scene);

// Bounds of a soup's vertices in its own space.
Bounds computeBounds(const TriangleSoup& soup);

// The box around `bounds` after an affine transform: its eight corners transformed, in double.
Bounds transformBounds(const Bounds& bounds, const glm::dmat4& transform);

} // namespace vkpt
