// compressed_gltf.h — one small textured scene (an icosphere under a point light, seen by one
// camera) written as .glb uncompressed and in each compressed form the loader reads: Draco
// (draco::Encoder), meshopt (meshopt_encodeVertexBuffer/IndexBuffer with filters), quantized
// attributes (KHR_mesh_quantization) and WebP textures (libwebp's lossless encoder). The
// compression tests compare what the loader makes of each with the uncompressed file; the fuzz
// build seeds its corpus with them.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace vkpt::test {

// Triangles sharing vertices; every attribute has one entry per vertex.
struct TexturedMesh {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<glm::vec2> texcoords;
    std::vector<std::uint32_t> indices;
};

// The icosphere of radius 1 at the origin (2 subdivisions, 162 vertices, 320 triangles) with
// its unit normals and equirectangular texture coordinates.
TexturedMesh texturedSphere();

// The 8 × 4 RGBA base colour texture: distinct texels, alpha 255.
struct Rgba8Image {
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    std::vector<std::uint8_t> rgba;
};
Rgba8Image baseColourImage();

enum class GeometryCoding { Floats, Draco, Meshopt, Quantized };
enum class ImageCoding {
    Png,
    Webp,               // EXT_texture_webp's source only
    WebpOverPngFallback // EXT_texture_webp's source and a different (black) PNG as core source
};

// The quantisation bounds the writers below use, stated for the tests:
// Draco quantises each attribute to a uniform grid over its bounding cube; the error of a
// rounded component is at most half a step, step = extent / (2^bits − 1) (Draco's
// AttributeQuantizationTransform).
constexpr int kDracoPositionBits = 14;
constexpr int kDracoNormalBits = 10;
constexpr int kDracoTexcoordBits = 12;
// meshopt: positions and indices lossless; normals through the OCTAHEDRAL filter with 12-bit
// components (stride 8); texture coordinates through the EXPONENTIAL filter with a 15-bit
// mantissa shared by u and v.
constexpr int kMeshoptNormalBits = 12;
constexpr int kMeshoptTexcoordMantissaBits = 15;
// Quantized: positions as normalized SHORT over the sphere's bounding cube (the node's scale
// undoes it), normals as normalized BYTE, texture coordinates as normalized UNSIGNED_SHORT.

// Writes the scene as a .glb at `path`.
void writeTestScene(const std::string& path, GeometryCoding geometry, ImageCoding image);

} // namespace vkpt::test
