// gltf_primitives.h — one mesh primitive to triangles with shading normals, in world space or in
// its mesh's own.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <tiny_gltf.h>

#include "scene/scene.h"

namespace vkpt::gltf {

// Whether to fill TriangleSoup::texcoords: only a scene with textures needs them.
enum class Texcoords { Skip, Read };

// What to put in TriangleSoup::tangents for a primitive: nothing (the scene has no normal
// textures), zeros (its material has none), or its frames: the file's TANGENT, else generated
// (scene/tangents.h). Read needs Texcoords::Read.
enum class Tangents { Skip, Zero, Read };

// What moves a primitive's vertices before `world` places them: its morph weights (empty: none)
// and, for a skinned node, its skin's joint matrices (gltf_skins.h), which place the vertices in
// the walk's space; `world` is then the identity.
struct Deformation {
    std::vector<double> morphWeights;
    const std::vector<glm::dmat4>* joints = nullptr;
};

// Appends the primitive's triangles, transformed by `world` (the identity for a mesh kept in its
// own space) and with material materialIndex, to `soup`, with Texcoords::Read their TEXCOORD_0 ((0,
// 0) when absent), and their tangents as `tangents` asks. Normals are transformed by the inverse
// transpose, or generated flat when absent; a mirroring transform swaps two corners so that the
// front face stays the front face. `deformation` morphs and skins the vertices first. `where` names
// the primitive ("mesh 3, primitive 0") in messages; what was repaired or skipped is counted in
// `repairs`.
void appendPrimitiveTriangles(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                              const glm::dmat4& world, std::uint32_t materialIndex,
                              Texcoords texcoords, Tangents tangents, const std::string& where,
                              TriangleSoup& soup, GeometryRepairs& repairs,
                              const Deformation& deformation = {});

} // namespace vkpt::gltf
