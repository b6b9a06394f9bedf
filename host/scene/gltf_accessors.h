// gltf_accessors.h — bounds-checked, typed reads of glTF accessors: every offset, stride and count
// is checked against its buffer view (and each view against its buffer) before a byte is read,
// because tinygltf checks none of them.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <tiny_gltf.h>

namespace vkpt::gltf {

// Every buffer view names an existing buffer and lies inside it.
void checkBufferViews(const tinygltf::Model& model);

// Whether the file requires KHR_mesh_quantization, which allows the integer attribute types
// below (the extension must be required when a file uses them).
bool allowsQuantizedAttributes(const tinygltf::Model& model);

// `where` names the use, e.g. "mesh 0, primitive 1: POSITION", and starts every message.
// Sparse accessors are read too: their buffer view's elements (zeros without one) with the
// listed elements replaced (glTF 2.0, section 3.6.2.3).

// POSITION: VEC3 of FLOAT; with KHR_mesh_quantization also of BYTE, UNSIGNED_BYTE, SHORT or
// UNSIGNED_SHORT, normalized or not (the node transform then carries the dequantisation, as the
// extension intends).
std::vector<glm::vec3> readPositions(const tinygltf::Model& model, int accessorIndex,
                                     const std::string& where);

// NORMAL: VEC3 of FLOAT; with KHR_mesh_quantization also of normalized BYTE or SHORT.
std::vector<glm::vec3> readNormals(const tinygltf::Model& model, int accessorIndex,
                                   const std::string& where);

// TANGENT: VEC4 of FLOAT; with KHR_mesh_quantization also of normalized BYTE or SHORT.
std::vector<glm::vec4> readTangents(const tinygltf::Model& model, int accessorIndex,
                                    const std::string& where);

// EXT_mesh_gpu_instancing ROTATION: VEC4 quaternions (x, y, z, w) of FLOAT or of normalized BYTE
// or SHORT, the types that extension allows.
std::vector<glm::vec4> readRotations(const tinygltf::Model& model, int accessorIndex,
                                     const std::string& where);

// TEXCOORD_n values: VEC2 of FLOAT, or of normalized UNSIGNED_BYTE or UNSIGNED_SHORT mapped to
// [0, 1], the three layouts glTF 2.0 allows (section 3.7.2.1); with KHR_mesh_quantization also
// BYTE and SHORT, and all four integer types unnormalized (KHR_texture_transform then scales).
std::vector<glm::vec2> readTexcoords(const tinygltf::Model& model, int accessorIndex,
                                     const std::string& where);

// Animation and skinning data, every component as a float, element after element (`components`
// per element): a FLOAT accessor of `type`, or with `normalizedIntegers` also one of normalized
// BYTE, UNSIGNED_BYTE, SHORT or UNSIGNED_SHORT (glTF 2.0, section 3.11: animation outputs of
// rotations and weights, and WEIGHTS_n, may be stored so).
std::vector<float> readFloatComponents(const tinygltf::Model& model, int accessorIndex, int type,
                                       bool normalizedIntegers, const std::string& where);

// JOINTS_n: VEC4 of UNSIGNED_BYTE or UNSIGNED_SHORT, widened.
std::vector<glm::uvec4> readJoints(const tinygltf::Model& model, int accessorIndex,
                                   const std::string& where);

// How many elements the accessor declares, without reading them.
std::size_t accessorElementCount(const tinygltf::Model& model, int accessorIndex,
                                 const std::string& where);

// Indices of any glTF index type (UNSIGNED_BYTE, UNSIGNED_SHORT, UNSIGNED_INT), widened.
std::vector<std::uint32_t> readIndices(const tinygltf::Model& model, int accessorIndex,
                                       const std::string& where);

} // namespace vkpt::gltf
